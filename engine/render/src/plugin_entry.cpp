// The plugin's one exported symbol (core/system.h, PluginEntry): creates the rendering system. No
// C++ exception leaves it.
#include "render_system.h"

extern "C" __attribute__((visibility("default"))) platon::core::System* platon_create_system(platon::core::Scene&,
                                                                                             char* error,
                                                                                             size_t errorSize) {
  return platon::core::createPluginSystem<platon::render::RenderSystem>(error, errorSize);
}
