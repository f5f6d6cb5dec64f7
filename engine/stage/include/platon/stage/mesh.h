// A triangle mesh as a mesh file holds it, and the convex solid it describes: coplanar
// triangles merged into polygon faces. The file reading (assimp) is a plugin (engine/mesh); this
// part is plain geometry so that it can be tested and fuzzed without a file.
#pragma once
#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "platon/stage/polyhedron.h"

namespace platon::stage {

struct MeshData {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<int, 3>> triangles;  // indices into positions
};

// The convex polyhedron the mesh is the surface of, scaled so that its longest edge is
// `longestEdge` units and centred on the origin. Positions closer than 1e-6 of the mesh's size
// are one vertex (STL files repeat them per triangle); a mesh wound clockwise throughout is turned
// over. Coplanar neighbouring triangles become one face and corners on a straight edge are
// dropped. Throws StageError naming the triangle or vertex for a mesh that is empty, degenerate,
// open, non-manifold, inconsistently wound or not convex.
Polyhedron polyhedronFromMesh(const MeshData& mesh, double longestEdge);

}  // namespace platon::stage
