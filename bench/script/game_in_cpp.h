// The first level's game written in C++: the same player (scripts/player.lua), rules
// (scripts/rules/game.lua), progression (scripts/progression.lua) and level (levels/cube_intro),
// line for line, so the benchmark can set the Lua engine beside what a C++ game would cost. The
// same input gives the same state hash in both: the comparison runs the same frames.
#pragma once
#include <memory>

#include "platon/core/scene.h"

namespace platon::bench {

// The cube_intro scene with the game in C++ (no Lua state at all).
std::unique_ptr<core::Scene> cubeIntroInCpp();

}  // namespace platon::bench
