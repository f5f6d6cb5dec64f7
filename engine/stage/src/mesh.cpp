#include "platon/stage/mesh.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "platon/stage/stage_error.h"
#include "surface_checks.h"

namespace platon::stage {
namespace {

using detail::fail;

std::string triangleName(size_t t) { return "triangle " + std::to_string(t); }

std::string pointText(const Eigen::Vector3d& x) {
  char text[80];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", x.x(), x.y(), x.z());
  return text;
}

std::string amountText(double d) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", d);
  return text;
}

// The file's triangles on welded points, in the file's units.
struct Surface {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<size_t> fileTriangle;  // each triangle's index in the file

  const Eigen::Vector3d& at(int v) const { return points[static_cast<size_t>(v)]; }
  Eigen::Vector3d normal(size_t t) const {
    const auto& c = triangles[t];
    return (at(c[1]) - at(c[0])).cross(at(c[2]) - at(c[0])).normalized();
  }
};

void checkInput(const MeshData& mesh, double longestEdge) {
  if (mesh.triangles.size() > kMaxMeshTriangles)
    fail("the mesh has " + std::to_string(mesh.triangles.size()) + " triangles; a stage takes at most " +
         std::to_string(kMaxMeshTriangles));
  if (mesh.triangles.size() < 4)
    fail("a closed solid needs at least 4 triangles, the mesh has " + std::to_string(mesh.triangles.size()));
  if (!(longestEdge >= 1) || longestEdge > (1 << 24)) fail("the mesh's size must be 1 to 2^24 units");
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (!mesh.positions[i].allFinite() || mesh.positions[i].cwiseAbs().maxCoeff() > kMaxMeshCoordinate)
      fail("vertex " + std::to_string(i) + " is not a finite point of sensible size (within 1e15)");
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const int v : mesh.triangles[t])
      if (v < 0 || static_cast<size_t>(v) >= mesh.positions.size())
        fail(triangleName(t) + " names vertex " + std::to_string(v) + ", which does not exist");
}

// Joins the positions the triangles use that lie within `weld` of a point already kept (STL files
// repeat them per triangle), on a hash grid of `weld` cells: linear time. Points are numbered in
// the order the triangles first use them, so that the numbering follows the file.
std::vector<int> weldPositions(const MeshData& mesh, const Eigen::Vector3d& lo, double weld,
                               std::vector<Eigen::Vector3d>& out) {
  std::vector<int> id(mesh.positions.size(), -1);
  std::unordered_map<uint64_t, std::vector<int>> cells;
  auto cellOf = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector3d c = ((x - lo) / weld).array().floor();
    return Eigen::Vector3i(int(c.x()), int(c.y()), int(c.z()));
  };
  auto key = [](const Eigen::Vector3i& c) {  // cells are 0 to about 10^6 along each axis: 21 bits each
    return (uint64_t(uint32_t(c.x()) & 0x1fffff) << 42) | (uint64_t(uint32_t(c.y()) & 0x1fffff) << 21) |
           uint64_t(uint32_t(c.z()) & 0x1fffff);
  };
  for (const auto& tri : mesh.triangles)
    for (const int v : tri) {
      const auto i = static_cast<size_t>(v);
      if (id[i] >= 0) continue;
      const Eigen::Vector3d& x = mesh.positions[i];
      const Eigen::Vector3i c = cellOf(x);
      for (int dx = -1; dx <= 1 && id[i] < 0; ++dx)
        for (int dy = -1; dy <= 1 && id[i] < 0; ++dy)
          for (int dz = -1; dz <= 1 && id[i] < 0; ++dz) {
            const auto near = cells.find(key(c + Eigen::Vector3i(dx, dy, dz)));
            if (near == cells.end()) continue;
            for (const int k : near->second)
              if ((out[static_cast<size_t>(k)] - x).norm() <= weld) {
                id[i] = k;
                break;
              }
          }
      if (id[i] >= 0) continue;
      id[i] = static_cast<int>(out.size());
      cells[key(c)].push_back(id[i]);
      out.push_back(x);
    }
  return id;
}

