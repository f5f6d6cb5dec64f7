#include "platon/core/data_root.h"

#include <algorithm>
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
  std::string root = programFolder() + "/" PLATON_DATA_FROM_BIN;
  std::error_code error;
  if (!std::filesystem::is_regular_file(root + "/scripts/scene.lua", error))
    throw std::runtime_error("cannot find the engine's scripts: no " + root +
                             "/scripts/scene.lua (the program's data folder, found from the program's own); set "
                             "PLATON_ROOT to a folder with scripts/ and levels/");
  return root;
}

std::string engineFile(const std::string& relative) {
  std::error_code error;
  std::string chosen = dataRoot() + "/" + relative;
  if (std::filesystem::exists(chosen, error)) return chosen;
  return programFolder() + "/" PLATON_DATA_FROM_BIN "/" + relative;
}

std::string pluginFolder() { return programFolder() + "/" PLATON_PLUGINS_FROM_BIN; }

namespace {

// `path` relative to `folder` when it lies inside it (both as the file system resolves them).
std::optional<std::string> inside(const std::filesystem::path& path, const std::filesystem::path& folder) {
  std::error_code error;
  const std::filesystem::path root = std::filesystem::canonical(folder, error);
  if (error) return std::nullopt;
  const std::filesystem::path relative = path.lexically_relative(root);
  if (relative.empty() || *relative.begin() == ".." || relative.is_absolute()) return std::nullopt;
  return relative.generic_string();
}

}  // namespace

std::optional<std::string> portableScenePath(const std::string& path) {
  const std::filesystem::path given(path);
  if (!path.empty() && given.is_relative() &&
      std::none_of(given.begin(), given.end(), [](const std::filesystem::path& step) { return step == ".."; }))
    return path;
  std::error_code error;
  const std::filesystem::path file = std::filesystem::weakly_canonical(path, error);
  if (error) return std::nullopt;
  try {  // each folder of the data folder on its own: in the build tree they are links to the sources
    const std::string root = dataRoot();
    for (const char* folder : {"levels", "scenarios", "replays", "scripts"})
      if (const std::optional<std::string> in = inside(file, root + "/" + folder))
        return std::string(folder) + "/" + *in;
  } catch (const std::runtime_error&) {}
  return inside(file, std::filesystem::current_path(error));
}

std::string resolveNamedPath(const std::string& path, const std::string& namingFile) {
  std::error_code error;
  if (!path.empty() && path[0] != '/') {
    const std::filesystem::path beside = std::filesystem::path(namingFile).parent_path() / path;
    if (!beside.parent_path().empty() && std::filesystem::exists(beside, error)) return beside.string();
  }
  return resolveDataPath(path);
}

std::string resolveDataPath(const std::string& path) {
  std::error_code error;
  if (path.empty() || path[0] == '/' || std::filesystem::exists(path, error)) return path;
  try {
    std::string installed = dataRoot() + "/" + path;
    if (std::filesystem::exists(installed, error)) return installed;
  } catch (const std::runtime_error&) {
    // No data folder: the path stays as given, and its reader says it is missing.
  }
  return path;
}

}  // namespace platon::core
