#include "platon/physics/convex.h"

#include <algorithm>
#include <cstdlib>

namespace platon::physics {

std::string toString(Vec2 p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

Convex::Convex(std::vector<Vec2> vertices) : vertices_(std::move(vertices)) {
  const int n = size();
  if (n < 3) throw Error("convex shape needs at least 3 vertices, got " + std::to_string(n));
  if (n > kMaxConvexVertices)
    throw Error("convex shape has " + std::to_string(n) + " vertices; the limit is " +
                std::to_string(kMaxConvexVertices));
  for (int i = 0; i < n; ++i) {
    const Vec2 v = vertices_[i];
    if (std::abs(int64_t{v.x}) > kShapeLimit || std::abs(int64_t{v.y}) > kShapeLimit)
      throw Error("convex shape vertex " + std::to_string(i) + " " + toString(v) +
                  " is outside the shape range |coordinate| <= 2^29");
  }
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (vertices_[i] == vertices_[j])
        throw Error("convex shape vertex " + std::to_string(j) + " repeats vertex " + std::to_string(i) + " " +
                    toString(vertices_[i]));
  // Every turn must be strictly left, and the polygon must wind exactly once.
  for (int i = 0; i < n; ++i) {
    const Vec2 a = vertices_[(i + n - 1) % n];
    const Vec2 b = vertices_[i];
    const Vec2 c = vertices_[(i + 1) % n];
    const int64_t turn = cross(b - a, c - b);
    if (turn == 0)
      throw Error("convex shape vertex " + std::to_string(i) + " " + toString(b) + " is collinear with its neighbours");
    if (turn < 0)
      throw Error("convex shape vertex " + std::to_string(i) + " " + toString(b) +
                  " turns clockwise: vertices must be counter-clockwise and convex");
  }
  // All left turns but winding more than once (a star) shows up as an angle sum above 360 degrees;
  // detect it by checking that every vertex is on the inner side of every edge.
  for (int i = 0; i < n; ++i) {
    const Vec2 a = vertices_[i];
    const Vec2 b = vertices_[(i + 1) % n];
    for (int j = 0; j < n; ++j) {
      if (j == i || j == (i + 1) % n) continue;
      if (cross(b - a, vertices_[j] - a) <= 0)
        throw Error("convex shape vertex " + std::to_string(j) + " " + toString(vertices_[j]) + " lies outside edge " +
                    std::to_string(i) + ": the polygon is not convex");
    }
  }
}

namespace {

// Whether o -> a -> b turns strictly left. In 128 bits: points anywhere in int32 differ by up to
// 2^32 in each coordinate, and the products of such differences pass 2^63.
bool leftTurn(Vec2 o, Vec2 a, Vec2 b) { return cross128(wide(a) - wide(o), wide(b) - wide(o)) > 0; }

}  // namespace

std::vector<Vec2> convexHull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(), [](Vec2 a, Vec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Vec2> hull(2 * points.size());
  size_t k = 0;
  for (const Vec2 p : points) {  // lower hull
    while (k >= 2 && !leftTurn(hull[k - 2], hull[k - 1], p)) --k;
    hull[k++] = p;
  }
  const size_t lower = k + 1;
  for (size_t i = points.size() - 1; i-- > 0;) {  // upper hull
    const Vec2 p = points[i];
    while (k >= lower && !leftTurn(hull[k - 2], hull[k - 1], p)) --k;
    hull[k++] = p;
  }
  hull.resize(k - 1);
  return hull;
}

Convex Convex::rotated(Angle angle) const {
  if (angle == 0) return *this;
  const Rotation r = rotationOf(angle);
  std::vector<Vec2> points;
  points.reserve(vertices_.size());
  for (const Vec2 v : vertices_) {
    const Vec2w w = rotateWide(r, wide(v));
    points.push_back({static_cast<int32_t>(w.x), static_cast<int32_t>(w.y)});
  }
  std::vector<Vec2> hull = convexHull(std::move(points));
  if (hull.size() < 3) throw Error("shape is too small to rotate: its rounded rotation collapses to a segment");
  return Convex(std::move(hull), Trusted{});
}

Convex Convex::regular(int n, int32_t radius) {
  if (n < 3 || n > kMaxConvexVertices) throw Error("regular polygon needs 3..64 vertices, got " + std::to_string(n));
  if (radius < 1 || radius > kShapeLimit)
    throw Error("regular polygon radius " + std::to_string(radius) + " is outside 1..2^29");
  std::vector<Vec2> points;
  for (int i = 0; i < n; ++i) {
    const Angle a = static_cast<Angle>((i128{1} << 32) * i / n);
    const Vec2w w = rotateWide(rotationOf(a), {radius, 0});
    points.push_back({static_cast<int32_t>(w.x), static_cast<int32_t>(w.y)});
  }
  return Convex(convexHull(std::move(points)));
}

Convex Convex::box(int32_t halfWidth, int32_t halfHeight) {
  // Checked before they are negated: -INT32_MIN does not exist.
  if (halfWidth < 1 || halfWidth > kShapeLimit || halfHeight < 1 || halfHeight > kShapeLimit)
    throw Error("box half-size (" + std::to_string(halfWidth) + ", " + std::to_string(halfHeight) +
                ") is outside 1..2^29");
  return Convex(
      {{-halfWidth, -halfHeight}, {halfWidth, -halfHeight}, {halfWidth, halfHeight}, {-halfWidth, halfHeight}});
}

}  // namespace platon::physics
