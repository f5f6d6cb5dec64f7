# The architecture as CMake enforces it. Each engine module is one target; a module may link only
# the modules its arrows allow (docs/architecture.md):
#
#   physics  <- stage <- core <- script          render -> core's headers (a plugin)
#                 ^               |   (script -> stage, physics)
#
# Two checks, both in every build:
#  - configure time: a module whose link libraries name a platon_ target outside its arrows stops
#    the configuration with an error naming the arrow;
#  - link time: each module is linked whole (every object file) into a small program with nothing
#    but its allowed modules, so a module whose code calls one it may not use fails to link, even
#    when the game, which links everything, would have hidden it.

set(PLATON_ARROWS_platon_physics "")
set(PLATON_ARROWS_platon_files "")
set(PLATON_ARROWS_platon_stage platon_physics platon_files)
set(PLATON_ARROWS_platon_core platon_stage platon_physics platon_camera platon_files platon_synth)
set(PLATON_ARROWS_platon_script platon_core platon_stage platon_physics platon_camera platon_files)
# The renderer is a plugin: core's headers only (plain data and interfaces), no engine library.
set(PLATON_ARROWS_platon_render platon_camera)
set(PLATON_ARROWS_platon_camera "")
set(PLATON_ARROWS_platon_synth "")
# The audio system is a plugin too: the synthesizer and core's headers, no engine library.
set(PLATON_ARROWS_platon_audio platon_synth)
set(PLATON_ARROWS_platon_mesh platon_files)
# Level packages: the data reader (core) for their manifests, bounded reads (files).
set(PLATON_ARROWS_platon_package platon_core platon_files)
# The level editor: the level document (stage's format), the picture (core's draw lists), the camera.
set(PLATON_ARROWS_platon_editor platon_core platon_stage platon_physics platon_camera platon_files)
# A scene played in a window and its tools: the scene and its run (core), the console and status
# (script), the camera, the player's folders (files).
set(PLATON_ARROWS_platon_session platon_core platon_script platon_stage platon_physics platon_camera platon_files)

set(PLATON_MODULES "" CACHE INTERNAL "")

# Declares `target` a module: it gets the arrow check and a whole-archive link check (and, with
# PLATON_UNITY, is built as a unity build).
function(platon_module target)
  if(PLATON_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON)
  endif()
  set(PLATON_MODULES ${PLATON_MODULES} ${target} CACHE INTERNAL "")
  set(check ${target}_link_check)
  file(WRITE ${CMAKE_BINARY_DIR}/link_check_main.cpp "int main() { return 0; }\n")
  add_executable(${check} ${CMAKE_BINARY_DIR}/link_check_main.cpp)
  target_link_libraries(${check} PRIVATE "$<LINK_LIBRARY:WHOLE_ARCHIVE,${target}>")
endfunction()

function(platon_check_architecture)
  foreach(module IN LISTS PLATON_MODULES)
    get_target_property(links ${module} LINK_LIBRARIES)
    if(NOT links)
      continue()
    endif()
    foreach(lib IN LISTS links)
      if(lib MATCHES "^platon_" AND NOT lib IN_LIST PLATON_ARROWS_${module})
        message(FATAL_ERROR "architecture: ${module} links ${lib}, an arrow docs/architecture.md does not allow "
                            "(allowed: ${PLATON_ARROWS_${module}})")
      endif()
    endforeach()
  endforeach()
endfunction()
