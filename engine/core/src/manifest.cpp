#include "platon/core/manifest.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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

// The manifest's keys, in the docs' order. Ranges and defaults are the reader's: nothing else
// says them.
const std::vector<ManifestKey> kManifestKeys{
    {"name", "string", 0, 0, 0, "the manifest's path", "the scene's name: titles, the HUD, messages"},
    {"systems", "systems", 0, 0, 0, "-", "what the scene needs: scripting, rendering, meshes, audio"},
    {"stage", "table", 0, 0, 0, "-", "the solid: { level = } or { solid =, edge = }"},
    {"stage.level", "file", 0, 0, 0, "-", "a level file (docs/level-format.md): the solid, lines, start and goal"},
    {"stage.solid", "string", 0, 0, 0, "cube", "tetrahedron, cube, octahedron, dodecahedron or icosahedron"},
    {"stage.edge", "whole number", 64, 1 << 24, 4096, "4096", "a face's edge, in units"},
    {"gravity", "number", 0, 1000, 0.35, "0.35", "units per frame per frame, along each face's -y"},
    {"seed", "whole number", 0, 4294967295.0, 1, "1", "the scene's random seed"},
    {"music", "string", 0, 0, 0, "-", "the tune of the sound bank played from the start (docs/sound.md)"},
    {"sounds", "file", 0, 0, 0, "-", "the level's own sound bank"},
    {"scripts", "table", 0, 0, 0, "-", "the scene's scripts (the systems must list scripting)"},
    {"scripts.preset", "string", 0, 0, 0, "-", "\"game\": the game's rules, player and progression for any not named"},
    {"scripts.rules", "script", 0, 0, 0, "-", "the contact rules"},
    {"scripts.player", "script", 0, 0, 0, "-", "the player"},
    {"scripts.progression", "script", 0, 0, 0, "-", "spawning, the goal, deaths, checkpoints"},
    {"scripts.level", "script", 0, 0, 0, "-", "the level script"},
    {"scripts.mods", "mods", 0, 0, 0, "-", "the level's mods, in order (always sandboxed)"},
    {"limits", "table", 0, 0, 0, "-", "lowers the scripts' ceilings"},
    {"limits.memory_mb", "whole number", 4, 4096, 128, "128", "MB of Lua memory"},
    {"limits.steps", "whole number", 1000, 1'000'000'000, 10'000'000, "10000000", "steps of sandboxed work a frame"},
    {"limits.deadline_ms", "number", 1, 60000, 2000, "2000", "ms of sandboxed script time a frame (the backstop)"},
};

const ManifestKey& manifestKey(std::string_view key) {
  for (const ManifestKey& k : kManifestKeys)
    if (key == k.key) return k;
  throw std::logic_error("no manifest key " + std::string(key));
}

// The keys of the table `section` ("" the manifest's own, "limits"), for checkKeys.
std::vector<std::string> manifestKeysUnder(std::string_view section) {
  std::vector<std::string> out;
  for (const ManifestKey& k : kManifestKeys) {
    const std::string_view key = k.key;
    const size_t dot = key.find('.');
    if (section.empty() ? dot == std::string_view::npos : dot == section.size() && key.substr(0, dot) == section)
      out.emplace_back(section.empty() ? key : key.substr(dot + 1));
  }
  return out;
}

// The number at `key` of `table` (its table's own name dropped), within the key's range.
double manifestNumber(const std::string& path, const DataValue& table, const char* key) {
  const ManifestKey& k = manifestKey(key);
  const char* name = std::strrchr(key, '.') ? std::strrchr(key, '.') + 1 : key;
  return std::string_view(k.holds) == "whole number" ? wholeField(path, table, name, k.fallback, k.low, k.high)
                                                     : numberField(path, table, name, k.fallback, k.low, k.high);
}

// The one path rule of a manifest: every file it names is a relative path inside the scene's
// folder once every link is resolved (no "..", not absolute, no link out); a script or a mod ends
// in .lua; "scripts/..." names an engine script only where a script goes (kept as written, found
// under the engine's root, trusted) and never a mod. Returns the path kept, and says in `engine`
// whether it is the engine's.
std::string manifestFilePath(const std::string& path, const DataValue& v, const char* key, SceneManifest& m,
                             bool& engine) {
  const std::string_view holds = manifestKey(key).holds;
  const bool script = holds == "script", mod = holds == "mods";
  const char* what = mod                                             ? "a mod"
                     : script                                        ? "a script"
                     : holds == "file" && std::strstr(key, "sounds") ? "a sound bank"
                                                                     : "a level file";
  const std::string p = v.isString() ? v.text : "";
  engine = script && p.rfind("scripts/", 0) == 0;
  const bool lua = script || mod;
  if (p.empty() || p.find("..") != std::string::npos || p[0] == '/' ||
      (lua && (p.size() < 5 || p.substr(p.size() - 4) != ".lua")) || (mod && p.rfind("scripts/", 0) == 0))
    fieldError(path, v,
               (v.isString() ? "'" + p + "': " : std::string()) + what + " is a " + (lua ? ".lua " : "") +
                   "path inside the scene's folder" + (script ? " or under scripts/" : "") + " (no '..', not absolute" +
                   (mod ? ", not under scripts/" : "") + ")");
  std::string kept = engine ? p : insideFolder(path, m.directory, v, p);
  m.placeOf[kept] = placeText(path, v);
  return kept;
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
  checkKeys(path, stage, manifestKeysUnder("stage"));
  if (const DataValue* level = stage.field("level")) {
    if (stage.field("solid") || stage.field("edge"))
      fieldError(path, *level, "a level file gives the solid and its size: no 'solid' or 'edge' beside 'level'");
    bool engine = false;
    m.levelFile = manifestFilePath(path, *level, "stage.level", m, engine);
  }
  m.solid = stringField(path, stage, "solid", manifestKey("stage.solid").shown);
  if (!solidOfManifest(m.solid))
    fieldError(path, *stage.field("solid"),
               "unknown solid '" + m.solid + "' (known: tetrahedron, cube, octahedron, dodecahedron, icosahedron)");
  m.edge = static_cast<int32_t>(manifestNumber(path, stage, "stage.edge"));
}

// One of scripts' rules, player, progression or level: "" when not given. Trust is decided here,
// once, from what the manifest wrote (manifestFilePath).
std::string manifestScript(const std::string& path, const DataValue& scripts, const char* key, bool& trusted,
                           SceneManifest& m) {
  trusted = false;
  const DataValue* v = scripts.field(std::strchr(key, '.') + 1);
  if (!v) return "";
  if (!v->isString()) (void)stringField(path, scripts, std::strchr(key, '.') + 1, "");  // its type's error
  if (v->text.empty()) return "";
  return manifestFilePath(path, *v, key, m, trusted);
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
    if (!e.key.isNumber() || e.key.number != ++index)
      fieldError(path, e.value, "'mods' must be a list of paths ({ \"a.lua\", \"b.lua\" }), not keyed");
    bool engine = false;
    m.mods.push_back(manifestFilePath(path, e.value, "scripts.mods", m, engine));
  }
}

