// Platon alone: walking and floating across warp edges of three fold angles. Two faces meet at an
// edge whose frames differ by `degrees` (90: cube, 120: tetrahedron, 72 + 180: dodecahedron); the
// answer is a straight path in the unfolded plane, mapped exactly into each part.
#pragma once
#include <string>

#include "runs.h"

namespace platon::bench::precision {

struct WarpScene {
  int degrees;
  bool walk;  // on a floor under gravity; else floating, no floor, no gravity
  std::string name() const { return "warp" + std::to_string(degrees) + (walk ? "" : "-float"); }
};

inline constexpr double kWarpSeconds = 2.5;

Row measureWarp(const WarpScene& scene, int upm, double hz);
double timeWarp(const WarpScene& scene, int upm, double hz);  // seconds for the frame loop

}  // namespace platon::bench::precision
