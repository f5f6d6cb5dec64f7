// penetrationDepth and gapToNearest (peer.h): separating-axis depth and polygon-segment distance
// in long double, with a bounding-box test first so long chains of segments stay cheap.
#include <algorithm>
#include <cmath>
#include <limits>

#include "peer.h"

namespace platon::bench {
namespace {

using ld = long double;
constexpr ld kInf = std::numeric_limits<ld>::infinity();

struct P {
  ld x, y;
};
P operator-(P a, P b) { return {a.x - b.x, a.y - b.y}; }
P operator+(P a, P b) { return {a.x + b.x, a.y + b.y}; }
P operator*(ld k, P a) { return {k * a.x, k * a.y}; }
ld dot(P a, P b) { return a.x * b.x + a.y * b.y; }

struct Box {
  ld x0 = kInf, y0 = kInf, x1 = -kInf, y1 = -kInf;
  void add(P p) { x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y); }
  // Distance between two boxes along the axes (0 when they touch or overlap): a lower bound of the
  // distance between anything inside them.
  ld gap(const Box& o) const {
    const ld dx = std::max({ld{0}, o.x0 - x1, x0 - o.x1}), dy = std::max({ld{0}, o.y0 - y1, y0 - o.y1});
    return std::hypot(dx, dy);
  }
};

std::vector<P> placed(const Polygon& shape, Pose pose) {
  const ld c = std::cos(static_cast<ld>(pose.angle)), s = std::sin(static_cast<ld>(pose.angle));
  std::vector<P> out;
  for (const auto& [x, y] : shape) out.push_back({pose.x + c * x - s * y, pose.y + s * x + c * y});
  return out;
}

Box boxOf(const std::vector<P>& poly) {
  Box b;
  for (const P& p : poly) b.add(p);
  return b;
}

// The shortest push that separates polygon and segment, over the separating axes (the polygon's
// edge normals and the segment's normal); <= 0 when they are apart or only touch.
ld overlapDepth(const std::vector<P>& poly, P a, P b) {
  ld depth = kInf;
  auto axis = [&](P d) {
    const P n{-d.y, d.x};
    ld lo = kInf, hi = -kInf;
    for (const P& v : poly) lo = std::min(lo, dot(n, v)), hi = std::max(hi, dot(n, v));
    const ld sLo = std::min(dot(n, a), dot(n, b)), sHi = std::max(dot(n, a), dot(n, b));
    depth = std::min(depth, std::min(hi - sLo, sHi - lo) / std::sqrt(dot(n, n)));
  };
  for (size_t i = 0; i < poly.size(); ++i) axis(poly[(i + 1) % poly.size()] - poly[i]);
  axis(b - a);
  return depth;
}

ld pointSegmentDistance(P p, P a, P b) {
  const P d = b - a;
  const ld t = std::clamp(dot(p - a, d) / dot(d, d), ld{0}, ld{1});
  const P gap = a + t * d - p;
  return std::sqrt(dot(gap, gap));
}

// Apart (no shared point), some vertex or segment end is closest.
ld distance(const std::vector<P>& poly, P a, P b) {
  if (overlapDepth(poly, a, b) >= 0) return 0;
  ld best = kInf;
  for (size_t i = 0; i < poly.size(); ++i) {
    const P v = poly[i], w = poly[(i + 1) % poly.size()];
    best =
        std::min({best, pointSegmentDistance(v, a, b), pointSegmentDistance(a, v, w), pointSegmentDistance(b, v, w)});
  }
  return best;
}

Box boxOf(P a, P b) {
  Box box;
  box.add(a);
  box.add(b);
  return box;
}

}  // namespace

double penetrationDepth(const Polygon& convexCCW, Pose pose, const Segments& segments) {
  const std::vector<P> poly = placed(convexCCW, pose);
  const Box box = boxOf(poly);
  ld deepest = 0;
  for (const auto& [x0, y0, x1, y1] : segments) {
    const P a{x0, y0}, b{x1, y1};
    if (box.gap(boxOf(a, b)) > 0) continue;
    deepest = std::max(deepest, overlapDepth(poly, a, b));
  }
  return static_cast<double>(deepest);
}

double gapToNearest(const Polygon& convexCCW, Pose pose, const Segments& segments) {
  const std::vector<P> poly = placed(convexCCW, pose);
  const Box box = boxOf(poly);
  ld nearest = kInf;
  for (const auto& [x0, y0, x1, y1] : segments) {
    const P a{x0, y0}, b{x1, y1};
    if (box.gap(boxOf(a, b)) >= nearest) continue;
    nearest = std::min(nearest, distance(poly, a, b));
  }
  return static_cast<double>(nearest);
}

}  // namespace platon::bench
