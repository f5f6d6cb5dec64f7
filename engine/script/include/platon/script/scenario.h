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
#pragma once
#include <cstdint>
#include <string>

namespace platon::script {

struct ScenarioResult {
  bool passed = false;
  std::string message;  // why it failed (file:line for script errors), or a summary
  uint64_t frames = 0;  // frames simulated
  double seconds = 0;   // wall time, load included
  std::string hash;     // the world's state hash after the last frame
};

// traceEvery > 0: print the player's face and position to stderr every that many frames.
ScenarioResult runScenario(const std::string& path, uint64_t traceEvery = 0);

}  // namespace platon::script
