// What a level designer wants to know before playing a level (`platon check`): its errors and
// warnings with file:line, and whether the goal can be reached at all.
#pragma once
#include <string>
#include <vector>

#include "platon/stage/level.h"

namespace platon::stage {

struct Finding {
  SourcePosition where;
  std::string message;
};

struct CheckReport {
  std::vector<Finding> errors, warnings;
};

// Checks a parsed level on its stage: checkLevelOnStage's errors; a goal no path reaches (error);
// lines lying along a face's edge, where they block the way to the next face, faces with no
// lines, faces narrower than the default player, and a reachability search that could not decide
// (it had to stop at coarse cells, and they neither join the goal nor seal it off: a warning,
// never the error).
//
// Reachability is conservative (src/reach_search.h, docs/level-format.md "platon check"): free
// space for the default player's disk (radius 96) as a quadtree per face, refined near walls down
// to 8 units, a cell free only when no wall comes within the radius of any of its points (the
// neighbours' walls near a shared edge included), joined within faces and across every edge. Doors
// count as open, one-way lines as passable, hazards as walls. Gravity and jump height are not
// modelled: "reachable" means a disk can slide there; "sealed off" means walls, or a gap under
// 216 units.
CheckReport checkLevel(const Level& level, const Stage& stage);

// Whether the search above joins the start to the goal.
bool goalReachable(const Level& level, const Stage& stage);

}  // namespace platon::stage
