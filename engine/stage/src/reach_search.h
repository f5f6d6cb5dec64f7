// `platon check`'s reachability search: free space for the default player's disk on each face,
// as a quadtree refined near walls, joined within faces and across every edge, searched from the
// start. Conservative: a cell counts as free only if no wall (its face's, or a neighbour's within
// reach of the shared edge) comes within the player's radius of any point of the cell's square,
// and cells are split down to kFinestCell units near walls. So a goal it reaches can be reached
// by a disk of that radius sliding through free space, at any face size from 64 to 2^24; a goal
// it calls sealed off may only be behind a gap less than the player's width plus three cells.
//
// The tree is built coarse to fine, one cell size at a time over every face, so that what it
// costs is counted as it grows (every wall costs cells at every level from the face's size down,
// and cells along its length near the bottom); when the next, finer level would not fit in
// kSearchBytes, the search stops there, and the cells still in doubt are undecided: blocked to
// its answer, and open to a second pass that bounds it from above. A goal that pass reaches but
// the first does not is undecided, never "sealed off".
#pragma once
#include "platon/stage/level.h"

namespace platon::stage {

inline constexpr double kPlayerRadius = 96;        // the default player's disk
inline constexpr double kFinestCell = 8;           // near walls, in units
inline constexpr size_t kSearchBytes = 48u << 20;  // the tree, its cells in doubt and their walls

struct ReachAnswer {
  bool reachable = false;
  double finestCell = kFinestCell;  // the cell size near walls the search could afford
  size_t walls = 0;                 // the walls it searched among (each face's, laid out with its neighbours')
  bool couldBeOpen = false;         // with the cells it left undecided counted open, a path reaches the goal

  // A goal not reached is sealed off when the cells near walls were the finest, or when even the
  // undecided cells counted open give no path (then none would with the finest cells either).
  bool decided() const { return reachable || !couldBeOpen; }
};

ReachAnswer searchReach(const Level& level, const Stage& stage);

}  // namespace platon::stage
