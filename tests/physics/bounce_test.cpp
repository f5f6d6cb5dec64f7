// Bounces (ContactResponse::restitution): exact for constant gravity, scaled by the restitution,
// ending in rest, never overlapping, keeping their energy in closed rooms of any shape.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "platon/physics/world.h"
#include "platon/testing/random_shapes.h"

using namespace platon::physics;
using platon::testing::between;

namespace {

struct Bouncy : Rules {
  Fraction restitution{1, 1};
  int contacts = 0;
  void contact(const Contact&, ContactResponse& r) override {
    ++contacts;
    r.restitution = restitution;
  }
};

// When the body is highest between bounces (frames from the drop, where the exact velocity turns
// from up to down, interpolated between frames) and how high it gets there.
struct Apexes {
  std::vector<double> times;
  std::vector<int32_t> heights;
};

Apexes dropAndWatch(World& world, EntityId body, int frames) {
  Apexes out;
  int32_t top = 0;
  int64_t lastVy = 0;
  for (int f = 1; f <= frames; ++f) {
    world.solve();
    EXPECT_EQ(world.countOverlaps(), 0u);
    const int32_t y = world.entity(body).instance(0).position.y;
    const int64_t vy = world.entity(body).velocity().y;
    if (vy > 0 || lastVy > 0) top = std::max(top, y);
    if (lastVy > 0 && vy <= 0) {
      out.times.push_back(f - 1 + static_cast<double>(lastVy) / static_cast<double>(lastVy - vy));
      out.heights.push_back(top);
      top = 0;
    }
    lastVy = vy;
  }
  return out;
}

}  // namespace

// Dropped from rest, an elastic body comes back to its height at every bounce, and the k-th apex
// comes at 2 k sqrt(2 h / g) frames: nothing drifts, however the contact falls inside a frame.
TEST(Bounce, AnElasticDropReturnsToItsHeightOnTime) {
  std::mt19937_64 rng(0xb01);
  for (int trial = 0; trial < 200; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    part.line({-100000, 0}, {100000, 0});
    const int64_t g = between(rng, 3000, 300000);
    part.setGravity({0, -g});
    part.initialize();
    Bouncy rules;
    world.setRules(&rules);
    const int32_t half = between(rng, 2, 60), start = half + between(rng, 100, 30000);
    const EntityId body = world.createEntity(Convex::box(half, half));
    world.insert(body, 1, {0, start}, 0);
    const double fall = start - half, halfPeriod = std::sqrt(2 * fall / (static_cast<double>(g) / 65536));
    const Apexes apexes = dropAndWatch(world, body, static_cast<int>(41 * halfPeriod) + 4);
    ASSERT_GE(apexes.times.size(), 20u) << "trial " << trial;
    for (size_t k = 0; k < 20; ++k) {
      // A whole-unit position near the top, where the motion per frame is below a unit.
      EXPECT_NEAR(apexes.heights[k], start, 2 + static_cast<double>(g) / 65536 / 2)
          << "trial " << trial << " apex " << k;
      // The velocity is exact to 1/65536 unit per frame: the time to a small part of a frame.
      EXPECT_NEAR(apexes.times[k], 2 * static_cast<double>(k + 1) * halfPeriod, 0.05)
          << "trial " << trial << " apex " << k;
    }
  }
}

// With restitution e each apex is e^2 of the last above the floor, and the bouncing ends at rest.
TEST(Bounce, RestitutionScalesTheApexAndTheBodyComesToRest) {
  std::mt19937_64 rng(0xb02);
  for (int trial = 0; trial < 100; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    part.line({-100000, 0}, {100000, 0});
    const int64_t g = between(rng, 3000, 100000);
    part.setGravity({0, -g});
    part.initialize();
    Bouncy rules;
    rules.restitution = {between(rng, 3, 9), 10};
    world.setRules(&rules);
    const int32_t half = between(rng, 2, 30), start = half + between(rng, 5000, 30000);
    const EntityId body = world.createEntity(Convex::box(half, half));
    world.insert(body, 1, {0, start}, 0);
    // The bounces take 1 + 2e / (1 - e) times the first fall, in all.
    const double e = static_cast<double>(rules.restitution.num) / 10, e2 = e * e;
    const double firstFall = std::sqrt(2.0 * (start - half) / (static_cast<double>(g) / 65536));
    const Apexes apexes = dropAndWatch(world, body, static_cast<int>(firstFall * (1 + 2 * e / (1 - e))) + 200);
    double expected = start - half;
    for (size_t k = 0; k < apexes.heights.size() && expected > 200; ++k) {
      expected *= e2;
      EXPECT_NEAR(apexes.heights[k] - half, expected, 3 + 0.01 * expected) << "trial " << trial << " apex " << k;
    }
    EXPECT_EQ(world.entity(body).velocity(), (Vec2w{}))
        << "trial " << trial << " still bouncing " << g << " " << rules.restitution.num << " " << half << " " << start
        << " " << static_cast<int>(firstFall * (1 + 2 * e / (1 - e))) + 200;
    EXPECT_EQ(world.entity(body).instance(0).position.y, half);
  }
}

