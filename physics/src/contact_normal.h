// Which way a body can go from where it touches several lines: at a joint, in a corner, at rest.
//
// Where a body touches a line beside its middle, it may move anywhere but into the line: a
// half-plane of directions. Where it touches the line's end (a polygon's vertex on the segment's
// endpoint, or the endpoint on the polygon's side), several separating axes have zero gap, and it
// may move anywhere but into the wedge between them. Touching several lines, it may move in the
// directions open past every one of them (a union of cones, not always convex).
//
// A sweep against one segment reports only the axis that opens last. At a joint (a floor of two
// pieces, a floor meeting the next face's floor, a valley between two slopes) that axis is often an
// edge of the body's own polygon: sliding along it sends the body up and back, and it snags on a
// joint it should glide over, or sinks into the next line. So a contact slides along the open
// direction that keeps the most of its motion, whichever line or polygon edge it runs along; when
// no open direction makes progress, the body is in a crease and stops. The same test, run on the
// lines within one unit, tells a body at rest (see WorldImpl::restsAgainstLines).
#pragma once
#include <span>
#include <vector>

#include "platon/physics/fraction.h"
#include "platon/physics/sweep.h"

namespace platon::physics {

// The polygon moved by t * motion against the segment: false if they are strictly apart (some axis
// has a positive gap); otherwise true, with the contact normals (pointing from the segment towards
// the polygon) of the axes with zero gap appended to `normals`.
bool touchingNormals(std::span<const Vec2> polygon, Vec2w motion, Fraction t, Segment segment,
                     std::vector<Vec2w>& normals);

// How far a polygon is from a segment, for the rest test. Touching: the normals of the zero-gap
// axes. Near (a gap below 1.5 units along every axis, the most a whole-unit position can be kept
// from the corner of a crease: the points within 1.5 units of two lines form a rhombus whose
// inscribed circle, 1.5 units across, always holds a whole-unit point, which 1 unit would not):
// only the segment's own normal, and only if the body is beside the line's middle (a body near the
// line's end can reach the end and go past).
enum class Nearness { Apart, Near, Touching };
Nearness nearNormals(std::span<const Vec2> polygon, Segment segment, std::vector<Vec2w>& normals);

// The same two against another entity's convex polygon. Short of touching, only the other
// polygon's own edges count (its sides, as a line's own side does).
bool touchingNormals(std::span<const Vec2> polygon, Vec2w motion, Fraction t, std::span<const Vec2> other,
                     std::vector<Vec2w>& normals);
Nearness nearNormals(std::span<const Vec2> polygon, std::span<const Vec2> other, std::vector<Vec2w>& normals);

// The directions open past a set of lines, each given by the contact normals of its active axes.
class OpenDirections {
 public:
  void clear() { normals_.clear(), groupEnds_.clear(); }
  // Starts a line; its normals follow with addNormal.
  void beginLine() { groupEnds_.push_back(static_cast<uint32_t>(normals_.size())); }
  void addNormal(Vec2w n) {
    normals_.push_back(n);
    groupEnds_.back() = static_cast<uint32_t>(normals_.size());
  }
  std::vector<Vec2w>& normals() { return normals_; }  // to turn them into another frame in place
  bool empty() const { return groupEnds_.empty(); }

  // d points into no line: for each, dot(d, n) >= 0 for at least one of its normals.
  bool open(Vec2w d) const;
  // The normal whose line (the direction perpendicular to it, either way) is open and keeps the
  // most of w, as an index into normals(); -1 if no open direction makes progress along w.
  int slideNormal(Vec2w w) const;
  // Neither w nor any open direction makes progress along it. w == 0 cannot move. (w may be a
  // velocity: any size.)
  bool cannotMove(Vec2w w) const;
  // -w lies in the cone of two normals of different lines that are not parallel: w presses the
  // body into a corner between two lines, not merely onto one.
  bool wedges(Vec2w w) const;

 private:
  std::vector<Vec2w> normals_;
  std::vector<uint32_t> groupEnds_;  // one past each line's last normal
};

}  // namespace platon::physics
