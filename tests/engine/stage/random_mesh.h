// Random convex solids that are not Platonic, for the stage tests' families.
#pragma once
#include <cmath>

#include "platon/stage/mesh.h"
#include "platon/testing/rng.h"

namespace platon::stage::test {

// A convex solid that is not Platonic, as a mesh file would give it: an n-sided prism or
// bipyramid of random proportions, turned at random.
inline MeshData randomConvexMesh(platon::testing::Rng& rng) {
  MeshData m;
  const int n = rng.between(3, 10);
  const bool prism = rng.between(0, 1) == 1;
  const double h = rng.uniform(0.3, 3.0);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    m.positions.push_back({std::cos(a), prism ? -h / 2 : 0.0, std::sin(a)});
    if (prism) m.positions.push_back({std::cos(a), h / 2, std::sin(a)});
  }
  const int low = static_cast<int>(m.positions.size()), high = low + 1;
  m.positions.push_back({0, prism ? -h / 2 : -h, 0});
  m.positions.push_back({0, prism ? h / 2 : h, 0});
  auto ring = [&](int i, int level) { return prism ? 2 * (i % n) + level : i % n; };
  for (int i = 0; i < n; ++i) {
    m.triangles.push_back({low, ring(i, 0), ring(i + 1, 0)});
    m.triangles.push_back({high, ring(i + 1, 1), ring(i, 1)});
    if (prism) {
      m.triangles.push_back({ring(i, 0), ring(i, 1), ring(i + 1, 1)});
      m.triangles.push_back({ring(i, 0), ring(i + 1, 1), ring(i + 1, 0)});
    }
  }
  // The winding above may run either way: the builder turns a mesh wound clockwise throughout over.
  Eigen::Quaterniond q(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
  q.normalize();
  for (Eigen::Vector3d& p : m.positions) p = q.toRotationMatrix() * p;
  return m;
}

}  // namespace platon::stage::test
