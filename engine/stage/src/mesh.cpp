#include "platon/stage/mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "platon/stage/stage_error.h"

namespace platon::stage {
namespace {

[[noreturn]] void fail(const std::string& reason) { throw StageError({}, reason); }

std::string triangleName(size_t t) { return "triangle " + std::to_string(t); }

std::string pointText(const Eigen::Vector3d& x) {
  char text[80];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", x.x(), x.y(), x.z());
  return text;
}

// Joins positions closer than `weld` (sorted along x so that only near neighbours are compared).
std::vector<int> weldPositions(const std::vector<Eigen::Vector3d>& positions, double weld, std::vector<Eigen::Vector3d>& out) {
  std::vector<size_t> order(positions.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return positions[a].x() < positions[b].x(); });
  std::vector<int> id(positions.size(), -1);
  for (size_t i = 0; i < order.size(); ++i) {
    const size_t a = order[i];
    if (id[a] >= 0) continue;
    id[a] = static_cast<int>(out.size());
    out.push_back(positions[a]);
    for (size_t j = i + 1; j < order.size() && positions[order[j]].x() - positions[a].x() <= weld; ++j)
      if (id[order[j]] < 0 && (positions[order[j]] - positions[a]).norm() <= weld) id[order[j]] = id[a];
  }
  return id;
}

}  // namespace

