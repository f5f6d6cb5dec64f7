// The plugin's one exported symbol (core/system.h, PluginEntry): creates the rendering system. No
// C++ exception leaves it.
#include <cstdio>
#include <exception>

#include "render_system.h"

extern "C" __attribute__((visibility("default"))) platon::core::System* platon_create_system(platon::core::Scene&,
                                                                                              char* error, size_t errorSize) {
  try {
    return new platon::render::RenderSystem();
  } catch (const std::exception& e) {
    std::snprintf(error, errorSize, "%s", e.what());
  } catch (...) {
    std::snprintf(error, errorSize, "unknown error");
  }
  return nullptr;
}
