// The plugin's one exported symbol (core/system.h, PluginEntry): creates the meshes system. No
// C++ exception leaves it.
#include "mesh_system.h"

extern "C" __attribute__((visibility("default"))) platon::core::System* platon_create_system(platon::core::Scene&,
                                                                                             char* error,
                                                                                             size_t errorSize) {
  return platon::core::createPluginSystem<platon::mesh::MeshSystem>(error, errorSize);
}
