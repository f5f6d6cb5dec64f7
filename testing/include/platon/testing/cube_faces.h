// A cube's six faces as map parts 0-5 of a world, `side` units square, each edge a warp to the
// face across it (counter-clockwise from outside; edge u->v of one face is v->u of its neighbour).
// The parts are left uninitialized: a test adds its lines and gravity, then initializes them.
#pragma once
#include "platon/physics/world.h"

namespace platon::testing {

inline void addCubeFaces(physics::World& world, int32_t side) {
  using physics::MapPartId;
  const physics::Vec2 c[4] = {{0, 0}, {side, 0}, {side, side}, {0, side}};
  const int faces[6][4] = {{5, 4, 6, 7}, {2, 0, 1, 3}, {6, 2, 3, 7}, {1, 0, 4, 5}, {3, 1, 5, 7}, {4, 0, 2, 6}};
  for (int f = 0; f < 6; ++f) world.createMapPart(static_cast<MapPartId>(f));
  for (int f = 0; f < 6; ++f)
    for (int i = 0; i < 4; ++i) {
      const int u = faces[f][i], v = faces[f][(i + 1) % 4];
      for (int g = 0; g < 6; ++g)
        for (int j = 0; j < 4; ++j)
          if (faces[g][j] == v && faces[g][(j + 1) % 4] == u)
            world.mapPart(static_cast<MapPartId>(f))
                .warp(c[i], c[(i + 1) % 4], static_cast<MapPartId>(g), c[(j + 1) % 4], c[j]);
    }
}

}  // namespace platon::testing
