// The checks that make a surface of polygon faces the boundary of a convex solid, each in time
// linear in its edges (a mesh of 10^5 triangles checks in milliseconds):
//
// - every directed edge is run by one face only, and the other way by exactly one other (closed,
//   manifold, consistently wound);
// - the faces are one connected piece;
// - across every edge the neighbouring face bends away (its corner after the edge lies behind this
//   face's plane, within the tolerance): locally convex at the edges;
// - the faces round every vertex make one fan that winds once round it (no bow-tie, no surface
//   that wraps round a point twice), and the far end of each of its edges lies behind each of its
//   faces' planes within the tolerance (inward bends under the tolerance at each edge must not
//   add up round a vertex into a dent).
//
// A closed connected surface that is locally convex at every edge and vertex is the boundary of a
// convex solid (its Gauss map covers the sphere once: Hadamard's theorem), so no vertex-against-
// every-face test is needed. Shared by validatePolyhedron (faces named "face N") and
// polyhedronFromMesh (faces are the file's triangles, named by their index in the file).
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "platon/stage/polyhedron.h"

namespace platon::stage::detail {

// Throws the StageError of a solid or a mesh, which has no place in a text file.
[[noreturn]] void fail(const std::string& reason);

// How messages name a face and a point of the surface being checked.
struct SurfaceNames {
  std::function<std::string(size_t face)> face;
  std::function<std::string(int vertex)> point;
};

// The face that runs each directed edge, and where in its cycle.
class EdgeIndex {
 public:
  struct Use {
    uint32_t face = 0, corner = 0;  // the edge runs from the face's corner `corner` to the next
  };
  // Throws StageError when two faces run one edge the same way (non-manifold or wound inconsistently).
  EdgeIndex(const Polyhedron& p, const SurfaceNames& names);
  const Use* find(int from, int to) const;

 private:
  static uint64_t key(int from, int to) { return (uint64_t(uint32_t(from)) << 32) | uint32_t(to); }
  std::unordered_map<uint64_t, Use> uses_;
};

// The corner of `face` farthest off the face's plane (through the mean of its corners, along its
// Newell normal), and how far: the one flatness test, for polygons and merged mesh faces alike.
struct OffPlane {
  int vertex = -1;
  double distance = 0;
};
OffPlane worstOffPlane(const Polyhedron& p, size_t face);

// Every edge has a face on its other side. `openEdge` says what is wrong with an edge that has
// none (the mesh builder names a T-junction there).
void checkClosed(const Polyhedron& p, const EdgeIndex& edges,
                 const std::function<std::string(int from, int to, size_t face)>& openEdge);

// The faces are one piece (joined across edges).
void checkConnected(const Polyhedron& p, const EdgeIndex& edges, const SurfaceNames& names);

// Across every edge the neighbour's next corner lies at most `tolerance` in front of the face's
// plane (`normals`: the faces' outward unit normals), and every vertex's fan winds round it once.
void checkLocallyConvex(const Polyhedron& p, const EdgeIndex& edges, const std::vector<Eigen::Vector3d>& normals,
                        double tolerance, const SurfaceNames& names);

// validatePolyhedron (polyhedron.h) naming faces and points as `names` do: the mesh builder checks
// the solid it merged so, in the file's triangles and coordinates.
void validatePolyhedron(const Polyhedron& p, double tolerance, const SurfaceNames& names);

}  // namespace platon::stage::detail
