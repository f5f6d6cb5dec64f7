#include "platon/physics/sweep.h"

#include <algorithm>

#include "separating_axes.h"

namespace platon::physics {
namespace {

// Interval bookkeeping for one axis. Returns false when the axis proves "never overlapping".
inline bool applyAxis(Sweep& r, int64_t slack, Vec2w c, Vec2w motion, int axis) {
  const int64_t rate = dot(c, motion);
  if (rate > 0) {  // closing: overlap on this axis once t > slack / rate
    const Fraction f{slack, rate};
    if (!r.hasEnter || f > r.enter) {
      r.hasEnter = true;
      r.enter = f;
      r.enterAxis = {slack, c};
      r.axis = axis;
    }
  } else if (rate < 0) {  // opening: overlap only while t < slack / rate
    if (slack >= 0) return false;
    const Fraction f{-slack, -rate};
    if (!r.hasExit || f < r.exit) {
      r.hasExit = true;
      r.exit = f;
    }
  } else if (slack >= 0) {  // parallel and separated (or touching): never overlaps
    return false;
  }
  return true;
}

}  // namespace

Sweep sweep(std::span<const Vec2> poly, Vec2w motion, Segment seg) {
  Sweep r;
  r.empty = false;
  const bool open =
      forEachAxis(poly, seg, [&](int64_t slack, Vec2w c, int axis) { return applyAxis(r, slack, c, motion, axis); });
  if (!open) return Sweep{};
  if (r.hasEnter && r.hasExit && r.enter >= r.exit) return Sweep{};
  if (r.hasExit && r.exit <= Fraction::zero()) return Sweep{};
  return r;
}

Sweep sweep(std::span<const Vec2> poly, Vec2w motion, std::span<const Vec2> obstacle) {
  Sweep r;
  r.empty = false;
  const bool open = forEachAxis(poly, obstacle,
                                [&](int64_t slack, Vec2w c, int axis) { return applyAxis(r, slack, c, motion, axis); });
  if (!open) return Sweep{};
  if (r.hasEnter && r.hasExit && r.enter >= r.exit) return Sweep{};
  if (r.hasExit && r.exit <= Fraction::zero()) return Sweep{};
  return r;
}

bool overlapsInterior(std::span<const Vec2> poly, std::span<const Vec2> other) {
  return forEachAxis(poly, other, [](int64_t slack, Vec2w, int) { return slack < 0; });
}

Vec2w roundedStep(Vec2w m, Fraction t, const Constraint* keep) {
  if (t == Fraction::one()) return m;
  if (t.num == 0) return {};  // as below, without dividing (a hit where it stands is common)
  auto one = [&](int64_t mk, int64_t ck) {
    const i128 q = i128{t.num} * mk;
    const bool down = keep && ck != 0 ? ck > 0 : mk >= 0;
    return static_cast<int64_t>(down ? floorDiv(q, t.den) : ceilDiv(q, t.den));
  };
  return {one(m.x, keep ? keep->c.x : 0), one(m.y, keep ? keep->c.y : 0)};
}

bool overlapsInterior(std::span<const Vec2> poly, Segment seg) {
  const int n = static_cast<int>(poly.size());
  for (int i = 0; i < n; ++i) {
    const Vec2 w = poly[i];
    if (edgeSlack(w, poly[i + 1 == n ? 0 : i + 1] - w, seg) >= 0) return false;
  }
  const SegmentSpan s = segmentSpan(poly, seg);
  return s.minG < 0 && s.maxG > 0;
}

bool touchesOrOverlaps(std::span<const Vec2> poly, Segment seg) {
  const int n = static_cast<int>(poly.size());
  for (int i = 0; i < n; ++i) {
    const Vec2 w = poly[i];
    if (edgeSlack(w, poly[i + 1 == n ? 0 : i + 1] - w, seg) > 0) return false;
  }
  const SegmentSpan s = segmentSpan(poly, seg);
  return s.minG <= 0 && s.maxG >= 0;
}

namespace {

// A point on the moving polygon at time num/den, or a segment endpoint; keyed by its position
// along the segment direction, scaled by den, so keys compare exactly in 128 bits.
struct KeyedPoint {
  i128 key;
  Vec2 point;
};

Vec2 movedVertex(Vec2 w, Vec2w motion, Fraction t) {
  if (t.num == 0) return w;  // a contact where it stands (as below, without dividing)
  return {static_cast<int32_t>(w.x + roundDiv(i128{t.num} * motion.x, t.den)),
          static_cast<int32_t>(w.y + roundDiv(i128{t.num} * motion.y, t.den))};
}

ContactPoints sharedStretch(Vec2 w0, Vec2 w1, Vec2w motion, Segment seg, Fraction t) {
  const Vec2w d = seg.b - seg.a;
  const i128 shift = i128{t.num} * dot(motion, d);
  const KeyedPoint sa{0, seg.a};
  const KeyedPoint sb{i128{dot(d, d)} * t.den, seg.b};
  KeyedPoint e0{i128{dot(w0 - seg.a, d)} * t.den + shift, movedVertex(w0, motion, t)};
  KeyedPoint e1{i128{dot(w1 - seg.a, d)} * t.den + shift, movedVertex(w1, motion, t)};
  if (e1.key < e0.key) std::swap(e0, e1);
  const KeyedPoint lo = e0.key > sa.key ? e0 : sa;
  const KeyedPoint hi = e1.key < sb.key ? e1 : sb;
  ContactPoints out;
  out.points[out.count++] = lo.point;
  if (hi.key > lo.key) out.points[out.count++] = hi.point;
  return out;
}

}  // namespace

ContactPoints contactPoints(std::span<const Vec2> poly, Vec2w motion, Segment seg, const Sweep& hit) {
  const int n = static_cast<int>(poly.size());
  const Fraction t = hit.enter;
  ContactPoints out;
  if (hit.axis < n) {  // a polygon edge reached a segment endpoint (or lies along the segment)
    const Vec2 w = poly[hit.axis];
    const Vec2 w1 = poly[hit.axis + 1 == n ? 0 : hit.axis + 1];
    const Vec2w e = w1 - w;
    const int64_t sa = cross(seg.a - w, e);
    const int64_t sb = cross(seg.b - w, e);
    if (sa != sb) {
      out.points[out.count++] = sa < sb ? seg.a : seg.b;
      return out;
    }
    return sharedStretch(w, w1, motion, seg, t);
  }
  // The segment's line reached the polygon's extreme vertex (or an edge parallel to it).
  const Vec2w d = seg.b - seg.a;
  const bool right = hit.axis == n;
  int first = -1;
  int64_t best = 0;
  for (int j = 0; j < n; ++j) {
    const int64_t g = cross(d, poly[j] - seg.a);
    if (first < 0 || (right ? g > best : g < best)) first = j, best = g;
  }
  const int next = first + 1 == n ? 0 : first + 1;
  const int prev = first == 0 ? n - 1 : first - 1;
  if (cross(d, poly[next] - seg.a) == best) return sharedStretch(poly[first], poly[next], motion, seg, t);
  if (cross(d, poly[prev] - seg.a) == best) return sharedStretch(poly[prev], poly[first], motion, seg, t);
  out.points[out.count++] = movedVertex(poly[first], motion, t);
  return out;
}

}  // namespace platon::physics
