#include "engine_registry.h"

#include <climits>
#include <string>
#include <unistd.h>

#include "platon/script/script_system.h"

namespace platon::app {
// Beside the program (an installed tree: <bin>/plugins), then the build tree's plugin folder.
std::vector<std::string> pluginFolders() {
  std::vector<std::string> folders;
  char self[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n > 0) {
    const std::string exe(self, static_cast<size_t>(n));
    folders.push_back(exe.substr(0, exe.find_last_of('/')) + "/plugins");
  }
  folders.push_back(PLATON_PLUGIN_DIR);
  return folders;
}

core::SystemRegistry engineRegistry(Presentation presentation) {
  core::SystemRegistry registry;
  registry.add("scripting", script::makeScriptSystem);
  registry.addPlugin("meshes", "platon_meshes", pluginFolders());  // headless too: a mesh stage is physics
  if (presentation == Presentation::Window) registry.addPlugin("rendering", "platon_render", pluginFolders());
  return registry;
}

}  // namespace platon::app