// The mesh's triangles on welded points. A triangle whose corners are not three different points
// once welded covers nothing and is left out; one of three different points in a line is refused.
Surface weldedSurface(const MeshData& mesh, const Eigen::Vector3d& lo, double extent) {
  Surface s;
  const std::vector<int> id = weldPositions(mesh, lo, 1e-6 * extent, s.points);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& m = mesh.triangles[t];
    const std::array<int, 3> tri{id[static_cast<size_t>(m[0])], id[static_cast<size_t>(m[1])],
                                 id[static_cast<size_t>(m[2])]};
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) continue;
    const double area = (s.at(tri[1]) - s.at(tri[0])).cross(s.at(tri[2]) - s.at(tri[0])).norm() / 2;
    if (area <= 1e-10 * extent * extent)
      fail(triangleName(t) + " is degenerate: its corners " + pointText(s.at(tri[0])) + ", " + pointText(s.at(tri[1])) +
           " and " + pointText(s.at(tri[2])) + " lie on one line (no area)");
    s.triangles.push_back(tri);
    s.fileTriangle.push_back(t);
  }
  const size_t left = mesh.triangles.size() - s.triangles.size();
  if (s.triangles.empty())
    fail("all " + std::to_string(mesh.triangles.size()) + " triangles are degenerate (each has a repeated corner)");
  if (s.triangles.size() < 4)
    fail("a closed solid needs at least 4 triangles, the mesh has " + std::to_string(s.triangles.size()) + " (and " +
         std::to_string(left) + " with a repeated corner, which cover nothing)");
  return s;
}

// Where an open edge comes from a T-junction (a point of one triangle on another's edge): the
// message naming it, or "" when no open edge has a point along it. Looks only at the open edges'
// own ends, which are where such points are.
std::string tJunction(const Surface& s, const detail::EdgeIndex& edges, double tolerance) {
  std::vector<std::pair<size_t, size_t>> open;  // triangle, corner
  std::vector<int> ends;
  for (size_t t = 0; t < s.triangles.size() && open.size() < 2000; ++t)
    for (size_t k = 0; k < 3; ++k)
      if (!edges.find(s.triangles[t][(k + 1) % 3], s.triangles[t][k])) {
        open.push_back({t, k});
        ends.push_back(s.triangles[t][k]);
      }
  for (const auto& [t, k] : open) {
    const int a = s.triangles[t][k], b = s.triangles[t][(k + 1) % 3];
    const Eigen::Vector3d along = s.at(b) - s.at(a);
    for (const int w : ends) {
      if (w == a || w == b) continue;
      const double u = (s.at(w) - s.at(a)).dot(along) / along.squaredNorm();
      if (u <= 0 || u >= 1 || (s.at(a) + u * along - s.at(w)).norm() > tolerance) continue;
      return "a T-junction: the point " + pointText(s.at(w)) + " lies on the edge " + pointText(s.at(a)) + " - " +
             pointText(s.at(b)) + " of " + triangleName(s.fileTriangle[t]) +
             ", which the triangles on its other side "
             "split there (split " +
             triangleName(s.fileTriangle[t]) + " at that point too)";
    }
  }
  return "";
}

Polyhedron asPolyhedron(const Surface& s) {
  Polyhedron p{s.points, {}};
  for (const auto& t : s.triangles) p.faces.push_back({t[0], t[1], t[2]});
  return p;
}

// Turns the triangles outward (a mesh wound clockwise throughout has a negative volume).
void windOutward(Surface& s) {
  double volume = 0;
  for (const auto& t : s.triangles) volume += s.at(t[0]).dot(s.at(t[1]).cross(s.at(t[2])));
  if (volume < 0)
    for (auto& t : s.triangles) std::swap(t[1], t[2]);
}

