// The plugin's one exported symbol (core/system.h, PluginEntry): creates the meshes system. No
// C++ exception leaves it.
#include <cstdio>
#include <exception>

#include "mesh_system.h"

extern "C" __attribute__((visibility("default"))) platon::core::System* platon_create_system(platon::core::Scene&,
                                                                                              char* error, size_t errorSize) {
  try {
    return new platon::mesh::MeshSystem();
  } catch (const std::exception& e) {
    std::snprintf(error, errorSize, "%s", e.what());
  } catch (...) {
    std::snprintf(error, errorSize, "unknown error");
  }
  return nullptr;
}
