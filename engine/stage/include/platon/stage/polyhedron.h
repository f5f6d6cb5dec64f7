// A convex polyhedron: the 3D solid a level is drawn on. Plain data; the five Platonic solids are
// built here and any convex mesh comes through mesh.h. Stages (stage.h) are made from it.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace platon::stage {

struct Polyhedron {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;  // vertex cycles, counter-clockwise seen from outside
};

enum class Solid { Tetrahedron, Hexahedron, Octahedron, Dodecahedron, Icosahedron };
inline constexpr Solid kSolids[] = {Solid::Tetrahedron, Solid::Hexahedron, Solid::Octahedron, Solid::Dodecahedron,
                                    Solid::Icosahedron};

// The level format's names: TETRAHEDRON, HEXAHEDRON, ...
std::string_view solidName(Solid solid);
std::optional<Solid> solidFromName(std::string_view name);
int faceCount(Solid solid);

// The solid with edges `edge` long, centred on the origin, turned so that one face looks along +z
// (toward the default camera) with one of its edges horizontal below its centre (docs/level-format.md).
Polyhedron platonicSolid(Solid solid, double edge);

// Checks that `p` is a closed convex polyhedron: at least four faces, each a planar convex polygon
// of three or more distinct corners, counter-clockwise from outside; every edge shared by exactly
// two faces running opposite ways; one connected piece; across every edge the neighbour bending
// away (its corner after the edge behind or on the face's plane) and every vertex's faces winding
// round it once, which together make the solid convex. Throws StageError naming the face, edge
// or vertex. `tolerance` is a length: how far off a plane a point may be and still count as on
// it. Two neighbouring faces may lie in one plane (within the tolerance): for a mesh, what is one
// face is polyhedronFromMesh's decision alone. Linear in the edges.
void validatePolyhedron(const Polyhedron& p, double tolerance);

// A length that scales with the solid: its bounding box's diagonal.
double sizeOf(const Polyhedron& p);

// The faces' outward unit normals (Newell's method: robust for any planar polygon).
Eigen::Vector3d faceNormal(const Polyhedron& p, size_t face);
// The mean of a face's corners.
Eigen::Vector3d faceCentre(const Polyhedron& p, size_t face);

}  // namespace platon::stage
