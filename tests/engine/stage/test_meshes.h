// Meshes for the mesh builder's tests and benchmarks: a box, a subdivided icosahedron (a geodesic
// sphere of 20 * 4^k triangles), a Platonic solid's faces fanned into triangles, and the
// every-point-against-every-plane convexity test the builder no longer runs (the oracle).
#pragma once
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "platon/stage/mesh.h"
#include "platon/stage/polyhedron.h"

namespace platon::testmesh {

// An axis-aligned box from -half to +half, 12 triangles counter-clockwise from outside.
inline stage::MeshData box(const Eigen::Vector3d& half) {
  stage::MeshData m;
  for (int i = 0; i < 8; ++i)
    m.positions.emplace_back((i & 1 ? 1 : -1) * half.x(), (i & 2 ? 1 : -1) * half.y(), (i & 4 ? 1 : -1) * half.z());
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

// A Platonic solid's polygon faces fanned into triangles.
inline stage::MeshData fanned(const stage::Polyhedron& p) {
  stage::MeshData m;
  m.positions = p.vertices;
  for (const auto& f : p.faces)
    for (size_t k = 1; k + 1 < f.size(); ++k) m.triangles.push_back({f[0], f[k], f[k + 1]});
  return m;
}

// The icosahedron with each triangle split in four `levels` times, points pushed onto the unit
// sphere: 20 * 4^levels triangles, none of them coplanar.
inline stage::MeshData icosphere(int levels) {
  stage::MeshData m = fanned(stage::platonicSolid(stage::Solid::Icosahedron, 1));
  for (auto& p : m.positions) p.normalize();
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> middle;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto [at, added] = middle.emplace(key, static_cast<int>(m.positions.size()));
      if (added) m.positions.push_back((m.positions[size_t(a)] + m.positions[size_t(b)]).normalized());
      return at->second;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& t : m.triangles) {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({t[1], bc, ab});
      finer.push_back({t[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    m.triangles = std::move(finer);
  }
  return m;
}

// How far the point of the mesh farthest in front of some triangle's plane lies in front of it
// (<= 0: every point behind every plane, the brute-force test of convexity), over the size.
inline double worstAhead(const stage::MeshData& m) {
  Eigen::Vector3d lo = m.positions[0], hi = m.positions[0];
  for (const auto& p : m.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  double volume = 0;  // a mesh wound clockwise throughout is turned over, as the builder does
  for (const auto& t : m.triangles)
    volume += m.positions[size_t(t[0])].dot(m.positions[size_t(t[1])].cross(m.positions[size_t(t[2])]));
  double worst = -INFINITY;
  for (const auto& t : m.triangles) {
    const Eigen::Vector3d& a = m.positions[size_t(t[0])];
    const Eigen::Vector3d n =
        (volume < 0 ? -1.0 : 1.0) * (m.positions[size_t(t[1])] - a).cross(m.positions[size_t(t[2])] - a).normalized();
    for (const auto& p : m.positions) worst = std::max(worst, n.dot(p - a));
  }
  return worst / (hi - lo).norm();
}

}  // namespace platon::testmesh
