# `cmake --install build [--prefix P]`: the game as a Linux game is laid out (GNUInstallDirs):
#   bin/platon                     the program
#   lib/platon/                    its plugins (renderer, meshes), loaded on demand
#   share/platon/                  scripts, levels, the shipped scenarios and replays
#   share/applications/, share/metainfo/, share/icons/   the desktop entry, AppStream data, icon
# The tree works wherever it is put (data_root.h). The renderer's shaders are compiled into its
# plugin. `cpack` (in build/) makes a Debian package of the same tree under /usr.
install(TARGETS platon RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS platon_render_plugin platon_mesh_plugin platon_audio_plugin LIBRARY DESTINATION ${PLATON_INSTALL_PLUGINDIR})
foreach(pair IN LISTS PLATON_DATA_FOLDERS)
  string(REPLACE "=" ";" pair ${pair})
  list(GET pair 0 installed)
  list(GET pair 1 source)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${source}/ DESTINATION ${PLATON_INSTALL_DATADIR}/${installed})
endforeach()
set(PLATON_APP_ID io.github.platon_game.Platon)
install(FILES ${PROJECT_SOURCE_DIR}/dist/${PLATON_APP_ID}.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_SOURCE_DIR}/dist/${PLATON_APP_ID}.metainfo.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
install(FILES ${PROJECT_SOURCE_DIR}/dist/${PLATON_APP_ID}.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)

# The Debian package: every file above under /usr; its library dependencies found by
# dpkg-shlibdeps from the program and the plugins (dpkg-dev), the font and libGL named by hand.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME platon)
set(CPACK_PACKAGE_VENDOR "The Platon developers")
# No public address yet: .invalid is reserved (RFC 2606) so it can never reach anyone by mistake.
set(CPACK_PACKAGE_CONTACT "The Platon developers <platon@example.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION "Platon is a puzzle platformer whose 2D levels are drawn on the faces of a 3D convex \
solid. Crossing a face's edge turns the solid, so down changes and walls become floors. Levels, rules and players are \
scripted in Lua.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION games)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core, libgl1")  # libepoxy opens libGL at run time
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libgl1-mesa-dri")
set(CPACK_STRIP_FILES ON)
include(CPack)