// Random convex bodies, upright or turned, bounce elastically in closed rooms of random sloped
// walls under gravity of random direction: never overlapping anything, and keeping their energy
// (|v|^2 / 2 - g . p) to within what rounding whole-unit positions costs.
TEST(Bounce, RandomBodiesInRandomRoomsKeepTheirEnergy) {
  std::mt19937_64 rng(0xb03);
  int bounces = 0;
  double worst = 0;
  for (int trial = 0; trial < 120; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    // A convex room: 5-9 corners on a circle of radius about 4000, jittered.
    const int corners = between(rng, 5, 9);
    std::vector<Vec2> room;
    for (int k = 0; k < corners; ++k) {
      const double a = 2 * M_PI * (k + between(rng, -200, 200) / 1000.0) / corners;
      room.push_back({static_cast<int32_t>(4000 * std::cos(a)), static_cast<int32_t>(4000 * std::sin(a))});
    }
    for (int k = 0; k < corners; ++k) part.line(room[k], room[(k + 1) % corners]);
    const Vec2w g{between(rng, -20000, 20000), -between(rng, 5000, 40000)};
    part.setGravity(g);
    part.initialize();
    Bouncy rules;
    world.setRules(&rules);
    const EntityId body =
        world.createEntity(platon::testing::randomConvex(rng, between(rng, 5, 60), platon::testing::Turn::MaybeTurned));
    world.insert(body, 1, {between(rng, -800, 800), between(rng, -800, 800)}, 0);
    world.setVelocity(body, {int64_t{between(rng, -30, 30)} * 65536, int64_t{between(rng, -30, 30)} * 65536});
    // Energy per unit mass, measured from the room's lowest point, so that it means the same at any
    // place and gravity.
    double lowest = 1e300;
    for (const Vec2 c : room)
      lowest = std::min(lowest, -(static_cast<double>(g.x) * c.x + static_cast<double>(g.y) * c.y) / 65536);
    auto energy = [&] {
      const Vec2w v = world.entity(body).velocity();
      const Vec2 p = world.entity(body).instance(0).position;
      const double vx = static_cast<double>(v.x) / 65536, vy = static_cast<double>(v.y) / 65536;
      return (vx * vx + vy * vy) / 2 - (static_cast<double>(g.x) * p.x + static_cast<double>(g.y) * p.y) / 65536 -
             lowest;
    };
    const double e0 = energy();
    for (int f = 0; f < 1500; ++f) {
      world.solve();
      ASSERT_EQ(world.countOverlaps(), 0u) << "trial " << trial << " frame " << f;
    }
    bounces += rules.contacts;
    // The energy moves by the rounding of the position (a unit times g) at each bounce, both ways.
    const double gLength = std::hypot(static_cast<double>(g.x), static_cast<double>(g.y)) / 65536;
    worst = std::max(worst, std::fabs(energy() - e0) / e0);
    EXPECT_NEAR(energy(), e0, 0.01 * e0 + 4 * gLength * std::sqrt(rules.contacts + 1.0))
        << "trial " << trial << " after " << rules.contacts << " bounces";
  }
  EXPECT_GT(bounces, 1000);
  std::printf("largest relative change of energy: %.3g\n", worst);
}

// Restitutions above one (up to the largest fraction) at the largest speeds, in rooms as wide as
// the world allows: the bounced velocity and the rest of the frame stay within what the world
// accepts (world_fuzz found the rest of the frame overflowing the sweep with 5/1), nothing overlaps
// and every body stays in the world. Under UBSan (tools/test's asan build) any overflow fails too.
TEST(Bounce, SuperElasticBouncesAtTheLargestSpeedsStayInRange) {
  std::mt19937_64 rng(0xb04);
  const Fraction restitutions[] = {{2, 1}, {5, 1}, {1'000'000'007, 3}, {INT64_MAX, 1}, {INT64_MAX, INT64_MAX - 1}};
  const int64_t limitQ16 = int64_t{kMaxMove} << 16;
  int contacts = 0;
  for (int trial = 0; trial < 60; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    const int corners = between(rng, 3, 9);
    const double radius = kCoordLimit * 1.41;  // corners outside the limit are clipped to it below
    std::vector<Vec2> room;
    for (int k = 0; k < corners; ++k) {
      const double a = 2 * M_PI * (k + between(rng, -200, 200) / 1000.0) / corners;
      auto clip = [](double v) { return static_cast<int32_t>(std::clamp<double>(v, -kCoordLimit, kCoordLimit)); };
      room.push_back({clip(radius * std::cos(a)), clip(radius * std::sin(a))});
    }
    for (int k = 0; k < corners; ++k)
      if (room[k] != room[(k + 1) % corners]) part.line(room[k], room[(k + 1) % corners]);
    if (rng() % 2) part.setGravity({between(rng, -40000, 40000), between(rng, -40000, 40000)});
    part.initialize();
    Bouncy rules;
    rules.restitution = restitutions[trial % std::size(restitutions)];
    world.setRules(&rules);
    const int size = between(rng, 1, 1 << 28);
    const EntityId body = world.createEntity(Convex::box(size, size));
    world.insert(body, 1, {between(rng, -1000, 1000), between(rng, -1000, 1000)}, 0);
    world.setVelocity(body,
                      {between(rng, 0, 1) ? limitQ16 : -limitQ16, limitQ16 / 65536 * between(rng, -65536, 65536)});
    for (int f = 0; f < 48; ++f) {
      world.solve();
      ASSERT_EQ(world.countOverlaps(), 0u) << "trial " << trial << " frame " << f;
      const Vec2w v = world.entity(body).velocity();
      ASSERT_LE(std::max(std::abs(v.x), std::abs(v.y)), limitQ16) << "trial " << trial << " frame " << f;
      ASSERT_TRUE(inRange(world.entity(body).instance(0).position));
    }
    contacts += rules.contacts;
  }
  EXPECT_GT(contacts, 100);
}
