# Where the program finds its files, installed or in the build tree (engine/core/include/platon/
# core/data_root.h): no absolute path is compiled in, only the install layout's folders relative to
# the program's own (bin/platon -> ../share/platon, ../lib/platon), and the build tree mirrors that
# layout, so a program in build/apps/ (or build/tests/, build/bench/) finds them the same way.
include(GNUInstallDirs)
set(PLATON_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/platon CACHE STRING "The scripts, levels, scenarios and replays")
set(PLATON_INSTALL_PLUGINDIR lib/platon CACHE STRING "The plugins (renderer, meshes)")
file(RELATIVE_PATH PLATON_DATA_FROM_BIN ${CMAKE_INSTALL_FULL_BINDIR} ${CMAKE_INSTALL_PREFIX}/${PLATON_INSTALL_DATADIR})
file(RELATIVE_PATH PLATON_PLUGINS_FROM_BIN ${CMAKE_INSTALL_FULL_BINDIR} ${CMAKE_INSTALL_PREFIX}/${PLATON_INSTALL_PLUGINDIR})

# The build tree's mirror: plugins are built into build/lib/platon; build/share/platon links to the
# sources' folders (so an edit to a script or a level needs no build step).
get_filename_component(PLATON_PLUGIN_DIR ${CMAKE_BINARY_DIR}/apps/${PLATON_PLUGINS_FROM_BIN} ABSOLUTE)
get_filename_component(PLATON_DATA_MIRROR ${CMAKE_BINARY_DIR}/apps/${PLATON_DATA_FROM_BIN} ABSOLUTE)
file(MAKE_DIRECTORY ${PLATON_DATA_MIRROR} ${PLATON_PLUGIN_DIR})
# What share/platon holds: folder in share/platon -> folder in the sources.
set(PLATON_DATA_FOLDERS scripts=scripts levels=levels sounds=sounds scenarios=tests/scenarios replays=tests/replays)
foreach(pair IN LISTS PLATON_DATA_FOLDERS)
  string(REPLACE "=" ";" pair ${pair})
  list(GET pair 0 installed)
  list(GET pair 1 source)
  # Relative, so a checkout moved with its build/ still finds them.
  file(RELATIVE_PATH target ${PLATON_DATA_MIRROR} ${PROJECT_SOURCE_DIR}/${source})
  file(REMOVE ${PLATON_DATA_MIRROR}/${installed})
  file(CREATE_LINK ${target} ${PLATON_DATA_MIRROR}/${installed} SYMBOLIC)
endforeach()
