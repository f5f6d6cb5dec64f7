// The faces of a Platonic solid as physics map parts: one part per face, in the face's own 2D
// frame, every edge a warp to the neighbouring face's copy of the same edge.
#pragma once
#include <vector>

#include "platon/physics/world.h"

namespace platon::stage {

enum class SolidType { Tetrahedron, Hexahedron, Octahedron, Icosahedron, Dodecahedron };

struct SolidNet {
  SolidType type;
  int32_t edgeLength = 0;
  std::vector<physics::MapPartId> parts;            // face i -> its map part
  std::vector<std::vector<physics::Vec2>> corners;  // face i's corners in its frame, counter-clockwise
};

// Creates the parts (ids firstId, firstId + 1, ...) with warp edges; the caller adds the level's
// lines and then calls initialize() on each part. Only the faces' vertex cycles are needed here:
// the 3D shape matters to the renderer, not to the physics.
SolidNet buildSolidNet(physics::World& world, SolidType type, int32_t edgeLength, physics::MapPartId firstId);

}  // namespace platon::stage
