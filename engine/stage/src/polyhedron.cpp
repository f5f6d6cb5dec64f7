#include "platon/stage/polyhedron.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "platon/stage/stage_error.h"
#include "surface_checks.h"

namespace platon::stage {
namespace {

std::string vertexName(const Polyhedron& p, int v) {
  const Eigen::Vector3d& x = p.vertices[static_cast<size_t>(v)];
  char text[96];
  std::snprintf(text, sizeof text, "vertex %d (%.6g, %.6g, %.6g)", v, x.x(), x.y(), x.z());
  return text;
}

using detail::fail;

void checkFaceShape(const Polyhedron& p, size_t f, double tolerance, const detail::SurfaceNames& names) {
  const auto& cycle = p.faces[f];
  const std::string name = names.face(f);
  auto vertexName = [&](const Polyhedron&, int v) { return names.point(v); };
  if (cycle.size() < 3) fail(name + " has " + std::to_string(cycle.size()) + " corners (at least 3)");
  for (const int v : cycle)
    if (v < 0 || static_cast<size_t>(v) >= p.vertices.size())
      fail(name + " names vertex " + std::to_string(v) + ", which does not exist");
  std::vector<int> sorted = cycle;  // sorted: a face of 10^5 corners checks in n log n
  std::sort(sorted.begin(), sorted.end());
  if (const auto twice = std::adjacent_find(sorted.begin(), sorted.end()); twice != sorted.end())
    fail(name + " visits " + vertexName(p, *twice) + " twice");
  const Eigen::Vector3d n = faceNormal(p, f);
  if (!n.allFinite()) fail(name + " is degenerate (no area)");
  if (const detail::OffPlane off = detail::worstOffPlane(p, f); off.distance > tolerance)
    fail(name + " is not flat: " + vertexName(p, off.vertex) + " is " + std::to_string(off.distance) +
         " off its plane");
  for (size_t i = 0; i < cycle.size(); ++i) {
    const Eigen::Vector3d& a = p.vertices[static_cast<size_t>(cycle[i])];
    const Eigen::Vector3d& b = p.vertices[static_cast<size_t>(cycle[(i + 1) % cycle.size()])];
    const Eigen::Vector3d& d = p.vertices[static_cast<size_t>(cycle[(i + 2) % cycle.size()])];
    const double edge = (b - a).norm();
    if (edge <= tolerance)
      fail(name + " has an edge of length " + std::to_string(edge) + " at " + vertexName(p, cycle[i]));
    // d's distance to the left of the line a -> b: positive for a convex counter-clockwise corner.
    const double turn = (b - a).cross(d - b).dot(n) / edge;
    if (turn <= tolerance)
      fail(name + (turn < -tolerance ? " is not convex" : " has a straight corner") + " at " +
           vertexName(p, cycle[(i + 1) % cycle.size()]));
  }
}

}  // namespace

std::string_view solidName(Solid solid) {
  switch (solid) {
    case Solid::Tetrahedron:
      return "TETRAHEDRON";
    case Solid::Hexahedron:
      return "HEXAHEDRON";
    case Solid::Octahedron:
      return "OCTAHEDRON";
    case Solid::Dodecahedron:
      return "DODECAHEDRON";
    case Solid::Icosahedron:
      return "ICOSAHEDRON";
  }
  return "?";
}

std::optional<Solid> solidFromName(std::string_view name) {
  for (const Solid s : kSolids)
    if (solidName(s) == name) return s;
  return std::nullopt;
}

int faceCount(Solid solid) {
  switch (solid) {
    case Solid::Tetrahedron:
      return 4;
    case Solid::Hexahedron:
      return 6;
    case Solid::Octahedron:
      return 8;
    case Solid::Dodecahedron:
      return 12;
    case Solid::Icosahedron:
      return 20;
  }
  return 0;
}

double sizeOf(const Polyhedron& p) {
  if (p.vertices.empty()) return 0;
  Eigen::Vector3d lo = p.vertices[0], hi = p.vertices[0];
  for (const auto& v : p.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return (hi - lo).norm();
}

Eigen::Vector3d faceCentre(const Polyhedron& p, size_t face) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const int v : p.faces[face]) c += p.vertices[static_cast<size_t>(v)];
  return c / static_cast<double>(p.faces[face].size());
}

Eigen::Vector3d faceNormal(const Polyhedron& p, size_t face) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  const auto& cycle = p.faces[face];
  for (size_t i = 0; i < cycle.size(); ++i) {
    const Eigen::Vector3d& a = p.vertices[static_cast<size_t>(cycle[i])];
    const Eigen::Vector3d& b = p.vertices[static_cast<size_t>(cycle[(i + 1) % cycle.size()])];
    n += a.cross(b);
  }
  const double length = n.norm();
  if (!(length > 0)) return Eigen::Vector3d::Constant(std::nan(""));
  return n / length;
}

void validatePolyhedron(const Polyhedron& p, double tolerance) {
  detail::validatePolyhedron(
      p, tolerance, {[](size_t f) { return "face " + std::to_string(f); }, [&](int v) { return vertexName(p, v); }});
}

void detail::validatePolyhedron(const Polyhedron& p, double tolerance, const SurfaceNames& names) {
  if (p.faces.size() < 4) fail("a solid needs at least 4 faces, this one has " + std::to_string(p.faces.size()));
  for (size_t v = 0; v < p.vertices.size(); ++v)
    if (!p.vertices[v].allFinite()) fail("vertex " + std::to_string(v) + " is not a finite point");
  for (size_t f = 0; f < p.faces.size(); ++f) checkFaceShape(p, f, tolerance, names);

  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (size_t f = 0; f < p.faces.size(); ++f) centre += faceCentre(p, f);
  centre /= static_cast<double>(p.faces.size());
  std::vector<Eigen::Vector3d> normals;
  for (size_t f = 0; f < p.faces.size(); ++f) {
    normals.push_back(faceNormal(p, f));
    if (normals.back().dot(faceCentre(p, f) - centre) <= 0)
      fail(names.face(f) + " faces inward (its corners run clockwise seen from outside)");
  }

  const detail::EdgeIndex edges(p, names);
  detail::checkClosed(p, edges, [&](int from, int to, size_t f) {
    return "open solid: the edge from " + names.point(from) + " to " + names.point(to) + " has " + names.face(f) +
           " on one side and nothing on the other";
  });
  detail::checkConnected(p, edges, names);
  detail::checkLocallyConvex(p, edges, normals, tolerance, names);
}

}  // namespace platon::stage
