// The solid lines a player on a face can touch: the face's own, and its neighbours' that come
// within a margin of the edge they share, laid flat in the face's frame (the neighbour turned
// about the shared edge into the face's plane, as crossing the edge carries a body). Used by the
// start and goal clearance and by the reachability search: a wall just across an edge blocks a
// disk near the edge as one on the face does. (Faces that meet the face only at a vertex are not
// laid out: near a vertex the unfolded neighbours overlap.)
#pragma once
#include <vector>

#include "platon/stage/level.h"

namespace platon::stage {

struct FlatWall {
  double ax = 0, ay = 0, bx = 0, by = 0;  // in the face's frame
  int face = 0;                           // the face the line is on
  const LevelLine* line = nullptr;
};

// The rigid map from the frame of the face across edge `edge` of `face` to `face`'s frame: that
// face's copy of the edge lands on this face's.
struct FlatMap {
  double cos = 1, sin = 0, x = 0, y = 0;
  void apply(double& px, double& py) const {
    const double qx = cos * px - sin * py + x, qy = sin * px + cos * py + y;
    px = qx, py = qy;
  }
  FlatMap inverse() const;
};
FlatMap unfoldAcross(const Stage& stage, size_t face, size_t edge);

// Which lines count: for the start and goal clearance every line the player does not pass
// through (shut doors and one-way lines included); for the reachability search, walls only
// (doors open, one-way lines passable).
enum class Counting { Clearance, Reach };
bool counts(const LevelLine& line, const TagTable& tags, Counting counting);

// The lines of `face`, and those of its neighbours within `margin` of the shared edge, that count.
std::vector<FlatWall> wallsNear(const Level& level, const Stage& stage, size_t face, double margin, Counting counting);

}  // namespace platon::stage
