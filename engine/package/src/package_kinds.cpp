// Which files a level package carries: the kinds of data a level is made of, and the Lua its scene
// names. Anything else (a scenario, a script nothing loads, a program, an unknown kind) stays out of
// a package and out of an installed level, and is named, so nothing a scene does not load travels
// with it (a kept test is Lua a person might run; a stray file is nobody's to vouch for).
#include <algorithm>
#include <array>
#include <filesystem>
#include <set>

#include "platon/core/manifest.h"
#include "platon/package/package.h"

namespace platon::package {
namespace {

namespace fs = std::filesystem;

// The kinds of data: the level format, replays, the mesh formats the meshes system reads and the
// files they name (an OBJ's material library, a glTF's buffers), and plain text (a read-me).
constexpr std::array<std::string_view, 11> kDataKinds = {".level", ".replay", ".obj", ".mtl", ".gltf", ".glb",
                                                         ".bin",   ".ply",    ".stl", ".txt", ".md"};

bool dataKind(const fs::path& file) {
  std::string ending = file.extension().string();
  std::transform(ending.begin(), ending.end(), ending.begin(), [](unsigned char c) { return std::tolower(c); });
  return std::find(kDataKinds.begin(), kDataKinds.end(), ending) != kDataKinds.end();
}

// The real paths of the Lua files the scene loads: the manifest, the level's own scripts and mods,
// the sound bank.
std::set<std::string> namedByTheScene(const fs::path& scene) {
  const core::SceneManifest m = core::loadManifest(scene.string());
  std::set<std::string> named{fs::canonical(scene).string()};
  const std::pair<const std::string*, bool> scripts[] = {{&m.rules, m.rulesTrusted},
                                                         {&m.player, m.playerTrusted},
                                                         {&m.progression, m.progressionTrusted},
                                                         {&m.level, m.levelTrusted}};
  for (const auto& [path, trusted] : scripts)
    if (!path->empty() && !trusted) named.insert(*path);
  named.insert(m.mods.begin(), m.mods.end());
  if (!m.soundBank.empty()) named.insert(m.soundBank);
  return named;
}

}  // namespace

std::vector<std::string> removeUncarriedFiles(const std::string& levelFolder) {
  const fs::path dir(levelFolder);
  const std::set<std::string> named = namedByTheScene(dir / "scene.lua");
  std::vector<fs::path> uncarried;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(dir)) {
    if (fs::is_directory(entry.symlink_status())) continue;  // a link is judged by its name (and refused later)
    if (dataKind(entry.path())) continue;
    std::error_code error;
    const fs::path real = fs::canonical(entry.path(), error);
    if (!error && named.count(real.string())) continue;
    uncarried.push_back(entry.path());
  }
  std::sort(uncarried.begin(), uncarried.end());
  std::vector<std::string> left;
  for (const fs::path& file : uncarried) {
    const std::string name = file.lexically_relative(dir).generic_string();
    left.push_back(name + (file.extension() == ".lua" ? ": Lua that scene.lua does not load (a kept test?)"
                                                      : ": not a kind a level is made of"));
    fs::remove(file);
  }
  return left;
}

}  // namespace platon::package
