// The five Platonic solids from their textbook coordinates: faces found as the planes through
// three vertices with every vertex on one side, then the solid turned to face the camera.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <set>

#include "platon/stage/polyhedron.h"

namespace platon::stage {
namespace {

std::vector<Eigen::Vector3d> textbookVertices(Solid solid) {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  std::vector<Eigen::Vector3d> v;
  auto signs = [&](double x, double y, double z) {  // every sign combination of the non-zero parts
    for (const double sx : {1.0, -1.0})
      for (const double sy : {1.0, -1.0})
        for (const double sz : {1.0, -1.0}) {
          const Eigen::Vector3d p{sx * x, sy * y, sz * z};
          if (std::none_of(v.begin(), v.end(), [&](const Eigen::Vector3d& q) { return q == p; })) v.push_back(p);
        }
  };
  switch (solid) {
    case Solid::Tetrahedron:
      return {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    case Solid::Hexahedron:
      signs(1, 1, 1);
      break;
    case Solid::Octahedron:
      signs(1, 0, 0);
      signs(0, 1, 0);
      signs(0, 0, 1);
      break;
    case Solid::Dodecahedron:
      signs(1, 1, 1);
      signs(0, 1 / phi, phi);
      signs(1 / phi, phi, 0);
      signs(phi, 0, 1 / phi);
      break;
    case Solid::Icosahedron:
      signs(0, 1, phi);
      signs(1, phi, 0);
      signs(phi, 0, 1);
      break;
  }
  return v;
}

// The faces of the convex hull of `points` (all of them on the hull), counter-clockwise from outside.
std::vector<std::vector<int>> hullFaces(const std::vector<Eigen::Vector3d>& points) {
  const double tolerance = 1e-9;
  std::set<std::vector<int>> seen;
  std::vector<std::vector<int>> faces;
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        Eigen::Vector3d normal = (points[j] - points[i]).cross(points[k] - points[i]);
        if (normal.norm() < tolerance) continue;
        normal.normalize();
        double lo = 0, hi = 0;
        for (const auto& p : points) {
          const double s = normal.dot(p - points[i]);
          lo = std::min(lo, s);
          hi = std::max(hi, s);
        }
        if (lo < -tolerance && hi > tolerance) continue;  // points on both sides: not a face
        if (hi > tolerance) normal = -normal;
        std::vector<int> on;
        for (int m = 0; m < n; ++m)
          if (std::abs(normal.dot(points[m] - points[i])) <= tolerance) on.push_back(m);
        if (!seen.insert(on).second) continue;
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        for (const int m : on) centre += points[m];
        centre /= static_cast<double>(on.size());
        const Eigen::Vector3d u = (points[on[0]] - centre).normalized(), w = normal.cross(u);
        std::sort(on.begin(), on.end(), [&](int a, int b) {
          return std::atan2(w.dot(points[a] - centre), u.dot(points[a] - centre)) <
                 std::atan2(w.dot(points[b] - centre), u.dot(points[b] - centre));
        });
        faces.push_back(on);
      }
  return faces;
}

// The rotation that turns direction a into direction b: Eigen's Quaternion::FromTwoVectors, step for
// step (so the same bits), but for opposite directions, where Eigen solves a singular value problem
// for the axis (its JacobiSVD is a third of this module's build time) and any axis at right angles
// will do (a face never looks straight away from +z here: the one chosen looks most toward it).
Eigen::Quaterniond fromTwoVectors(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d v0 = a.normalized(), v1 = b.normalized();
  const double c = v1.dot(v0);
  Eigen::Quaterniond q;
  if (c < -1 + Eigen::NumTraits<double>::dummy_precision()) {
    const double w2 = (1 + std::max(c, -1.0)) * 0.5;
    q.w() = std::sqrt(w2);
    q.vec() = v0.unitOrthogonal() * std::sqrt(1 - w2);
    return q;
  }
  const Eigen::Vector3d axis = v0.cross(v1);
  const double s = std::sqrt((1 + c) * 2);
  const double invs = 1 / s;
  q.vec() = axis * invs;
  q.w() = s * 0.5;
  return q;
}

}  // namespace

Polyhedron platonicSolid(Solid solid, double edge) {
  Polyhedron p{textbookVertices(solid), {}};
  p.faces = hullFaces(p.vertices);
  double shortest = INFINITY;
  for (size_t i = 0; i < p.vertices.size(); ++i)
    for (size_t j = i + 1; j < p.vertices.size(); ++j)
      shortest = std::min(shortest, (p.vertices[i] - p.vertices[j]).norm());
  // Turn the face most toward +z to look along +z, then about z so that its edge most toward -y
  // runs along x below its centre. The textbook coordinates already do this for the cube.
  size_t front = 0;
  for (size_t f = 1; f < p.faces.size(); ++f)
    if (faceNormal(p, f).z() > faceNormal(p, front).z() + 1e-9) front = f;
  const Eigen::Quaterniond toFront = fromTwoVectors(faceNormal(p, front), Eigen::Vector3d::UnitZ());
  for (auto& v : p.vertices) v = toFront * v;
  const auto& cycle = p.faces[front];
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const int v : cycle) centre += p.vertices[static_cast<size_t>(v)];
  centre /= static_cast<double>(cycle.size());
  double bestY = INFINITY, angle = 0;
  for (size_t i = 0; i < cycle.size(); ++i) {
    const Eigen::Vector3d mid =
        (p.vertices[static_cast<size_t>(cycle[i])] + p.vertices[static_cast<size_t>(cycle[(i + 1) % cycle.size()])]) /
            2 -
        centre;
    if (mid.y() < bestY - 1e-9) {
      bestY = mid.y();
      angle = -M_PI / 2 - std::atan2(mid.y(), mid.x());
    }
  }
  const Eigen::AngleAxisd level(angle, Eigen::Vector3d::UnitZ());
  for (auto& v : p.vertices) {
    v = level * v * (edge / shortest);
    for (int c = 0; c < 3; ++c)
      if (std::abs(v[c]) < 1e-12 * edge) v[c] = 0;  // exact zeros keep the frame rule's ties exact
  }
  return p;
}

}  // namespace platon::stage
