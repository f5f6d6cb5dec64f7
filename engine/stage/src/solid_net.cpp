#include "platon/stage/solid_net.h"

#include <array>
#include <stdexcept>

namespace platon::stage {
namespace {

using physics::Vec2;

// Vertex cycles of each face, counter-clockwise seen from outside.
std::vector<std::vector<int>> faceCycles(SolidType type) {
  switch (type) {
    case SolidType::Tetrahedron:
      return {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
    case SolidType::Hexahedron:
      return {{5, 4, 6, 7}, {2, 0, 1, 3}, {6, 2, 3, 7}, {1, 0, 4, 5}, {3, 1, 5, 7}, {4, 0, 2, 6}};
    default:
      throw std::invalid_argument(
          "solid nets for the octahedron, icosahedron and dodecahedron come with the level loader");
  }
}

// A regular polygon with integer corners, first edge along +x from the origin.
std::vector<Vec2> regularFace(int sides, int32_t edge) {
  std::vector<Vec2> out{{0, 0}};
  physics::Vec2w position{0, 0};  // Q30
  for (int k = 0; k + 1 < sides; ++k) {
    const physics::Angle heading = static_cast<physics::Angle>((physics::i128{1} << 32) * k / sides);
    const physics::Rotation r = physics::rotationOf(heading);
    position = position + physics::Vec2w{r.c * edge, r.s * edge};
    out.push_back({static_cast<int32_t>(physics::roundDiv(position.x, physics::i128{1} << 30)),
                   static_cast<int32_t>(physics::roundDiv(position.y, physics::i128{1} << 30))});
  }
  return out;
}

}  // namespace

SolidNet buildSolidNet(physics::World& world, SolidType type, int32_t edgeLength, physics::MapPartId firstId) {
  const auto faces = faceCycles(type);
  SolidNet net{type, edgeLength, {}, {}};
  for (size_t f = 0; f < faces.size(); ++f) {
    net.parts.push_back(firstId + static_cast<physics::MapPartId>(f));
    net.corners.push_back(regularFace(static_cast<int>(faces[f].size()), edgeLength));
    world.createMapPart(net.parts.back());
  }
  // Edge u -> v of face F is edge v -> u of its neighbour G; t0 -> t1 runs u -> v in G's frame.
  for (size_t f = 0; f < faces.size(); ++f) {
    const auto& cycle = faces[f];
    for (size_t i = 0; i < cycle.size(); ++i) {
      const int u = cycle[i], v = cycle[(i + 1) % cycle.size()];
      for (size_t g = 0; g < faces.size(); ++g) {
        const auto& other = faces[g];
        for (size_t j = 0; j < other.size(); ++j) {
          if (other[j] != v || other[(j + 1) % other.size()] != u) continue;
          world.mapPart(net.parts[f])
              .warp(net.corners[f][i], net.corners[f][(i + 1) % cycle.size()], net.parts[g],
                    net.corners[g][(j + 1) % other.size()], net.corners[g][j]);
        }
      }
    }
  }
  return net;
}

}  // namespace platon::stage
