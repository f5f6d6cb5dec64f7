// A triangle mesh as a mesh file holds it, and the convex solid it describes: coplanar
// triangles merged into polygon faces. The file reading (assimp) is a plugin (engine/mesh); this
// part is plain geometry so that it can be tested and fuzzed without a file.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "platon/stage/polyhedron.h"

namespace platon::stage {

struct MeshData {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<int, 3>> triangles;  // indices into positions
};

// The most triangles a mesh stage may have (a level gives every face a '%' line; the mesh plugin
// refuses bigger files before reading them whole), and the largest coordinate a mesh may hold.
inline constexpr size_t kMaxMeshTriangles = 100000;
inline constexpr double kMaxMeshCoordinate = 1e15;

// The convex polyhedron the mesh is the surface of, scaled so that its longest edge is
// `longestEdge` units and centred on the origin. Positions closer than 1e-6 of the mesh's size
// are one vertex (STL files repeat them per triangle); a mesh wound clockwise throughout is turned
// over. Coplanar neighbouring triangles become one face and corners on a straight edge are
// dropped. Throws StageError naming the file's triangle or a point for a mesh that is empty, too
// big, degenerate, open, non-manifold, inconsistently wound, in more than one piece or not convex.
// Linear in the triangles (give or take hashing): no point is tested against every plane.
Polyhedron polyhedronFromMesh(const MeshData& mesh, double longestEdge);

}  // namespace platon::stage
