#include "level_argument.h"

#include <filesystem>
#include <stdexcept>

#include "platon/core/data_root.h"
#include "platon/core/manifest.h"

namespace platon::app {
namespace {

namespace fs = std::filesystem;

bool regularFile(const std::string& path) {
  std::error_code error;
  return fs::is_regular_file(path, error);
}

}  // namespace

LevelArgument levelArgument(const std::string& argument) {
  LevelArgument out;
  if (argument.ends_with(".level")) {
    out.levelFile = core::resolveDataPath(argument);
    const std::string beside = fs::path(out.levelFile).parent_path().empty()
                                   ? std::string("scene.lua")
                                   : (fs::path(out.levelFile).parent_path() / "scene.lua").string();
    if (regularFile(beside)) out.scene = beside;
    return out;
  }
  if (argument.ends_with(".lua")) {
    out.scene = core::resolveDataPath(argument);
  } else {
    std::string trimmed = argument;
    while (trimmed.size() > 1 && trimmed.back() == '/') trimmed.pop_back();
    for (const std::string& candidate : {trimmed + "/scene.lua", "levels/" + trimmed + "/scene.lua"})
      if (const std::string found = core::resolveDataPath(candidate); regularFile(found)) {
        out.scene = found;
        break;
      }
    if (out.scene.empty())
      throw std::runtime_error(argument +
                               ": no level here (a level is its folder, its scene.lua, its .level file, or a folder "
                               "name under levels/; looked for " +
                               trimmed + "/scene.lua and levels/" + trimmed + "/scene.lua)");
  }
  out.levelFile = core::loadManifest(out.scene).levelFile;  // a broken manifest says why, at its place
  return out;
}

}  // namespace platon::app
