// A scene manifest: a Lua table literal that names what a scene needs. It is data, read in C++
// without a Lua state by the data reader (lua_data.h; a scene with no scripts never creates one).
// Anything else (a function call, an expression, a variable) is an error at file:line:column.
// docs/scripting.md documents the fields.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "platon/core/lua_data.h"
#include "platon/stage/polyhedron.h"

namespace platon::core {

struct SceneManifest {
  std::string path;       // the manifest file
  std::string directory;  // its folder: level-relative paths resolve here
  std::string name;
  std::vector<std::string> systems;  // "scripting", "rendering", "meshes", "audio"
  std::string solid = "cube";        // tetrahedron | cube | octahedron | dodecahedron | icosahedron
  int32_t edge = 4096;               // face edge, units
  // stage = { level = "x.level" }: a level file (docs/level-format.md), relative to the manifest,
  // gives the solid, the lines, start and goal instead of solid and edge.
  std::string levelFile;
  double gravity = 0.35;  // units per frame per frame, along each face's -y
  // Scripts: "scripts/..." names an engine script (trusted; kept as written, the script system
  // finds it under the engine's root); any other path is the level's own, relative to the
  // manifest, resolved (links included) and kept inside its folder, and runs sandboxed. Mods are
  // always the level's own.
  std::string rules, player, progression, level;
  std::vector<std::string> mods;
  // Which of the four are engine scripts: decided by the parser from what the manifest wrote,
  // never from a joined path.
  bool rulesTrusted = false, playerTrusted = false, progressionTrusted = false, levelTrusted = false;
  // Where the manifest names each of its scripts and the level file ("scene.lua:7:13"), by the
  // path kept above: a file that cannot be opened is reported at that place.
  std::map<std::string, std::string> placeOf;
  // limits = { memory_mb, steps, deadline_ms }: the script system uses them only to lower its own
  // limits (the Lua state's memory, the frame's budget of steps, the frame's wall-clock deadline).
  size_t memoryMegabytes = 128;
  int64_t frameSteps = 10'000'000;
  double deadlineMilliseconds = 2000;
  uint32_t seed = 1;
  // music = "name": the tune of the level's bank (or the engine's) played from its start, and where
  // the manifest names it. sounds = "file": the level's own sound bank (core/sound.h), inside its
  // folder like its scripts.
  std::string music, musicPlace;
  std::string soundBank;

  bool needs(std::string_view system) const;
};

// One key a manifest may have: one table (engine/core/src/manifest.cpp) for the reader, its lists
// of known keys, its ranges and defaults, and docs/scripting.md's table of them (a test compares).
struct ManifestKey {
  const char* key;    // "gravity", "limits.steps": a table's keys after its own name and a dot
  const char* holds;  // "number", "whole number", "string", "file", "script", "mods", "systems", "table"
  double low, high;   // a number's range
  double fallback;    // a number's default
  const char* shown;  // the default as the docs show it ("-": none)
  const char* does;
};
const std::vector<ManifestKey>& manifestKeys();

// Reads and checks a manifest file; throws std::runtime_error "file:line:column: reason".
// A manifest is a regular file of at most this.
inline constexpr size_t kMaxManifestBytes = size_t{1} << 20;
SceneManifest loadManifest(const std::string& path);

// The manifest's name for a solid ("cube", "icosahedron", ...), or nothing.
std::optional<stage::Solid> solidOfManifest(const std::string& name);

}  // namespace platon::core
