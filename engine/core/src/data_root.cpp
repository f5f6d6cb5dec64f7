#include "platon/core/data_root.h"

#include <climits>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace platon::core {

// PLATON_DATA_FROM_BIN and PLATON_PLUGINS_FROM_BIN are the install layout's folders relative to
// the program's ("../share/platon", "../lib/platon"), set by the build (cmake/layout.cmake).

std::string programFolder() {
  char self[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  if (n <= 0) return ".";
  const std::string exe(self, static_cast<size_t>(n));
  return exe.substr(0, exe.find_last_of('/'));
}

std::string dataRoot() {
  if (const char* root = std::getenv("PLATON_ROOT"); root && *root) return root;
  const std::string root = programFolder() + "/" PLATON_DATA_FROM_BIN;
  std::error_code error;
  if (!std::filesystem::is_regular_file(root + "/scripts/scene.lua", error))
    throw std::runtime_error("cannot find the engine's scripts: no " + root +
                             "/scripts/scene.lua (the program's data folder, found from the program's own); set "
                             "PLATON_ROOT to a folder with scripts/ and levels/");
  return root;
}

std::string pluginFolder() { return programFolder() + "/" PLATON_PLUGINS_FROM_BIN; }

std::string resolveDataPath(const std::string& path) {
  std::error_code error;
  if (path.empty() || path[0] == '/' || std::filesystem::exists(path, error)) return path;
  try {
    const std::string installed = dataRoot() + "/" + path;
    if (std::filesystem::exists(installed, error)) return installed;
  } catch (const std::runtime_error&) {
    // No data folder: the path stays as given, and its reader says it is missing.
  }
  return path;
}

}  // namespace platon::core
