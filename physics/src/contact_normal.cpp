#include "contact_normal.h"

#include "separating_axes.h"

namespace platon::physics {
namespace {

// Sign of (slack - t * rate) for t = num / den >= 0: both products are below 2^126 in magnitude
// (slack, rate, num, den all below 2^63), so they are compared, never subtracted.
int signAt(i128 slack, i128 rate, Fraction t) {
  const i128 a = slack * t.den, b = rate * t.num;
  return a > b ? 1 : (a < b ? -1 : 0);
}

}  // namespace

bool touchingNormals(std::span<const Vec2> polygon, Vec2w motion, Fraction t, Segment segment,
                     std::vector<Vec2w>& normals) {
  const size_t before = normals.size();
  const bool touching = forEachAxis(polygon, segment, [&](int64_t slack, Vec2w c, int) {
    const int sign = signAt(slack, dot(c, motion), t);
    if (sign == 0) normals.push_back(-c);
    return sign <= 0;
  });
  if (!touching) normals.resize(before);
  return touching;
}

Nearness nearNormals(std::span<const Vec2> polygon, Segment segment, std::vector<Vec2w>& normals) {
  // The gap along axis c is slack / |c|: below 1.5 units iff slack <= 0 or 4 slack^2 < 9 |c|^2
  // (slack below 2^63, and below 2^32 when it passes, so the products fit in 128 bits).
  const size_t before = normals.size();
  const int n = static_cast<int>(polygon.size());
  bool touching = true;
  const bool near = forEachAxis(polygon, segment, [&](int64_t slack, Vec2w c, int axis) {
    if (slack > 0) touching = false;
    if (slack < 0) return true;
    if (slack >= (int64_t{1} << 32) ||
        4 * static_cast<u128>(slack) * static_cast<u128>(slack) >= 9 * static_cast<u128>(dot128(c, c)))
      return false;
    if (slack == 0 || axis >= n) normals.push_back(-c);
    return true;
  });
  if (near && !touching) {  // short of touching only the line's own normal counts
    size_t kept = before;
    for (size_t k = before; k < normals.size(); ++k)
      if (dot128(normals[k], segment.b - segment.a) == 0) normals[kept++] = normals[k];
    normals.resize(kept);
  }
  if (!near || normals.size() == before) {  // apart, near only its end, or (never) overlapping
    normals.resize(before);
    return Nearness::Apart;
  }
  return touching ? Nearness::Touching : Nearness::Near;
}

bool touchingNormals(std::span<const Vec2> polygon, Vec2w motion, Fraction t, std::span<const Vec2> other,
                     std::vector<Vec2w>& normals) {
  const size_t before = normals.size();
  const bool touching = forEachAxis(polygon, other, [&](int64_t slack, Vec2w c, int) {
    const int sign = signAt(slack, dot(c, motion), t);
    if (sign == 0) normals.push_back(-c);
    return sign <= 0;
  });
  if (!touching) normals.resize(before);
  return touching;
}

Nearness nearNormals(std::span<const Vec2> polygon, std::span<const Vec2> other, std::vector<Vec2w>& normals) {
  const size_t before = normals.size();
  const int n = static_cast<int>(polygon.size());
  bool touching = true;
  size_t firstOwn = SIZE_MAX;  // the other polygon's edges come after ours: where they start
  const bool near = forEachAxis(polygon, other, [&](int64_t slack, Vec2w c, int axis) {
    if (slack > 0) touching = false;
    if (slack < 0) return true;
    if (slack >= (int64_t{1} << 32) ||
        4 * static_cast<u128>(slack) * static_cast<u128>(slack) >= 9 * static_cast<u128>(dot128(c, c)))
      return false;
    if (axis >= n && firstOwn == SIZE_MAX) firstOwn = normals.size();
    normals.push_back(-c);
    return true;
  });
  if (near && !touching)
    normals.erase(normals.begin() + static_cast<long>(before),
                  normals.begin() + static_cast<long>(std::min(firstOwn, normals.size())));
  if (!near || normals.size() == before) {
    normals.resize(before);
    return Nearness::Apart;
  }
  return touching ? Nearness::Touching : Nearness::Near;
}

bool OpenDirections::open(Vec2w d) const {
  uint32_t first = 0;
  for (const uint32_t end : groupEnds_) {
    bool open = false;
    for (uint32_t k = first; k < end && !open; ++k) open = dot128(d, normals_[k]) >= 0;
    if (!open) return false;
    first = end;
  }
  return true;
}

bool OpenDirections::cannotMove(Vec2w w) const {
  if (w == Vec2w{}) return true;
  if (open(w)) return false;
  const bool oneLine = groupEnds_.size() == 1;  // then along any of its normals is open past it
  for (const Vec2w n : normals_)
    for (const Vec2w r : {Vec2w{-n.y, n.x}, Vec2w{n.y, -n.x}})
      if (dot128(r, w) > 0 && (oneLine || open(r))) return false;
  return true;
}

bool OpenDirections::wedges(Vec2w w) const {
  const Vec2w u = -w;
  uint32_t firstA = 0;
  for (size_t ga = 0; ga < groupEnds_.size(); firstA = groupEnds_[ga++]) {
    uint32_t firstB = groupEnds_[ga];
    for (size_t gb = ga + 1; gb < groupEnds_.size(); firstB = groupEnds_[gb++])
      for (uint32_t i = firstA; i < groupEnds_[ga]; ++i)
        for (uint32_t j = firstB; j < groupEnds_[gb]; ++j) {
          const Vec2w a = normals_[i], b = normals_[j];
          const i128 ab = cross128(a, b);
          if (ab == 0) continue;
          // u between a and b the short way round: on the same side of each as the other is.
          if (ab > 0 ? cross128(a, u) >= 0 && cross128(u, b) >= 0 : cross128(a, u) <= 0 && cross128(u, b) <= 0)
            return true;
        }
  }
  return false;
}

int OpenDirections::slideNormal(Vec2w w) const {
  // The open directions are a union of cones whose edges run perpendicular to the normals: if any
  // open direction makes progress along w, the best of them is one of those edges. Best: the
  // smallest angle to w, i.e. the least |cross(r, w)| / dot(r, w), compared cross-multiplied (both
  // factors below 2^63, so the products fit in 128 bits). Ties keep the earlier normal.
  int best = -1;
  u128 bestCross = 0, bestDot = 1;
  // One line: a direction along one of its normals is open past it (dot 0 with that normal).
  const bool oneLine = groupEnds_.size() == 1;
  for (size_t k = 0; k < normals_.size(); ++k) {
    const Vec2w n = normals_[k];
    // The same direction as the one before (a body's side on the line: the line's normal and the
    // side's): its edges are the same directions scaled, never better (ties keep the earlier).
    if (k > 0 && cross128(normals_[k - 1], n) == 0 && dot128(normals_[k - 1], n) > 0) continue;
    for (const Vec2w r : {Vec2w{-n.y, n.x}, Vec2w{n.y, -n.x}}) {
      const i128 along = dot128(r, w);
      if (along <= 0 || (!oneLine && !open(r))) continue;
      const i128 across = cross128(r, w);
      const u128 a = static_cast<u128>(across < 0 ? -across : across), d = static_cast<u128>(along);
      if (best < 0 || a * bestDot < bestCross * d) best = static_cast<int>(k), bestCross = a, bestDot = d;
    }
  }
  return best;
}

}  // namespace platon::physics
