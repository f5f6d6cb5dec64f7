#include "platon/core/manifest.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits.h>
#include <sstream>
#include <stdexcept>
#include <stdlib.h>

#include "data_fields.h"
#include "platon/files/read_file.h"

namespace platon::core {

namespace {

std::string realPath(const std::string& path) {
  char resolved[PATH_MAX];
  return ::realpath(path.c_str(), resolved) ? std::string(resolved) : std::string();
}

// A level's own file: `p` (no "..", not absolute: checked by the caller) inside the manifest's
// folder, with every link resolved, and refused when a link leads out of the folder. A file that
// does not exist (yet) is the folder's real path joined with p: loading it says it is missing.
std::string insideFolder(const std::string& manifest, const std::string& folder, const DataValue& where,
                         const std::string& p) {
  const std::string realFolder = realPath(folder);
  if (realFolder.empty()) fieldError(manifest, where, "'" + folder + "': the scene's folder cannot be resolved");
  std::string file = realPath(folder + "/" + p);
  if (file.empty()) return realFolder + "/" + p;
  if (file.rfind(realFolder + "/", 0) != 0)
    fieldError(manifest, where, "'" + p + "' leads to " + file + ", outside the scene's folder (a link?)");
  return file;
}

// systems = { "scripting", ... }: each one a system the engine knows.
void readManifestSystems(const std::string& path, const DataValue& systems, SceneManifest& m) {
  if (!systems.isTable()) fieldError(path, systems, "'systems' must be a list of names");
  for (const DataEntry& e : systems.entries) {
    const DataValue& v = e.value;
    if (!v.isString()) fieldError(path, v, "'systems' must be a list of names");
    const std::string& s = v.text;
    if (s != "scripting" && s != "rendering" && s != "meshes" && s != "audio")
      fieldError(path, v, "unknown system '" + s + "' (known: scripting, rendering, meshes, audio)");
    m.systems.push_back(s);
  }
}

// stage = { solid =, edge = } or { level = }: a level file names its solid and size itself.
void readManifestStage(const std::string& path, const DataValue& stage, SceneManifest& m) {
  if (!stage.isTable()) fieldError(path, stage, "'stage' must be a table {solid =, edge =} or {level =}");
  checkKeys(path, stage, {"solid", "edge", "level"});
  if (const DataValue* level = stage.field("level")) {
    if (stage.field("solid") || stage.field("edge"))
      fieldError(path, *level, "a level file gives the solid and its size: no 'solid' or 'edge' beside 'level'");
    const std::string p = stringField(path, stage, "level", "");
    if (p.empty() || p.find("..") != std::string::npos || p[0] == '/')
      fieldError(path, *level, "'" + p + "': a level file is a path inside the scene's folder (no '..', not absolute)");
    m.levelFile = insideFolder(path, m.directory, *level, p);
    m.placeOf[m.levelFile] = placeText(path, *level);
  }
  m.solid = stringField(path, stage, "solid", m.solid);
  if (!solidOfManifest(m.solid))
    fieldError(path, *stage.field("solid"),
               "unknown solid '" + m.solid + "' (known: tetrahedron, cube, octahedron, dodecahedron, icosahedron)");
  m.edge = static_cast<int32_t>(wholeField(path, stage, "edge", m.edge, 64, 1 << 24));
}

// One of scripts' rules, player, progression or level: "" when not given. Trust is decided here,
// once, from what the manifest wrote: "scripts/..." names an engine script (trusted; the script
// system finds it under the engine's root), anything else is the level's own (sandboxed),
// resolved inside the manifest's folder.
std::string manifestScript(const std::string& path, const DataValue& scripts, const char* key, bool& trusted,
                           SceneManifest& m) {
  std::string p = stringField(path, scripts, key, "");
  trusted = false;
  if (p.empty()) return p;
  const bool engine = p.rfind("scripts/", 0) == 0;
  if (p.find("..") != std::string::npos || p[0] == '/' || p.size() < 5 || p.substr(p.size() - 4) != ".lua")
    fieldError(
        path, *scripts.field(key),
        "'" + p + "': a script is a .lua path inside the level's folder or under scripts/ (no '..', not absolute)");
  trusted = engine;
  std::string kept = engine ? p : insideFolder(path, m.directory, *scripts.field(key), p);
  m.placeOf[kept] = placeText(path, *scripts.field(key));
  return kept;
}

// preset = "game": the game's own rules, player and progression, for any of the three the
// manifest does not name itself (every campaign level uses them).
void applyManifestPreset(const std::string& path, const DataValue& preset, SceneManifest& m) {
  if (!preset.isString() || preset.text != "game") fieldError(path, preset, "unknown script preset (known: \"game\")");
  if (m.rules.empty()) m.rules = "scripts/rules/game.lua", m.rulesTrusted = true;
  if (m.player.empty()) m.player = "scripts/player.lua", m.playerTrusted = true;
  if (m.progression.empty()) m.progression = "scripts/progression.lua", m.progressionTrusted = true;
}

// mods = { "a.lua", "b.lua" }: the level's own files, in order, each sandboxed.
void readManifestMods(const std::string& path, const DataValue& mods, SceneManifest& m) {
  if (!mods.isTable()) fieldError(path, mods, "'mods' must be a list of paths");
  double index = 0;
  for (const DataEntry& e : mods.entries) {
    const DataValue& v = e.value;
    if (!e.key.isNumber() || e.key.number != ++index)
      fieldError(path, v, "'mods' must be a list of paths ({ \"a.lua\", \"b.lua\" }), not keyed");
    const std::string* p = v.isString() ? &v.text : nullptr;
    if (!p || p->size() < 5 || p->substr(p->size() - 4) != ".lua" || p->find("..") != std::string::npos ||
        p->rfind("scripts/", 0) == 0 || (*p)[0] == '/')
      fieldError(path, v, "a mod is a .lua path inside the level's folder (no '..', not absolute, not under scripts/)");
    m.mods.push_back(insideFolder(path, m.directory, v, *p));
    m.placeOf[m.mods.back()] = placeText(path, v);
  }
}

// scripts = { preset =, rules =, player =, progression =, level =, mods = }: read after the
// systems, which must then list "scripting".
void readManifestScripts(const std::string& path, const DataValue& scripts, SceneManifest& m) {
  if (!scripts.isTable()) fieldError(path, scripts, "'scripts' must be a table");
  checkKeys(path, scripts, {"preset", "rules", "player", "progression", "level", "mods"});
  m.rules = manifestScript(path, scripts, "rules", m.rulesTrusted, m);
  m.player = manifestScript(path, scripts, "player", m.playerTrusted, m);
  m.progression = manifestScript(path, scripts, "progression", m.progressionTrusted, m);
  if (const DataValue* preset = scripts.field("preset")) applyManifestPreset(path, *preset, m);
  m.level = manifestScript(path, scripts, "level", m.levelTrusted, m);
  if (const DataValue* mods = scripts.field("mods")) readManifestMods(path, *mods, m);
  if (!m.rules.empty() || !m.player.empty() || !m.progression.empty() || !m.level.empty() || !m.mods.empty())
    if (!m.needs("scripting"))
      fieldError(path, scripts, "the scene has scripts but does not list \"scripting\" in its systems");
}

// limits = { memory_mb =, steps =, deadline_ms = }: the scripts' budgets, each within its range.
void readManifestLimits(const std::string& path, const DataValue& limits, SceneManifest& m) {
  if (!limits.isTable()) fieldError(path, limits, "'limits' must be a table {memory_mb =, steps =, deadline_ms =}");
  checkKeys(path, limits, {"memory_mb", "steps", "deadline_ms"});
  m.memoryMegabytes = static_cast<size_t>(wholeField(path, limits, "memory_mb", 128, 4, 4096));
  m.frameSteps = static_cast<int64_t>(wholeField(path, limits, "steps", 10'000'000, 1000, 1'000'000'000));
  m.deadlineMilliseconds = numberField(path, limits, "deadline_ms", 2000, 1, 60000);
}

}  // namespace

bool SceneManifest::needs(std::string_view system) const {
  for (const auto& s : systems)
    if (s == system) return true;
  return false;
}

SceneManifest loadManifest(const std::string& path) {
  std::string text;
  try {
    text = files::readBoundedFile(path, kMaxManifestBytes);
  } catch (const files::FileError& e) {
    throw std::runtime_error(path + ": the manifest: " + e.reason());
  }
  const DataValue root = readLuaData(text, path);
  if (!root.isTable()) fieldError(path, root, "a manifest is a table: return { ... }");
  checkKeys(path, root, {"name", "systems", "stage", "gravity", "scripts", "limits", "seed", "music", "sounds"});

  SceneManifest m;
  m.path = path;
  const size_t slash = path.find_last_of('/');
  m.directory = slash == std::string::npos ? "." : path.substr(0, slash);
  m.name = stringField(path, root, "name", path);
  if (const DataValue* systems = root.field("systems")) readManifestSystems(path, *systems, m);
  if (const DataValue* stage = root.field("stage")) readManifestStage(path, *stage, m);
  m.gravity = numberField(path, root, "gravity", m.gravity, 0, 1000);
  m.seed = static_cast<uint32_t>(wholeField(path, root, "seed", m.seed, 0, 4294967295.0));
  if (const DataValue* music = root.field("music")) {
    m.music = stringField(path, root, "music", "");
    m.musicPlace = placeText(path, *music);
  }
  if (const DataValue* sounds = root.field("sounds")) {
    const std::string p = stringField(path, root, "sounds", "");
    if (p.empty() || p.find("..") != std::string::npos || p[0] == '/')
      fieldError(path, *sounds,
                 "'" + p + "': a sound bank is a path inside the scene's folder (no '..', not absolute)");
    m.soundBank = insideFolder(path, m.directory, *sounds, p);
    m.placeOf[m.soundBank] = placeText(path, *sounds);
  }
  if (const DataValue* scripts = root.field("scripts")) readManifestScripts(path, *scripts, m);
  if (const DataValue* limits = root.field("limits")) readManifestLimits(path, *limits, m);
  return m;
}

std::optional<stage::Solid> solidOfManifest(const std::string& name) {
  using stage::Solid;
  if (name == "tetrahedron") return Solid::Tetrahedron;
  if (name == "cube" || name == "hexahedron") return Solid::Hexahedron;
  if (name == "octahedron") return Solid::Octahedron;
  if (name == "dodecahedron") return Solid::Dodecahedron;
  if (name == "icosahedron") return Solid::Icosahedron;
  return std::nullopt;
}

}  // namespace platon::core
