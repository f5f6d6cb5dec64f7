// Headless regression scenarios: a scene, scripted input frame by frame, and checks.
//
// A scenario file is trusted Lua that returns a table (docs/scripting.md, "Scenarios"):
//   return {
//     scene = "levels/cube_intro/scene.lua",     -- the manifest, relative to the working directory
//     frames = 900,                              -- how long to run
//     input = { { hold = "right", from = 1, to = 900 }, { press = "jump", at = 120 } },
//     expect = { goal_by = 900, deaths = 0, face = { [300] = 1 },
//                inside = { { frame = 600, face = 2, box = { x0, y0, x1, y1 } } },
//                hash = { [600] = "0123456789abcdef" } },
//   }
// Every frame also checks that no instance overlaps a solid line (World::countOverlaps() == 0).
//
// Replays (platon/core/replay.h) run through the same loop: their input, and a check of every
// recorded state hash.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "platon/core/replay.h"
#include "platon/script/script_system.h"

namespace platon::script {

struct RunOptions {
  uint64_t traceEvery = 0;  // > 0: print the player's face and position to stderr this often
  bool record = false;      // keep the run's input and hashes in ScenarioResult::recorded
  uint64_t hashEvery = 60;  // the recording's hash interval
  // Where the meshes plugin (libplaton_meshes.so) is looked for, after $PLATON_PLUGIN_PATH: loaded
  // only for a level drawn on a mesh.
  std::vector<std::string> pluginFolders;
};

struct ScenarioResult {
  bool passed = false;
  std::string message;                   // why it failed (file:line for script errors), or a summary
  uint64_t frames = 0;                   // frames simulated
  double seconds = 0;                    // wall time, load included
  std::string hash;                      // the world's state hash after the last frame
  std::optional<GameStatus> status;      // the game's state at the end (scenes with scripts)
  std::optional<core::Replay> recorded;  // with RunOptions::record
};

// A scenario file is a regular file of at most this.
inline constexpr size_t kMaxScenarioBytes = size_t{16} << 20;
ScenarioResult runScenario(const std::string& path, const RunOptions& options = {});
// Replays a recorded run headless and checks every recorded hash: the first frame whose state
// differs fails it.
ScenarioResult runReplay(const std::string& path, const RunOptions& options = {});
// Turns a replay into a regression scenario (Lua text): its input as hold ranges, and what the
// run reached (`outcome`, from runReplay) as expectations: the goal frame, the deaths, the face
// and the recorded hashes. `name` goes into the leading comment.
std::string scenarioFromReplay(const core::Replay& replay, const ScenarioResult& outcome, const std::string& name);

}  // namespace platon::script
