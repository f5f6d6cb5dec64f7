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
// lines lying along a face's edge, where they block the way to the next face, and faces with no
// lines (warnings).
//
// Reachability is coarse: free space for the default player (a disk of kStartClearance units)
// on a grid of size / 64 (at least 8 units), four ways within a face and across every edge to
// the neighbour, from the start's cell. Doors count as open, one-way lines as passable, hazards
// as walls. Gravity and jump height are not modelled: "reachable" means not sealed off, and a goal
// it calls unreachable is sealed off by walls (or by gaps narrower than the player within a cell).
CheckReport checkLevel(const Level& level, const Stage& stage);

// Whether the goal's cell is joined to the start's (the search above).
bool goalReachable(const Level& level, const Stage& stage);

}  // namespace platon::stage