// The triangles make a closed, manifold surface in one piece, convex at every edge and vertex
// (surface_checks.h: linear in the edges, not every point against every plane). Returns its edges.
detail::EdgeIndex checkSolid(const Surface& s, double tolerance) {
  const Polyhedron surface = asPolyhedron(s);
  const detail::SurfaceNames names{[&](size_t t) { return triangleName(s.fileTriangle[t]); },
                                   [&](int v) { return pointText(s.at(v)); }};
  detail::EdgeIndex edges(surface, names);
  detail::checkClosed(surface, edges, [&](int from, int to, size_t t) {
    const std::string junction = tJunction(s, edges, tolerance);
    return !junction.empty() ? junction
                             : "open mesh: the edge " + pointText(s.at(from)) + " - " + pointText(s.at(to)) + " of " +
                                   triangleName(s.fileTriangle[t]) + " has no triangle on its other side";
  });
  detail::checkConnected(surface, edges, names);
  std::vector<Eigen::Vector3d> normals;
  for (size_t t = 0; t < s.triangles.size(); ++t) normals.push_back(s.normal(t));
  detail::checkLocallyConvex(surface, edges, normals, tolerance, names);
  return edges;
}

// Faces: triangles joined across edges where they lie in one plane (flood fill from each face's
// first triangle, whose plane the others must lie within `tolerance` of). Returns each
// triangle's face and the number of faces.
std::pair<std::vector<int>, int> coplanarGroups(const Surface& s, const detail::EdgeIndex& edges, double tolerance) {
  std::vector<int> group(s.triangles.size(), -1);
  int groups = 0;
  for (size_t seed = 0; seed < s.triangles.size(); ++seed) {
    if (group[seed] >= 0) continue;
    const Eigen::Vector3d n = s.normal(seed);
    const Eigen::Vector3d& on = s.at(s.triangles[seed][0]);
    std::vector<size_t> stack{seed};
    group[seed] = groups;
    while (!stack.empty()) {
      const size_t t = stack.back();
      stack.pop_back();
      for (size_t k = 0; k < 3; ++k) {
        const size_t u = edges.find(s.triangles[t][(k + 1) % 3], s.triangles[t][k])->face;
        if (group[u] >= 0) continue;
        bool flat = true;
        for (const int v : s.triangles[u]) flat = flat && std::abs(n.dot(s.at(v) - on)) <= tolerance;
        if (!flat) continue;
        group[u] = groups;
        stack.push_back(u);
      }
    }
    ++groups;
  }
  return {group, groups};
}

// A face's corners: its triangles' edges whose other side is another face, chained, without the
// corners on a straight edge (a triangulation may put points along an edge).
std::vector<int> faceOutline(const Surface& s, const detail::EdgeIndex& edges, const std::vector<int>& group,
                             const std::vector<size_t>& members, double tolerance) {
  const int g = group[members[0]];
  const std::string name = "the face of " + triangleName(s.fileTriangle[members[0]]);
  std::unordered_map<int, int> next;
  for (const size_t t : members)
    for (size_t k = 0; k < 3; ++k) {
      const int a = s.triangles[t][k], b = s.triangles[t][(k + 1) % 3];
      if (group[edges.find(b, a)->face] == g) continue;
      if (!next.emplace(a, b).second)
        fail(name + " is not a simple polygon (it touches itself at " + pointText(s.at(a)) + ")");
    }
  // A group with no edge to another face is the whole surface in one plane: no volume.
  if (next.empty()) fail(name + " is the whole mesh: every triangle lies in one plane, so it encloses no volume");
  int start = next.begin()->first;  // the corner the file's triangles use first: points are numbered so
  for (const auto& [a, b] : next) start = std::min(start, a);
  std::vector<int> cycle{start};
  while (cycle.size() <= next.size()) {
    const auto it = next.find(cycle.back());
    if (it == next.end()) fail(name + " has a broken boundary at " + pointText(s.at(cycle.back())));
    if (it->second == cycle.front()) break;
    cycle.push_back(it->second);
  }
  if (cycle.size() != next.size()) fail(name + " has a hole or touches itself");
  std::vector<int> corners;
  for (size_t i = 0; i < cycle.size(); ++i) {
    const Eigen::Vector3d& a = s.at(cycle[(i + cycle.size() - 1) % cycle.size()]);
    const Eigen::Vector3d& b = s.at(cycle[i]);
    const Eigen::Vector3d& c = s.at(cycle[(i + 1) % cycle.size()]);
    if ((b - a).cross(c - a).norm() / (c - a).norm() > tolerance) corners.push_back(cycle[i]);
  }
  return corners;
}

