// The invariant, by random trial: no instance ever overlaps the interior of a solid line, whatever
// the map, shapes, speeds, rotations and warps. Seeded, so any failure replays.
#include <random>

#include <gtest/gtest.h>

#include "platon/physics/world.h"

using namespace platon::physics;

namespace {

constexpr int64_t kUnit = 65536;

Convex randomConvex(std::mt19937_64& rng, int32_t size) {
  for (;;) {
    std::vector<Vec2> points;
    const int n = 3 + static_cast<int>(rng() % 8);
    for (int i = 0; i < n; ++i)
      points.push_back(
          {static_cast<int32_t>(rng() % (2 * size + 1)) - size, static_cast<int32_t>(rng() % (2 * size + 1)) - size});
    std::vector<Vec2> hull = convexHull(points);
    if (hull.size() >= 3) return Convex(hull);
  }
}

Vec2 randomPoint(std::mt19937_64& rng, int32_t half) {
  return {static_cast<int32_t>(rng() % (2 * half + 1)) - half, static_cast<int32_t>(rng() % (2 * half + 1)) - half};
}

void addRandomLines(std::mt19937_64& rng, MapPart& part, int count, int32_t half) {
  for (int i = 0; i < count; ++i) {
    const Vec2 a = randomPoint(rng, half);
    Vec2 b = randomPoint(rng, half);
    switch (rng() % 4) {  // bias towards the hard cases: axis lines, short lines, shared endpoints
      case 0:
        b.y = a.y;
        break;
      case 1:
        b = {a.x + static_cast<int32_t>(rng() % 21) - 10, a.y + static_cast<int32_t>(rng() % 21) - 10};
        break;
      case 2:
        if (!part.segments().empty()) b = part.segments().back().b;
        break;
      default:
        break;
    }
    if (a == b) continue;
    part.line(a, b);
  }
}

void box(MapPart& part, int32_t h) {
  part.line({-h, -h}, {h, -h});
  part.line({h, -h}, {h, h});
  part.line({h, h}, {-h, h});
  part.line({-h, h}, {-h, -h});
}

// Inserts an entity at a random free place; gives up quietly after a few tries.
bool insertSomewhere(std::mt19937_64& rng, World& world, EntityId id, MapPartId part, int32_t half) {
  for (int tries = 0; tries < 60; ++tries) {
    try {
      world.insert(id, part, randomPoint(rng, half), static_cast<Angle>(rng()));
      return true;
    } catch (const Error&) {}
  }
  return false;
}

Vec2w randomVelocity(std::mt19937_64& rng) {
  const int64_t scale = (rng() % 10 == 0) ? 5000 : 40;  // a few very fast ones
  return {static_cast<int64_t>(rng() % (2 * scale * kUnit)) - scale * kUnit,
          static_cast<int64_t>(rng() % (2 * scale * kUnit)) - scale * kUnit};
}

}  // namespace

TEST(WorldProperty, RandomMapsNeverOverlap) {
  const uint64_t seed = 20261121;
  int inserted = 0, frames = 0;
  for (int map = 0; map < 150; ++map) {
    std::mt19937_64 rng(seed + map);
    World world;
    MapPart& part = world.createMapPart(1);
    box(part, 4000);
    addRandomLines(rng, part, 40 + static_cast<int>(rng() % 60), 4000);
    part.setGravity({static_cast<int64_t>(rng() % 40000) - 20000, static_cast<int64_t>(rng() % 40000) - 20000});
    part.initialize();
    std::vector<EntityId> ids;
    for (int i = 0; i < 6; ++i) {
      const EntityId id = world.createEntity(randomConvex(rng, 5 + static_cast<int32_t>(rng() % 150)));
      if (!insertSomewhere(rng, world, id, 1, 3800)) continue;
      world.setVelocity(id, randomVelocity(rng));
      if (rng() % 3 == 0) world.setAngularVelocity(id, static_cast<int32_t>(rng() % 40000000) - 20000000);
      ids.push_back(id);
    }
    inserted += static_cast<int>(ids.size());
    for (int f = 0; f < 120; ++f) {
      if (f % 30 == 0)
        for (const EntityId id : ids) world.setVelocity(id, randomVelocity(rng));
      if (f % 40 == 20)
        for (const EntityId id : ids) {
          try {
            world.rotate(id, static_cast<Angle>(rng()));
          } catch (const Error&) {  // a sliver that cannot take that angle: refused, nothing changes
          }
        }
      world.solve();
      ++frames;
      ASSERT_EQ(world.countOverlaps(), 0u) << "seed " << seed + map << " frame " << f;
    }
  }
  EXPECT_GT(inserted, 500);
  RecordProperty("frames", frames);
}

// Four faces of a cube around one vertex region, edges warping into each other, random walls.
TEST(WorldProperty, RandomWarpingNeverOverlaps) {
  const uint64_t seed = 777;
  int crossings = 0;
  for (int map = 0; map < 60; ++map) {
    std::mt19937_64 rng(seed + map);
    World world;
    constexpr int32_t s = 2000;
    MapPart& a = world.createMapPart(1);
    MapPart& b = world.createMapPart(2);
    // Face 1 right edge = face 2 left edge (no turn); face 1 top edge = face 2 bottom (quarter turn).
    a.line({0, 0}, {s, 0});
    a.line({0, s}, {0, 0});
    a.warp({s, 0}, {s, s}, 2, {0, 0}, {0, s});
    a.warp({s, s}, {0, s}, 2, {s, 0}, {0, 0});
    b.warp({0, s}, {0, 0}, 1, {s, s}, {s, 0});
    b.warp({0, 0}, {s, 0}, 1, {0, s}, {s, s});
    b.line({s, 0}, {s, s});
    b.line({s, s}, {0, s});
    for (MapPart* p : {&a, &b}) {
      for (int i = 0; i < 15; ++i) {
        const Vec2 p0{static_cast<int32_t>(rng() % (s - 200)) + 100, static_cast<int32_t>(rng() % (s - 200)) + 100};
        const Vec2 p1{p0.x + static_cast<int32_t>(rng() % 601) - 300, p0.y + static_cast<int32_t>(rng() % 601) - 300};
        if (p0 != p1) p->line(p0, p1);
      }
      p->setGravity({static_cast<int64_t>(rng() % 30000) - 15000, static_cast<int64_t>(rng() % 30000) - 15000});
    }
    a.initialize();
    b.initialize();
    std::vector<EntityId> ids;
    for (int i = 0; i < 4; ++i) {
      const EntityId id = world.createEntity(randomConvex(rng, 10 + static_cast<int32_t>(rng() % 60)));
      for (int tries = 0; tries < 60; ++tries) {
        try {
          world.insert(
              id, 1, {static_cast<int32_t>(rng() % (s - 200)) + 100, static_cast<int32_t>(rng() % (s - 200)) + 100}, 0);
          ids.push_back(id);
          break;
        } catch (const Error&) {}
      }
    }
    for (int f = 0; f < 300; ++f) {
      if (f % 50 == 0)
        for (const EntityId id : ids) world.setVelocity(id, randomVelocity(rng));
      const SolveReport r = world.solve();
      crossings += static_cast<int>(r.warpsCreated);
      ASSERT_EQ(world.countOverlaps(), 0u) << "seed " << seed + map << " frame " << f;
      for (const EntityId id : ids) ASSERT_TRUE(world.entity(id).inserted());
    }
  }
  EXPECT_GT(crossings, 100);
}
