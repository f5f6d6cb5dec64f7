// A strictly convex polygon with integer vertices in counter-clockwise order.
#pragma once
#include <span>
#include <vector>

#include "platon/physics/angle.h"
#include "platon/physics/vec2.h"

namespace platon::physics {

inline constexpr int kMaxConvexVertices = 64;

class Convex {
 public:
  // Validates: 3..64 vertices, |coordinate| <= kShapeLimit, no repeats, counter-clockwise,
  // strictly convex. Throws Error naming the offending vertex index.
  explicit Convex(std::vector<Vec2> vertices);

  std::span<const Vec2> vertices() const& { return vertices_; }
  std::span<const Vec2> vertices() const&& = delete;  // would dangle: keep the Convex alive
  int size() const { return static_cast<int>(vertices_.size()); }

  // The shape turned by `angle` about its origin: each vertex rotated and rounded to the nearest
  // unit, then the convex hull of those points (rounding may merge or straighten vertices).
  // Throws Error if the rotated shape collapses to fewer than three corners.
  Convex rotated(Angle angle) const;

  // Regular n-gon with the given circumradius (vertices rounded), first vertex at angle 0.
  static Convex regular(int n, int32_t radius);
  static Convex box(int32_t halfWidth, int32_t halfHeight);

 private:
  struct Trusted {};
  Convex(std::vector<Vec2> vertices, Trusted) : vertices_(std::move(vertices)) {}
  std::vector<Vec2> vertices_;
};

// Convex hull (counter-clockwise, no collinear points) of integer points; may have < 3 points.
std::vector<Vec2> convexHull(std::vector<Vec2> points);

}  // namespace platon::physics