// The solid of the coplanar groups' outlines, in the file's units.
Polyhedron mergedFaces(const Surface& s, const detail::EdgeIndex& edges, double tolerance,
                       std::vector<size_t>& firstTriangle) {
  const auto [group, groups] = coplanarGroups(s, edges, tolerance);
  std::vector<std::vector<size_t>> members(static_cast<size_t>(groups));
  for (size_t t = 0; t < s.triangles.size(); ++t) members[static_cast<size_t>(group[t])].push_back(t);
  Polyhedron out;
  std::unordered_map<int, int> used;  // point -> output vertex
  for (const auto& m : members) {
    std::vector<int> face;
    for (const int c : faceOutline(s, edges, group, m, tolerance)) {
      const auto [at, added] = used.emplace(c, static_cast<int>(out.vertices.size()));
      if (added) out.vertices.push_back(s.at(c));
      face.push_back(at->second);
    }
    out.faces.push_back(std::move(face));
    firstTriangle.push_back(s.fileTriangle[m[0]]);
    // The same flatness test validatePolyhedron makes, so that it never refuses what the merge made.
    if (const detail::OffPlane off = detail::worstOffPlane(out, out.faces.size() - 1); off.distance > tolerance)
      fail("the face of " + triangleName(s.fileTriangle[m[0]]) + " is not flat: its triangles each lie within " +
           "1e-6 of the mesh's size of its first one's plane, but the point " +
           pointText(out.vertices[size_t(off.vertex)]) + " is " + amountText(off.distance) +
           " off the face's own plane (the mesh curves too gently to be one face or two)");
  }
  return out;
}

// What stageFromPolyhedron checks of the merged solid, checked here so that a refusal names the
// file's triangles and points (the merged faces and vertices are the builder's own).
// `firstTriangle`: each merged face's first triangle in the file.
void checkMerged(const Polyhedron& merged, const std::vector<size_t>& firstTriangle, double tolerance) {
  const detail::SurfaceNames names{[&](size_t f) { return "the face of " + triangleName(firstTriangle[f]); },
                                   [&](int v) { return pointText(merged.vertices[size_t(v)]); }};
  try {
    detail::validatePolyhedron(merged, tolerance, names);
  } catch (const StageError& e) {
    fail(
        "the faces merged from triangles within 1e-6 of the mesh's size of one plane do not make a convex solid (the "
        "mesh bends too gently to tell its faces apart): " +
        e.reason());
  }
}

}  // namespace

Polyhedron polyhedronFromMesh(const MeshData& mesh, double longestEdge) {
  checkInput(mesh, longestEdge);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (const auto& tri : mesh.triangles)
    for (const int v : tri) {
      lo = lo.cwiseMin(mesh.positions[static_cast<size_t>(v)]);
      hi = hi.cwiseMax(mesh.positions[static_cast<size_t>(v)]);
    }
  const double extent = (hi - lo).norm();
  if (!(extent > 0))
    fail("all " + std::to_string(mesh.triangles.size()) +
         " triangles are degenerate (every point of the mesh is the same)");
  const double tolerance = 1e-6 * extent;  // a mesh file's floats hold about 7 digits
  Surface surface = weldedSurface(mesh, lo, extent);
  windOutward(surface);
  const detail::EdgeIndex edges = checkSolid(surface, tolerance);
  std::vector<size_t> firstTriangle;
  Polyhedron out = mergedFaces(surface, edges, tolerance, firstTriangle);
  checkMerged(out, firstTriangle, tolerance);

  // Scaled to units round the centre of the bounding box. stageFromPolyhedron validates the result
  // once more as a polyhedron (in linear time too).
  double longest = 0;
  for (const auto& f : out.faces)
    for (size_t i = 0; i < f.size(); ++i)
      longest = std::max(
          longest,
          (out.vertices[static_cast<size_t>(f[i])] - out.vertices[static_cast<size_t>(f[(i + 1) % f.size()])]).norm());
  const Eigen::Vector3d centre = (lo + hi) / 2;
  for (auto& v : out.vertices) v = (v - centre) * (longestEdge / longest);
  return out;
}

}  // namespace platon::stage
