// Systems in shared modules: the heavy ones (the window and GL renderer, mesh loading) are not linked
// into the engine, so a process that never needs them never maps their libraries (SDL2's video,
// libGL, assimp). A headless scenario proves it by reading /proc/self/maps.
#include <algorithm>
#include <cstdlib>
#include <dlfcn.h>
#include <stdexcept>

#include "platon/core/system.h"

namespace platon::core {
namespace {

std::vector<std::string> searchFolders(const std::vector<std::string>& folders) {
  std::vector<std::string> out;
  if (const char* path = std::getenv("PLATON_PLUGIN_PATH")) {
    std::string all = path;
    for (size_t start = 0; start <= all.size();) {
      const size_t end = std::min(all.find(':', start), all.size());
      if (end > start) out.push_back(all.substr(start, end - start));
      start = end + 1;
    }
  }
  out.insert(out.end(), folders.begin(), folders.end());
  return out;
}

// Loads the module once per process: dlopen counts references, and no handle is ever closed, since
// the code of a system must stay mapped as long as any instance of it lives.
PluginEntry* findEntry(const std::string& name, const std::string& module, const std::vector<std::string>& folders) {
  std::string tried;
  for (const std::string& folder : searchFolders(folders)) {
    const std::string file = folder + (folder.ends_with('/') ? "lib" : "/lib") + module + ".so";
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      tried += "\n  " + (why ? std::string(why) : file + ": cannot be loaded");
      continue;
    }
    if (auto* entry = reinterpret_cast<PluginEntry*>(dlsym(handle, kPluginEntryName))) return entry;
    dlclose(handle);  // not a plugin: it need not stay loaded
    tried += "\n  " + file + ": no " + kPluginEntryName + " in it";
  }
  throw std::runtime_error("system '" + name + "': cannot load its plugin lib" + module + ".so" +
                           (tried.empty() ? std::string(" (no folder to look in)") : ":" + tried));
}

}  // namespace

void SystemRegistry::addPlugin(const std::string& name, const std::string& module, std::vector<std::string> folders) {
  PluginEntry* entry = nullptr;  // found on first use, shared by every scene this factory makes
  add(name, [name, module, folders = std::move(folders), entry](Scene& scene) mutable -> std::unique_ptr<System> {
    if (!entry) entry = findEntry(name, module, folders);
    char error[512] = "";
    System* system = entry(scene, error, sizeof error);
    if (!system)
      throw std::runtime_error("system '" + name + "': " + (error[0] ? error : "its plugin refused the scene"));
    return std::unique_ptr<System>(system);
  });
}

}  // namespace platon::core
