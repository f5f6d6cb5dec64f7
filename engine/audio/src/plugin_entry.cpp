// The plugin's one exported symbol (core/system.h, PluginEntry): creates the audio system with the
// scene's sound bank. No C++ exception leaves it.
#include <cstdio>
#include <exception>

#include "audio_system.h"
#include "platon/core/scene.h"

extern "C" __attribute__((visibility("default"))) platon::core::System* platon_create_system(platon::core::Scene& scene,
                                                                                             char* error,
                                                                                             size_t errorSize) {
  try {
    return new platon::audio::AudioSystem(scene.sounds().bank());
  } catch (const std::exception& e) {
    std::snprintf(error, errorSize, "%s", e.what());
  } catch (...) {
    std::snprintf(error, errorSize, "unknown error");
  }
  return nullptr;
}
