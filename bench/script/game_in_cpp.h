// The first level's game written in C++: the same player (scripts/player.lua), rules
// (scripts/rules/game.lua), progression (scripts/progression.lua) and level script
// (levels/cube_intro/level.lua), line for line, on the same scene loaded from its manifest and
// level file, so the benchmark can set the Lua engine beside what a C++ game would cost. The same
// input gives the same state hash in both: the comparison runs the same frames.
#pragma once
#include <memory>

#include "platon/core/scene.h"

namespace platon::bench {

// The cube_intro scene with the game in C++ (no Lua state at all).
std::unique_ptr<core::Scene> cubeIntroInCpp();

}  // namespace platon::bench