// scripts = { preset =, rules =, player =, progression =, level =, mods = }: read after the
// systems, which must then list "scripting".
void readManifestScripts(const std::string& path, const DataValue& scripts, SceneManifest& m) {
  if (!scripts.isTable()) fieldError(path, scripts, "'scripts' must be a table");
  checkKeys(path, scripts, manifestKeysUnder("scripts"));
  m.rules = manifestScript(path, scripts, "scripts.rules", m.rulesTrusted, m);
  m.player = manifestScript(path, scripts, "scripts.player", m.playerTrusted, m);
  m.progression = manifestScript(path, scripts, "scripts.progression", m.progressionTrusted, m);
  if (const DataValue* preset = scripts.field("preset")) applyManifestPreset(path, *preset, m);
  m.level = manifestScript(path, scripts, "scripts.level", m.levelTrusted, m);
  if (const DataValue* mods = scripts.field("mods")) readManifestMods(path, *mods, m);
  if (!m.rules.empty() || !m.player.empty() || !m.progression.empty() || !m.level.empty() || !m.mods.empty())
    if (!m.needs("scripting"))
      fieldError(path, scripts, "the scene has scripts but does not list \"scripting\" in its systems");
}

// limits = { memory_mb =, steps =, deadline_ms = }: the scripts' budgets, each within its range.
void readManifestLimits(const std::string& path, const DataValue& limits, SceneManifest& m) {
  if (!limits.isTable()) fieldError(path, limits, "'limits' must be a table {memory_mb =, steps =, deadline_ms =}");
  checkKeys(path, limits, manifestKeysUnder("limits"));
  m.memoryMegabytes = static_cast<size_t>(manifestNumber(path, limits, "limits.memory_mb"));
  m.frameSteps = static_cast<int64_t>(manifestNumber(path, limits, "limits.steps"));
  m.deadlineMilliseconds = manifestNumber(path, limits, "limits.deadline_ms");
}

}  // namespace

const std::vector<ManifestKey>& manifestKeys() { return kManifestKeys; }

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
  checkKeys(path, root, manifestKeysUnder(""));

  SceneManifest m;
  m.path = path;
  const size_t slash = path.find_last_of('/');
  m.directory = slash == std::string::npos ? "." : path.substr(0, slash);
  m.name = stringField(path, root, "name", path);
  if (const DataValue* systems = root.field("systems")) readManifestSystems(path, *systems, m);
  if (const DataValue* stage = root.field("stage")) readManifestStage(path, *stage, m);
  m.gravity = manifestNumber(path, root, "gravity");
  m.seed = static_cast<uint32_t>(manifestNumber(path, root, "seed"));
  if (const DataValue* music = root.field("music")) {
    m.music = stringField(path, root, "music", "");
    m.musicPlace = placeText(path, *music);
  }
  if (const DataValue* sounds = root.field("sounds")) {
    bool engine = false;
    m.soundBank = manifestFilePath(path, *sounds, "sounds", m, engine);
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
