// `platon check`'s reachability search: free space for the default player's disk on each face,
// as a quadtree refined near walls, joined within faces and across every edge, searched from the
// start. Conservative: a cell counts as free only if no wall (its face's, or a neighbour's within
// reach of the shared edge) comes within the player's radius of any point of the cell's square,
// and cells are split down to kFinestCell units near walls. So a goal it reaches can be reached
// by a disk of that radius sliding through free space, at any face size from 64 to 2^24; a goal
// it calls sealed off may only be behind a gap less than the player's width plus three cells.
#pragma once
#include "platon/stage/level.h"

namespace platon::stage {

inline constexpr double kPlayerRadius = 96;  // the default player's disk
inline constexpr double kFinestCell = 8;     // near walls, in units
inline constexpr size_t kMostCells = 1'000'000;  // over this (40 MB), the search starts again with cells twice as big

struct ReachAnswer {
  bool reachable = false;
  double finestCell = kFinestCell;  // the cell size the search could afford (more when walls are very long)
};

ReachAnswer searchReach(const Level& level, const Stage& stage);

}  // namespace platon::stage
