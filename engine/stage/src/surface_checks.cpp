#include "surface_checks.h"

#include <algorithm>
#include <cmath>

#include "platon/stage/stage_error.h"

namespace platon::stage::detail {

void fail(const std::string& reason) { throw StageError({}, reason); }

namespace {

size_t next(size_t i, size_t n) { return (i + 1) % n; }

// The face across the edge from corner `corner` of `face`, and that edge's corner there.
EdgeIndex::Use across(const Polyhedron& p, const EdgeIndex& edges, size_t face, size_t corner) {
  const auto& cycle = p.faces[face];
  return *edges.find(cycle[next(corner, cycle.size())], cycle[corner]);  // checkClosed ran first
}

// The fan's faces whose planes each far end of its edges must lie behind: every one for a fan
// of up to kEveryFace faces, else that many spread round it (a cone's apex may have 10^5).
constexpr size_t kEveryFace = 32;

// Walks the fan of faces round the vertex at `corner` of `face` (its outgoing edges, clockwise
// seen from outside) and checks that it is the vertex's only fan, that the far end of each of its
// edges lies at most `tolerance` in front of each of its faces' planes (so that inward bends each
// under the tolerance at its edge cannot add up round a vertex into a dent), and that it winds
// round the vertex once.
void checkFan(const Polyhedron& p, const EdgeIndex& edges, const std::vector<Eigen::Vector3d>& normals, size_t face,
              size_t corner, int outgoing, double tolerance, const SurfaceNames& names) {
  const int v = p.faces[face][corner];
  const Eigen::Vector3d& at = p.vertices[size_t(v)];
  std::vector<Eigen::Vector3d> directions;  // unit vectors along the fan's edges
  std::vector<int> ends;                    // the edges' far ends
  std::vector<size_t> fanFaces;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  size_t f = face, c = corner;
  do {
    const auto& cycle = p.faces[f];
    ends.push_back(cycle[next(c, cycle.size())]);
    directions.push_back((p.vertices[size_t(ends.back())] - at).normalized());
    fanFaces.push_back(f);
    normal += normals[f];
    // The face across the outgoing edge v -> b runs b -> v; its outgoing edge from v comes next.
    const EdgeIndex::Use back = across(p, edges, f, c);
    f = back.face;
    c = next(back.corner, p.faces[f].size());
    if (directions.size() > size_t(outgoing)) break;
  } while (f != face || c != corner);
  if (directions.size() != size_t(outgoing))
    fail("two fans of faces meet at the point " + names.point(v) + " (the surface pinches there): not a solid");
  // The winding is counted round an axis out of the solid whose opposite lies inside the cone of
  // the fan's edges. A convex corner's cone is where every face's plane has it behind, so the
  // mean normal serves whenever each face's normal leans toward it (every nearly flat fan: the
  // mean edge direction would lie almost in the plane, and its winding mean nothing); a sharp,
  // skewed corner, whose faces' normals spread wide, takes the mean edge direction reversed,
  // which lies inside the cone of any convex corner. Seen from outside the fan turns clockwise:
  // -2 pi once.
  normal.normalize();
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
  double leastLean = 1;
  for (const auto& d : directions) axis -= d;
  for (const size_t g : fanFaces) leastLean = std::min(leastLean, normals[g].dot(normal));
  axis = leastLean > 0.5 ? normal : axis.normalized();
  double turn = 0;
  for (size_t i = 0; i < directions.size(); ++i) {
    const Eigen::Vector3d a = directions[i] - directions[i].dot(axis) * axis;
    const Eigen::Vector3d b =
        directions[next(i, directions.size())] - directions[next(i, directions.size())].dot(axis) * axis;
    if (!(a.norm() > 1e-12)) fail("not convex at the point " + names.point(v) + " (its faces fold back)");
    turn += std::atan2(a.cross(b).dot(axis), a.dot(b));
  }
  const long winds = std::lround(-turn / (2 * M_PI));
  if (winds > 1)
    fail("not convex: the faces round the point " + names.point(v) + " wind round it " + std::to_string(winds) +
         " times, not once (the surface folds over itself)");
  const size_t step = std::max<size_t>(1, fanFaces.size() / kEveryFace);
  for (size_t i = 0; i < ends.size(); ++i)
    for (size_t k = 0; k < fanFaces.size(); k += step) {
      const double ahead = normals[fanFaces[k]].dot(p.vertices[size_t(ends[i])] - at);
      if (ahead <= tolerance) continue;
      char amount[32];
      std::snprintf(amount, sizeof amount, "%.3g", ahead);
      fail("not convex near the point " + names.point(v) + ": the point " + names.point(ends[i]) + " lies " + amount +
           " in front of " + names.face(fanFaces[k]) +
           "'s plane (the surface curves inward round it: by less than the "
           "tolerance at each edge, but more in all)");
    }
  if (winds != 1)
    fail("not convex at the point " + names.point(v) + ": the faces round it wind round it " + std::to_string(winds) +
         " times, not once");
}

}  // namespace

EdgeIndex::EdgeIndex(const Polyhedron& p, const SurfaceNames& names) {
  size_t count = 0;
  for (const auto& cycle : p.faces) count += cycle.size();
  uses_.reserve(count);
  for (size_t f = 0; f < p.faces.size(); ++f) {
    const auto& cycle = p.faces[f];
    for (size_t i = 0; i < cycle.size(); ++i) {
      const int a = cycle[i], b = cycle[next(i, cycle.size())];
      const auto [at, added] = uses_.emplace(key(a, b), Use{uint32_t(f), uint32_t(i)});
      if (!added)
        fail(names.face(at->second.face) + " and " + names.face(f) + " run the same way along the edge " +
             names.point(a) + " - " + names.point(b) + " (non-manifold, or wound inconsistently)");
    }
  }
}

const EdgeIndex::Use* EdgeIndex::find(int from, int to) const {
  const auto it = uses_.find(key(from, to));
  return it == uses_.end() ? nullptr : &it->second;
}

OffPlane worstOffPlane(const Polyhedron& p, size_t face) {
  const Eigen::Vector3d n = faceNormal(p, face), c = faceCentre(p, face);
  OffPlane worst;
  for (const int v : p.faces[face]) {
    const double off = std::abs(n.dot(p.vertices[size_t(v)] - c));
    if (worst.vertex < 0 || off > worst.distance) worst = {v, off};
  }
  return worst;
}

void checkClosed(const Polyhedron& p, const EdgeIndex& edges,
                 const std::function<std::string(int, int, size_t)>& openEdge) {
  for (size_t f = 0; f < p.faces.size(); ++f) {
    const auto& cycle = p.faces[f];
    for (size_t i = 0; i < cycle.size(); ++i)
      if (!edges.find(cycle[next(i, cycle.size())], cycle[i]))
        fail(openEdge(cycle[i], cycle[next(i, cycle.size())], f));
  }
}

void checkConnected(const Polyhedron& p, const EdgeIndex& edges, const SurfaceNames& names) {
  std::vector<bool> reached(p.faces.size(), false);
  std::vector<size_t> stack{0};
  reached[0] = true;
  size_t count = 1;
  while (!stack.empty()) {
    const size_t f = stack.back();
    stack.pop_back();
    for (size_t i = 0; i < p.faces[f].size(); ++i) {
      const size_t g = across(p, edges, f, i).face;
      if (reached[g]) continue;
      reached[g] = true;
      ++count;
      stack.push_back(g);
    }
  }
  if (count == p.faces.size()) return;
  size_t apart = 0;
  while (reached[apart]) ++apart;
  fail("the mesh is more than one piece: " + names.face(apart) + " is not joined to " + names.face(0) +
       " (a stage is one closed convex solid)");
}

void checkLocallyConvex(const Polyhedron& p, const EdgeIndex& edges, const std::vector<Eigen::Vector3d>& normals,
                        double tolerance, const SurfaceNames& names) {
  for (size_t f = 0; f < p.faces.size(); ++f) {
    const auto& cycle = p.faces[f];
    for (size_t i = 0; i < cycle.size(); ++i) {
      // The neighbour across u -> v runs v -> u; its corner after u is the first off the edge.
      const EdgeIndex::Use back = across(p, edges, f, i);
      const auto& other = p.faces[back.face];
      const int w = other[(back.corner + 2) % other.size()];
      const Eigen::Vector3d& u = p.vertices[size_t(cycle[i])];
      const double ahead = normals[f].dot(p.vertices[size_t(w)] - u);
      if (ahead > tolerance) {
        char amount[32];
        std::snprintf(amount, sizeof amount, "%.3g", ahead);
        fail("not convex: the point " + names.point(w) + " of " + names.face(back.face) + " lies " + amount +
             " in front of " + names.face(f) + "'s plane, across their edge " + names.point(cycle[i]) + " - " +
             names.point(cycle[next(i, cycle.size())]));
      }
    }
  }
  std::vector<int> outgoing(p.vertices.size(), 0);
  for (const auto& cycle : p.faces)
    for (const int v : cycle) ++outgoing[size_t(v)];
  std::vector<bool> done(p.vertices.size(), false);
  for (size_t f = 0; f < p.faces.size(); ++f)
    for (size_t i = 0; i < p.faces[f].size(); ++i) {
      const int v = p.faces[f][i];
      if (done[size_t(v)]) continue;
      done[size_t(v)] = true;
      checkFan(p, edges, normals, f, i, outgoing[size_t(v)], tolerance, names);
    }
}

}  // namespace platon::stage::detail