Polyhedron polyhedronFromMesh(const MeshData& mesh, double longestEdge) {
  if (mesh.triangles.size() < 4) fail("a closed solid needs at least 4 triangles, the mesh has " + std::to_string(mesh.triangles.size()));
  if (!(longestEdge >= 1) || longestEdge > (1 << 24)) fail("the mesh's size must be 1 to 2^24 units");
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (!mesh.positions[i].allFinite() || mesh.positions[i].cwiseAbs().maxCoeff() > 1e15)
      fail("vertex " + std::to_string(i) + " is not a finite point of sensible size");
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const int v : mesh.triangles[t])
      if (v < 0 || static_cast<size_t>(v) >= mesh.positions.size())
        fail(triangleName(t) + " names vertex " + std::to_string(v) + ", which does not exist");

  // Size, weld, and scale to units around the centre of the bounding box.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (const auto& tri : mesh.triangles)
    for (const int v : tri) {
      lo = lo.cwiseMin(mesh.positions[static_cast<size_t>(v)]);
      hi = hi.cwiseMax(mesh.positions[static_cast<size_t>(v)]);
    }
  const double extent = (hi - lo).norm();
  if (!(extent > 0)) fail("the mesh has no extent (all its points are one)");
  std::vector<Eigen::Vector3d> points;
  const std::vector<int> id = weldPositions(mesh.positions, 1e-6 * extent, points);
  std::vector<std::array<int, 3>> tris;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& m = mesh.triangles[t];
    const std::array<int, 3> tri{id[static_cast<size_t>(m[0])], id[static_cast<size_t>(m[1])], id[static_cast<size_t>(m[2])]};
    const Eigen::Vector3d& a = points[static_cast<size_t>(tri[0])];
    const double area = (points[static_cast<size_t>(tri[1])] - a).cross(points[static_cast<size_t>(tri[2])] - a).norm() / 2;
    if (area <= 1e-10 * extent * extent)
      fail(triangleName(t) + " is degenerate (no area) at " + pointText(mesh.positions[static_cast<size_t>(m[0])]));
    tris.push_back(tri);
  }

  // Every directed edge once; the winding: turned over when the volume comes out negative.
  std::map<std::pair<int, int>, size_t> edgeTriangle;
  for (size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::pair<int, int> e{tris[t][static_cast<size_t>(k)], tris[t][static_cast<size_t>((k + 1) % 3)]};
      const auto [at, added] = edgeTriangle.emplace(e, t);
      if (!added)
        fail("triangles " + std::to_string(at->second) + " and " + std::to_string(t) + " run the same way along the edge " +
             pointText(points[static_cast<size_t>(e.first)]) + " - " + pointText(points[static_cast<size_t>(e.second)]) +
             " (non-manifold, or wound inconsistently)");
    }
  for (const auto& [e, t] : edgeTriangle)
    if (!edgeTriangle.count({e.second, e.first}))
      fail("open mesh: the edge " + pointText(points[static_cast<size_t>(e.first)]) + " - " +
           pointText(points[static_cast<size_t>(e.second)]) + " of " + triangleName(t) + " has no triangle on its other side");
  double volume = 0;
  for (const auto& t : tris)
    volume += points[static_cast<size_t>(t[0])].dot(points[static_cast<size_t>(t[1])].cross(points[static_cast<size_t>(t[2])]));
  if (volume < 0)
    for (auto& t : tris) std::swap(t[1], t[2]);

  const double tolerance = 1e-6 * extent;
  auto normalOf = [&](const std::array<int, 3>& t) {
    return Eigen::Vector3d((points[static_cast<size_t>(t[1])] - points[static_cast<size_t>(t[0])])
                               .cross(points[static_cast<size_t>(t[2])] - points[static_cast<size_t>(t[0])])
                               .normalized());
  };
  for (size_t t = 0; t < tris.size(); ++t) {
    const Eigen::Vector3d n = normalOf(tris[t]);
    for (size_t v = 0; v < points.size(); ++v) {
      const double ahead = n.dot(points[v] - points[static_cast<size_t>(tris[t][0])]);
      if (ahead > tolerance)
        fail("not convex: the point " + pointText(points[v]) + " lies in front of " + triangleName(t) + "'s plane");
    }
  }

  // Faces: triangles joined across edges where they lie in one plane (flood fill).
  std::vector<int> group(tris.size(), -1);
  int groups = 0;
  std::map<std::pair<int, int>, size_t> owner;
  for (size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) owner[{tris[t][static_cast<size_t>(k)], tris[t][static_cast<size_t>((k + 1) % 3)]}] = t;
  for (size_t seed = 0; seed < tris.size(); ++seed) {
    if (group[seed] >= 0) continue;
    const Eigen::Vector3d n = normalOf(tris[seed]);
    const Eigen::Vector3d& on = points[static_cast<size_t>(tris[seed][0])];
    std::vector<size_t> stack{seed};
    group[seed] = groups;
    while (!stack.empty()) {
      const size_t t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const size_t u = owner.at({tris[t][static_cast<size_t>((k + 1) % 3)], tris[t][static_cast<size_t>(k)]});
        if (group[u] >= 0) continue;
        bool flat = true;
        for (const int v : tris[u]) flat = flat && std::abs(n.dot(points[static_cast<size_t>(v)] - on)) <= tolerance;
        if (!flat) continue;
        group[u] = groups;
        stack.push_back(u);
      }
    }
    ++groups;
  }

  // Each face's boundary: its triangles' edges whose other side is another face, chained.
  Polyhedron out;
  std::map<int, int> used;  // point -> output vertex
  for (int g = 0; g < groups; ++g) {
    std::map<int, int> next;
    for (size_t t = 0; t < tris.size(); ++t) {
      if (group[t] != g) continue;
      for (int k = 0; k < 3; ++k) {
        const int a = tris[t][static_cast<size_t>(k)], b = tris[t][static_cast<size_t>((k + 1) % 3)];
        if (group[owner.at({b, a})] == g) continue;
        if (!next.emplace(a, b).second) fail("face " + std::to_string(g) + " (around " + triangleName(t) + ") is not a simple polygon");
      }
    }
    std::vector<int> cycle{next.begin()->first};
    while (cycle.size() <= next.size()) {
      const auto it = next.find(cycle.back());
      if (it == next.end()) fail("face " + std::to_string(g) + " has a broken boundary");
      if (it->second == cycle.front()) break;
      cycle.push_back(it->second);
    }
    if (cycle.size() != next.size()) fail("face " + std::to_string(g) + " has a hole or touches itself");
    // Drop corners on a straight edge (a triangulation may put points along an edge).
    std::vector<int> corners;
    for (size_t i = 0; i < cycle.size(); ++i) {
      const Eigen::Vector3d& a = points[static_cast<size_t>(cycle[(i + cycle.size() - 1) % cycle.size()])];
      const Eigen::Vector3d& b = points[static_cast<size_t>(cycle[i])];
      const Eigen::Vector3d& c = points[static_cast<size_t>(cycle[(i + 1) % cycle.size()])];
      if ((b - a).cross(c - a).norm() / (c - a).norm() > tolerance) corners.push_back(cycle[i]);
    }
    std::vector<int> face;
    for (const int c : corners) {
      const auto [at, added] = used.emplace(c, static_cast<int>(out.vertices.size()));
      if (added) out.vertices.push_back(points[static_cast<size_t>(c)]);
      face.push_back(at->second);
    }
    out.faces.push_back(std::move(face));
  }

  double longest = 0;
  for (const auto& f : out.faces)
    for (size_t i = 0; i < f.size(); ++i)
      longest = std::max(longest, (out.vertices[static_cast<size_t>(f[i])] - out.vertices[static_cast<size_t>(f[(i + 1) % f.size()])]).norm());
  const Eigen::Vector3d centre = (lo + hi) / 2;
  for (auto& v : out.vertices) v = (v - centre) * (longestEdge / longest);
  validatePolyhedron(out, 1e-6 * sizeOf(out));
  return out;
}

}  // namespace platon::stage
