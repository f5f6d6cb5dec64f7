#include "engine_registry.h"

#include <string>

#include "platon/core/data_root.h"
#include "platon/script/script_system.h"

namespace platon::app {

std::vector<std::string> pluginFolders() { return {core::pluginFolder()}; }

core::SystemRegistry engineRegistry(Presentation presentation) {
  core::SystemRegistry registry;
  registry.add("scripting", script::makeScriptSystem);
  registry.addPlugin("meshes", "platon_meshes", pluginFolders());  // headless too: a mesh stage is physics
  if (presentation != Presentation::Headless) registry.addPlugin("rendering", "platon_render", pluginFolders());
  if (presentation == Presentation::Window) registry.addPlugin("audio", "platon_audio", pluginFolders());
  return registry;
}

}  // namespace platon::app
