// Faces of a solid: map parts whose warp lines close into one convex counter-clockwise loop
// (MapPart::faceLoop, found by initialize()). What the warp and vertex rules ask of one: how far
// a point lies inside an edge, whether it is on the face, which corner is nearest, and where a
// point maps across an edge.
#pragma once
#include <algorithm>

#include "fixed_point.h"
#include "platon/physics/map_part.h"

namespace platon::physics {

inline int64_t lengthOf(Vec2w d) {
  return static_cast<int64_t>(isqrt(static_cast<u128>(i128{d.x} * d.x + i128{d.y} * d.y)));
}

// How far `p` lies to the left of the directed line through `s` (inside a counter-clockwise
// face's edge), times the segment's length.
inline i128 insideEdge(Segment s, Vec2 p) {
  const Vec2w d = s.b - s.a;
  return i128{d.x} * (i128{p.y} - s.a.y) - i128{d.y} * (i128{p.x} - s.a.x);
}

// Whether `p` is inside the face, on its border, or beyond it by no more than rounding: the two
// copies of an entity crossing an edge both have their centre on it to within a unit or two.
inline bool insideFace(const MapPart& face, Vec2 p) {
  constexpr int64_t kRounding = 4;  // units
  for (const LineIndex line : face.faceLoop()) {
    const Segment s = face.segments()[line];
    const i128 side = insideEdge(s, p);
    const Vec2w d = s.b - s.a;
    if (side < 0 && side * side > i128{kRounding} * kRounding * (i128{d.x} * d.x + i128{d.y} * d.y)) return false;
  }
  return true;
}

// How far `p` lies beyond the face's edges (the furthest edge), in units rounded down; 0 inside.
inline int64_t unitsOutside(const MapPart& face, Vec2 p) {
  int64_t worst = 0;
  for (const LineIndex line : face.faceLoop()) {
    const Segment s = face.segments()[line];
    const i128 side = insideEdge(s, p);
    if (side < 0) worst = std::max<int64_t>(worst, static_cast<int64_t>(-side / lengthOf(s.b - s.a)));
  }
  return worst;
}

// The loop index of the face's corner nearest `p`: the corner where loop[k] starts.
inline size_t nearestCorner(const MapPart& face, Vec2 p) {
  const auto loop = face.faceLoop();
  size_t corner = 0;
  i128 best = -1;
  for (size_t k = 0; k < loop.size(); ++k) {
    const Vec2w d = face.segments()[loop[k]].a - p;
    const i128 d2 = i128{d.x} * d.x + i128{d.y} * d.y;
    if (best < 0 || d2 < best) best = d2, corner = k;
  }
  return corner;
}

// A Q30 point of the part that has warp `w` on its line `from`, in the warp target's frame.
inline Vec2w mapThroughWarp(const Warp& w, Segment from, Vec2w pointQ30) {
  const Vec2w rel = pointQ30 - q30FromPoint(from.a);
  return q30FromPoint(w.targetSegment.a) + rotateWide(w.rotation, rel);
}

}  // namespace platon::physics
