// Continuous sweep of a convex polygon against a line segment, in exact integer arithmetic.
//
// The polygon P moves by t * motion. By the separating-axis theorem its interior meets the segment
// exactly when the projections overlap strictly on every candidate axis: the normals of P's edges
// and the segment's normal (this is the seed's Minkowski-sum test: each axis is one edge of
// segment (+) (-P)). On each axis the separation is linear in t, "slack - t * rate", so the times of
// overlap form one open interval (enter, exit) whose ends are exact fractions of 64-bit integers.
#pragma once
#include <span>

#include "platon/physics/fraction.h"
#include "platon/physics/vec2.h"

namespace platon::physics {

struct Segment {
  Vec2 a;
  Vec2 b;
};

// One separating axis: the polygon moved by D is separated (or touching) iff slack - dot(c, D) >= 0.
// -c is the contact normal: it points from the segment towards the polygon.
struct Constraint {
  int64_t slack = 0;
  Vec2w c;
};

struct Sweep {
  bool empty = true;      // no interior overlap for any t >= 0
  bool hasEnter = false;  // otherwise enter = -infinity
  bool hasExit = false;   // otherwise exit = +infinity
  Fraction enter;
  Fraction exit;
  Constraint enterAxis;  // the axis that opens last: its normal is the contact normal
  int axis = -1;         // 0..n-1: polygon edge i; n: segment's right side; n+1: its left side

  bool startsInside() const {
    return !empty && (!hasEnter || enter < Fraction::zero()) && (!hasExit || exit > Fraction::zero());
  }
  // The interior first meets the segment at t = enter, with 0 <= enter < limit.
  bool hitsBefore(Fraction limit) const {
    return !empty && hasEnter && enter >= Fraction::zero() && enter < limit && (!hasExit || enter < exit);
  }
  bool hitsWithinFrame() const { return hitsBefore(Fraction::one()); }
  Vec2w normal() const { return -enterAxis.c; }
};

// `polygon`: world vertices, counter-clockwise; `segment` of non-zero length (map parts refuse
// others). |motion component| <= 2^31 - 2 and every point in
// range (see vec2.h). No allocation, no floating point.
Sweep sweep(std::span<const Vec2> polygon, Vec2w motion, Segment segment);

// t * motion rounded to whole units the way the world stops a move. With `keep` (the axis of the
// contact that stopped it), each component rounds to the side that keeps the polygon on the outer
// side of that axis, so it ends touching or short, never across; without, towards the start.
Vec2w roundedStep(Vec2w motion, Fraction t, const Constraint* keep = nullptr);

// The same against another convex polygon (counter-clockwise, at least 3 vertices) that stays
// still: the axes are both polygons' edge normals (Minkowski: polygon (+) (-obstacle)); axis n + j
// is the obstacle's edge j.
Sweep sweep(std::span<const Vec2> polygon, Vec2w motion, std::span<const Vec2> obstacle);

// Static tests at the current position.
bool overlapsInterior(std::span<const Vec2> polygon, Segment segment);   // interiors meet
bool touchesOrOverlaps(std::span<const Vec2> polygon, Segment segment);  // closed sets meet
bool overlapsInterior(std::span<const Vec2> polygon, std::span<const Vec2> other);

// Where the polygon, moved by `enter * motion`, touches the segment: one point, or the two ends of
// a shared stretch when an edge lies along the segment. Points of the moving polygon are rounded
// to the nearest unit; segment endpoints are exact.
struct ContactPoints {
  Vec2 points[2];
  int count = 0;
};
ContactPoints contactPoints(std::span<const Vec2> polygon, Vec2w motion, Segment segment, const Sweep& hit);

}  // namespace platon::physics
