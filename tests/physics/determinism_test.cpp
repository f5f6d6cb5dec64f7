// Same inputs, same bits: two worlds stepped side by side hash alike; a one-unit change shows.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "platon/physics/world.h"

using namespace platon::physics;

namespace {
uint64_t runScene(int32_t nudge, int frames, bool inBulk = false) {
  World world;
  MapPart& a = world.createMapPart(1);
  MapPart& b = world.createMapPart(2);
  const std::vector<Segment> room{
      {{0, 0}, {4000, 0}}, {{0, 4000}, {0, 0}}, {{4000, 4000}, {0, 4000}}, {{1000, 0}, {1600, 700}}};
  if (inBulk)
    a.lines(room);
  else
    for (const Segment& s : room) a.line(s.a, s.b);
  a.warp({4000, 0}, {4000, 4000}, 2, {4000, 0}, {0, 0});
  b.warp({0, 0}, {4000, 0}, 1, {4000, 4000}, {4000, 0});
  b.line({4000, 0}, {4000, 4000});
  b.line({4000, 4000}, {0, 4000});
  b.line({0, 4000}, {0, 0});
  a.setGravity({0, -20000});
  b.setGravity({-20000, 0});
  a.initialize();
  b.initialize();
  std::mt19937_64 rng(42);
  for (int i = 0; i < 20; ++i) {
    const EntityId id = world.createEntity(Convex::regular(5 + i % 4, 30 + i));
    world.insert(id, 1, {200 + i * 180 + (i == 7 ? nudge : 0), 2000 + (i % 5) * 300}, 0);
    world.setVelocity(id, {static_cast<int64_t>(rng() % 800000) - 200000, static_cast<int64_t>(rng() % 400000)});
    world.setAngularVelocity(id, static_cast<int32_t>(rng() % 20000000));
  }
  for (int f = 0; f < frames; ++f) world.solve();
  EXPECT_EQ(world.countOverlaps(), 0u);
  return world.stateHash();
}
}  // namespace

TEST(Determinism, IdenticalRunsHashIdentically) {
  EXPECT_EQ(runScene(0, 600), runScene(0, 600));
  EXPECT_NE(runScene(0, 600), runScene(1, 600));
}

TEST(Determinism, LinesAddedInBulkAreTheSameLines) { EXPECT_EQ(runScene(0, 600, true), runScene(0, 600, false)); }
