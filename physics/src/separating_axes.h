// The candidate separating axes of a convex polygon and a segment, in the sweep's form: the
// polygon moved by D is separated from (or touches) the segment along an axis iff
// slack - dot(c, D) >= 0, and c points from the polygon towards the segment. One definition for
// the sweep, the static tests and the contact normal.
#pragma once
#include <span>

#include "platon/physics/sweep.h"

namespace platon::physics {

// The polygon's extent across the segment's line: cross(d, v - a) over its vertices.
struct SegmentSpan {
  int64_t minG, maxG;
  int minIndex, maxIndex;
};

inline SegmentSpan segmentSpan(std::span<const Vec2> poly, Segment seg) {
  const Vec2w d = seg.b - seg.a;
  SegmentSpan s{INT64_MAX, INT64_MIN, 0, 0};
  for (int j = 0; j < static_cast<int>(poly.size()); ++j) {
    const int64_t g = cross(d, poly[j] - seg.a);
    if (g < s.minG) s.minG = g, s.minIndex = j;
    if (g > s.maxG) s.maxG = g, s.maxIndex = j;
  }
  return s;
}

// Slack of the edge from vertex w along e (outward normal (e.y, -e.x)) against the segment.
inline int64_t edgeSlack(Vec2 w, Vec2w e, Segment seg) { return std::min(cross(seg.a - w, e), cross(seg.b - w, e)); }

// Calls visit(slack, c, axis) for the polygon's edges (axis 0..n-1), then the segment's right side
// (n) and left side (n+1); stops early, returning false, when visit returns false.
template <class Visit>
inline bool forEachAxis(std::span<const Vec2> poly, Segment seg, Visit&& visit) {
  const int n = static_cast<int>(poly.size());
  for (int i = 0; i < n; ++i) {
    const Vec2 w = poly[i];
    const Vec2w e = poly[i + 1 == n ? 0 : i + 1] - w;
    if (!visit(edgeSlack(w, e, seg), Vec2w{e.y, -e.x}, i)) return false;
  }
  const Vec2w d = seg.b - seg.a;
  const SegmentSpan s = segmentSpan(poly, seg);
  const Vec2w left{-d.y, d.x};
  if (!visit(-s.maxG, left, n)) return false;
  return visit(s.minG, -left, n + 1);
}

// The same for two convex polygons: the first one's edges (axis 0..n-1), then the second's (n..),
// with c pointing from the first towards the second. For the second's edge j from w along f (outward
// normal m = (f.y, -f.x)), the axis is c = -m and the slack is min over the first's vertices p of
// cross(p - w, f).
template <class Visit>
inline bool forEachAxis(std::span<const Vec2> poly, std::span<const Vec2> other, Visit&& visit) {
  const int n = static_cast<int>(poly.size()), m = static_cast<int>(other.size());
  for (int i = 0; i < n; ++i) {
    const Vec2 w = poly[i];
    const Vec2w e = poly[i + 1 == n ? 0 : i + 1] - w;
    int64_t slack = INT64_MAX;
    for (const Vec2 q : other) slack = std::min(slack, cross(q - w, e));
    if (!visit(slack, Vec2w{e.y, -e.x}, i)) return false;
  }
  for (int j = 0; j < m; ++j) {
    const Vec2 w = other[j];
    const Vec2w f = other[j + 1 == m ? 0 : j + 1] - w;
    int64_t slack = INT64_MAX;
    for (const Vec2 p : poly) slack = std::min(slack, cross(p - w, f));
    if (!visit(slack, Vec2w{-f.y, f.x}, n + j)) return false;
  }
  return true;
}

}  // namespace platon::physics
