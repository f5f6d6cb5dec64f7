// Entities meeting entities: overlap events (pickups, hazards, enemies), solid contact (crates a
// player pushes, crates resting on crates), filters, and the invariant extended to solid pairs.
#include <array>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "platon/physics/world.h"
#include "platon/testing/random_shapes.h"

using namespace platon::physics;

namespace {

using platon::testing::between;
using platon::testing::randomConvex;
using platon::testing::Turn;

constexpr int64_t kUnit = 65536;
constexpr uint32_t kPlayer = 1, kCrate = 2, kCoin = 4, kEnemy = 8;

// Counts begin/over/end per (entity, other) pair, and solid contacts with entities.
struct Events : Rules {
  std::map<std::pair<uint32_t, uint32_t>, int> begins, ends, overs;
  int entityContacts = 0;
  static std::pair<uint32_t, uint32_t> key(const Contact& c) {
    return {std::min(c.entity.index, c.other.index), std::max(c.entity.index, c.other.index)};
  }
  void beginContact(const Contact& c) override {
    if (c.other.isSet()) ++begins[key(c)];
  }
  void overContact(const Contact& c) override {
    if (c.other.isSet()) ++overs[key(c)];
  }
  void endContact(const Contact& c) override {
    if (c.other.isSet()) ++ends[key(c)];
  }
  void contact(const Contact& c, ContactResponse&) override { entityContacts += c.other.isSet(); }
};

struct Room {
  World world;
  MapPart* part;
  Room() {
    part = &world.createMapPart(1);
    part->line({-4000, 0}, {4000, 0});
    part->line({-4000, 0}, {-4000, 4000});
    part->line({4000, 4000}, {4000, 0});
  }
  EntityId add(const Convex& shape, Vec2 at, EntityFilter filter) {
    if (!part->initialized()) part->initialize();
    const EntityId id = world.createEntity(shape);
    world.setFilter(id, filter);
    world.insert(id, 1, at, 0);
    return id;
  }
};

}  // namespace

// A player crossing a coin in one frame (far faster than the coin is wide) still gets begin and end,
// in that order; one walking through it slowly gets begin, over on every frame inside, and end.
TEST(EntityOverlaps, FastAndSlowCrossingsBeginAndEnd) {
  for (const int64_t speed : {int64_t{300}, int64_t{3}}) {
    Room room;
    Events events;
    room.world.setRules(&events);
    room.part->setGravity({0, 0});
    const EntityId coin = room.add(Convex::box(5, 5), {0, 100}, {kCoin, 0, kPlayer});
    const EntityId player = room.add(Convex::box(10, 10), {-1000, 100}, {kPlayer, 0, 0});
    room.world.setVelocity(player, {speed * kUnit, 0});
    int inside = 0;
    for (int f = 0; f < 700; ++f) {
      room.world.solve();
      const int32_t x = room.world.entity(player).position().x;
      inside += x > -15 && x < 15;
    }
    const auto k = std::make_pair(std::min(coin.index, player.index), std::max(coin.index, player.index));
    EXPECT_EQ(events.begins[k], 1) << "speed " << speed;
    EXPECT_EQ(events.ends[k], 1) << "speed " << speed;
    EXPECT_EQ(events.overs[k], inside) << "speed " << speed;
  }
}

// Destroying an entity while something overlaps it ends the overlap; so does a filter change.
TEST(EntityOverlaps, DestroyingOrRefilteringEndsOverlaps) {
  Room room;
  Events events;
  room.world.setRules(&events);
  room.part->setGravity({0, 0});
  auto total = [](const std::map<std::pair<uint32_t, uint32_t>, int>& m) {
    int n = 0;
    for (const auto& [pair, count] : m) n += count;
    return n;
  };
  const EntityId player = room.add(Convex::box(10, 10), {0, 100}, {kPlayer, 0, 0});
  const EntityId coin = room.add(Convex::box(5, 5), {0, 100}, {kCoin, 0, kPlayer});
  EXPECT_EQ(total(events.begins), 1);
  room.world.destroyEntity(coin);
  EXPECT_EQ(total(events.ends), 1);
  const EntityId hazard = room.add(Convex::box(5, 5), {5, 100}, {kEnemy, 0, kPlayer});  // reuses the coin's slot
  EXPECT_EQ(total(events.begins), 2);
  room.world.setFilter(hazard, {kEnemy, 0, 0});  // no longer reports the player
  EXPECT_EQ(total(events.ends), 2);
  room.world.solve();
  EXPECT_EQ(total(events.overs), 0);
  (void)player;
}

// A player walking into a crate pushes it along the floor; the crate stops at a wall, and then so
// does the player. Nothing overlaps at any frame.
TEST(EntitySolids, APlayerPushesACrateUntilAWallStopsIt) {
  Room room;
  room.part->line({500, 0}, {500, 500});
  room.part->setGravity({0, -kUnit / 2});
  const EntityId crate = room.add(Convex::box(40, 40), {100, 40}, {kCrate, kPlayer | kCrate, 0, true});
  const EntityId player = room.add(Convex::box(15, 30), {-200, 30}, {kPlayer, kCrate, 0});
  for (int f = 0; f < 400; ++f) {
    room.world.setVelocity(player, {3 * kUnit, room.world.entity(player).velocity().y});
    room.world.solve();
    ASSERT_EQ(room.world.countOverlaps(), 0u) << "frame " << f;
  }
  EXPECT_EQ(room.world.entity(crate).position(), (Vec2{460, 40})) << "pushed to the wall";
  EXPECT_EQ(room.world.entity(player).position(), (Vec2{405, 30})) << "stopped by the crate";
  // The crate has no velocity of its own: pushed, it does not slide on when the push stops.
  EXPECT_EQ(room.world.entity(crate).velocity().x, 0);
}

// An unpushable entity (an enemy standing guard) stops the player like a wall; the player does not
// push it, and slides along its side.
TEST(EntitySolids, AnUnpushableEntityHoldsLikeAWall) {
  Room room;
  room.part->setGravity({0, -kUnit / 2});
  const EntityId guard = room.add(Convex::box(30, 30), {100, 30}, {kEnemy, kPlayer, 0, false});
  const EntityId player = room.add(Convex::box(10, 10), {0, 10}, {kPlayer, kEnemy, 0});
  for (int f = 0; f < 100; ++f) {
    room.world.setVelocity(player, {3 * kUnit, room.world.entity(player).velocity().y});
    room.world.solve();
  }
  EXPECT_EQ(room.world.entity(guard).position(), (Vec2{100, 30}));
  EXPECT_EQ(room.world.entity(player).position(), (Vec2{60, 10}));
  ASSERT_FALSE(room.world.entity(player).contacts().empty());
}

// Crates dropped on crates stack and come to rest exactly: a tower of eight stands still for
// 100,000 frames; the player standing on top rests too.
TEST(EntitySolids, StacksOfCratesRestExactly) {
  Room room;
  room.part->setGravity({0, -kUnit / 3});
  std::vector<EntityId> crates;
  for (int i = 0; i < 8; ++i)
    crates.push_back(room.add(Convex::box(30, 20), {i % 2 ? 7 : -7, 30 + 60 * i}, {kCrate, kCrate | kPlayer, 0, true}));
  const EntityId player = room.add(Convex::box(10, 15), {0, 600}, {kPlayer, kCrate, 0});
  for (int f = 0; f < 2000; ++f) room.world.solve();
  std::vector<Vec2> rest;
  for (const EntityId c : crates) rest.push_back(room.world.entity(c).position());
  const Vec2 playerRest = room.world.entity(player).position();
  for (int i = 0; i < 8; ++i) EXPECT_EQ(rest[i].y, 20 + 40 * i) << "crate " << i;
  EXPECT_EQ(playerRest.y, 8 * 40 + 15);
  for (int f = 0; f < 100000; ++f) room.world.solve();
  for (int i = 0; i < 8; ++i) EXPECT_EQ(room.world.entity(crates[i]).position(), rest[i]);
  EXPECT_EQ(room.world.entity(player).position(), playerRest);
  EXPECT_EQ(room.world.countOverlaps(), 0u);
}

// Inserting into, or refiltering onto, an entity it would be solid to is refused with the reason.
TEST(EntitySolids, OverlappingPlacementsAreRefused) {
  Room room;
  room.part->setGravity({0, 0});
  const EntityId crate = room.add(Convex::box(20, 20), {0, 100}, {kCrate, kPlayer, 0, true});
  const EntityId player = room.world.createEntity(Convex::box(10, 10));
  room.world.setFilter(player, {kPlayer, kCrate, 0});
  try {
    room.world.insert(player, 1, {5, 100}, 0);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("would overlap entity " + std::to_string(crate.index)), std::string::npos)
        << e.what();
  }
  room.world.setFilter(player, {kPlayer, 0, 0});
  room.world.insert(player, 1, {5, 100}, 0);  // passes through crates now
  try {
    room.world.setFilter(player, {kPlayer, kCrate, 0});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("would overlap entity"), std::string::npos) << e.what();
  }
  EXPECT_EQ(room.world.entity(player).filter().solidWith, 0u);
}

// A turn blocked by another entity stops there and reports it.
TEST(EntitySolids, RotationStopsAtAnotherEntity) {
  Room room;
  room.part->setGravity({0, 0});
  struct Touch : Rules {
    EntityId other;
    void touchContact(const Contact& c) override { other = c.other; }
  } rules;
  room.world.setRules(&rules);
  const EntityId post = room.add(Convex::box(5, 5), {0, 150}, {kEnemy, kCrate, 0});
  const EntityId plank = room.add(Convex::box(100, 4), {0, 100}, {kCrate, kEnemy, 0});
  EXPECT_FALSE(room.world.rotate(plank, kQuarterTurn));
  EXPECT_EQ(rules.other, post);
  EXPECT_EQ(room.world.countOverlaps(), 0u);
}

// Random families: random shapes with random filters (solid, pushable, overlap-reporting) moving,
// falling and being driven in random rooms. The invariant holds for lines and solid pairs on every
// frame, every begin has its end, and two runs give the same hash.
TEST(EntitySolids, RandomCrowdsNeverOverlapAndPairTheirEvents) {
  std::mt19937_64 rng(61);
  for (int trial = 0; trial < 30; ++trial) {
    auto run = [&](uint64_t seed, bool check) {
      std::mt19937_64 r(seed);
      Room room;
      Events events;
      room.world.setRules(&events);
      for (int i = 0; i < 20; ++i) {
        const Vec2 a{between(r, -3800, 3800), between(r, 100, 3800)};
        const Vec2 b{a.x + between(r, -500, 500), a.y + between(r, -200, 200)};
        if (a != b) room.part->line(a, b);
      }
      room.part->setGravity({between(r, -3000, 3000), -between(r, 4000, 40000)});
      std::vector<EntityId> ids;
      for (int i = 0; i < 40; ++i) {
        const uint32_t category = 1u << between(r, 0, 3);
        const EntityFilter filter{category, static_cast<uint32_t>(between(r, 0, 15)),
                                  static_cast<uint32_t>(between(r, 0, 15)), r() % 2 == 0};
        const Convex shape = randomConvex(r, between(r, 5, 60), Turn::Upright);
        for (int tries = 0; tries < 30; ++tries) {
          try {
            ids.push_back(room.add(shape, {between(r, -3700, 3700), between(r, 100, 3700)}, filter));
            room.world.setVelocity(ids.back(), {between(r, -8, 8) * kUnit, between(r, -8, 8) * kUnit});
            break;
          } catch (const Error&) {}
        }
      }
      for (int f = 0; f < 800; ++f) {
        if (f % 7 == 0 && !ids.empty()) {  // drive one, as a player would
          const EntityId id = ids[static_cast<size_t>(f / 7) % ids.size()];
          room.world.setVelocity(id, {between(r, -6, 6) * kUnit, room.world.entity(id).velocity().y});
        }
        room.world.solve();
        if (check && room.world.countOverlaps() != 0) {
          ADD_FAILURE() << "trial " << trial << ", frame " << f << ": overlap";
          break;
        }
      }
      if (check) {
        int open = 0;
        for (const auto& [pair, n] : events.begins) open += n - events.ends[pair];
        // Every begin without an end is a pair that still overlaps; over events come once a frame.
        int overlapping = 0;
        for (size_t i = 0; i < ids.size(); ++i)
          for (size_t j = i + 1; j < ids.size(); ++j) {
            const EntityView a = room.world.entity(ids[i]), b = room.world.entity(ids[j]);
            if (!overlapPair(a.filter(), b.filter())) continue;
            for (const InstanceView ia : a.instances())
              if (const auto ib = b.instanceIn(ia.part)) {
                std::vector<Vec2> va, vb;
                for (const Vec2 v : ia.shape) va.push_back({ia.position.x + v.x, ia.position.y + v.y});
                for (const Vec2 v : ib->shape) vb.push_back({ib->position.x + v.x, ib->position.y + v.y});
                overlapping += overlapsInterior(va, vb);
              }
          }
        EXPECT_EQ(open, overlapping) << "trial " << trial;
      }
      return room.world.stateHash();
    };
    const uint64_t seed = rng();
    EXPECT_EQ(run(seed, true), run(seed, false)) << "trial " << trial;
  }
}

// A crate of a random convex shape with a flat bottom and upright sides (its top is random): a row
// of them pushed along a floor meets side to side, and none is lifted onto another.
Convex uprightCrate(std::mt19937_64& r) {
  const int32_t w = between(r, 8, 40), h = between(r, 8, 40);
  std::vector<Vec2> points{{-w, -h}, {w, -h}, {w, between(r, 0, h)}, {-w, between(r, 0, h)}};
  for (int i = between(r, 0, 4); i > 0; --i) points.push_back({between(r, -w, w), between(r, 0, h)});
  return Convex(convexHull(points));
}

// The orders a scene's n bodies are made in: forward, backward and shuffled.
std::array<std::vector<size_t>, 3> handleOrders(size_t n, std::mt19937_64& r) {
  std::vector<size_t> forward(n);
  for (size_t k = 0; k < n; ++k) forward[k] = k;
  std::vector<size_t> shuffled = forward;
  std::shuffle(shuffled.begin(), shuffled.end(), r);
  return {forward, std::vector<size_t>(forward.rbegin(), forward.rend()), shuffled};
}

// A push chain meets every entity where that entity is this frame, whatever the handles' order: an
// entity a move meets (or a moving body's rest test finds holding it) that has not stepped yet steps
// first. Random families: a player walking into a row of none to four crates (boxes and random
// convex shapes, touching or a few units apart; none: the player right behind the guard), the
// row led by a guard that walks away (or stands) at its own speed, either way along the floor; the
// same scene made in three handle orders moves identically, frame by frame. (Without the rule, a
// later guard is met at its start-of-frame place: the chain stops short every other frame.)
TEST(EntitySolids, AChainSeesItsNeighboursWhereTheyAreThisFrameWhateverTheirHandleOrder) {
  std::mt19937_64 rng(83);
  int differentBefore = 0;  // scenes whose guard moves: the case the rule is for
  for (int trial = 0; trial < 60; ++trial) {
    const uint64_t seed = rng();
    struct Body {
      Convex shape;
      Vec2 at;
      EntityFilter filter;
      int64_t speedQ16;  // set every frame along the chain (0: none)
    };
    std::mt19937_64 r(seed);
    const int dir = r() % 2 ? 1 : -1;
    const int64_t gravity = between(r, 8000, 60000);
    std::vector<Body> bodies;
    const int32_t pw = between(r, 8, 30), ph = between(r, 8, 40);
    bodies.push_back({Convex::box(pw, ph),
                      {-1500 * dir, ph},
                      {kPlayer, kCrate | kEnemy, 0, false},
                      dir * int64_t{between(r, kUnit, 30 * kUnit)}});
    int32_t front = -1500 * dir + dir * pw;  // where the row so far ends
    const int crates = between(r, 0, 4);     // none: the player walks right behind the guard
    for (int i = 0; i <= crates; ++i) {
      const bool guard = i == crates;
      const Convex shape = r() % 2 ? Convex::box(between(r, 8, 40), between(r, 8, 40)) : uprightCrate(r);
      int32_t lo = INT32_MAX, hi = INT32_MIN, bottom = INT32_MAX;
      for (const Vec2 v : shape.vertices())
        lo = std::min(lo, v.x), hi = std::max(hi, v.x), bottom = std::min(bottom, v.y);
      const int32_t gap = between(r, 0, 1) ? 0 : between(r, 1, 20);
      const int32_t x = dir > 0 ? front + gap - lo : front - gap - hi;
      bodies.push_back({shape,
                        {x, -bottom},
                        guard ? EntityFilter{kEnemy, kCrate | kPlayer, 0, false}
                              : EntityFilter{kCrate, kPlayer | kCrate | kEnemy, 0, true},
                        guard ? dir * int64_t{between(r, 0, 20 * kUnit)} : 0});
      front = dir > 0 ? x + hi : x + lo;
    }
    auto run = [&](const std::vector<size_t>& order) {
      Room room;
      room.part->setGravity({0, -gravity});
      std::vector<EntityId> ids(bodies.size());
      for (const size_t k : order) ids[k] = room.add(bodies[k].shape, bodies[k].at, bodies[k].filter);
      std::vector<std::vector<Vec2>> path;
      for (int f = 0; f < 150; ++f) {
        for (size_t k = 0; k < bodies.size(); ++k)
          if (bodies[k].speedQ16 != 0)
            room.world.setVelocity(ids[k], {bodies[k].speedQ16, room.world.entity(ids[k]).velocity().y});
        room.world.solve();
        EXPECT_EQ(room.world.countOverlaps(), 0u) << "trial " << trial << ", frame " << f;
        std::vector<Vec2> at;
        for (const EntityId id : ids) at.push_back(room.world.entity(id).position());
        path.push_back(at);
      }
      return path;
    };
    const auto [forward, backward, shuffled] = handleOrders(bodies.size(), r);
    const auto a = run(forward), b = run(backward), c = run(shuffled);
    for (size_t f = 0; f < a.size(); ++f) {
      ASSERT_EQ(a[f], b[f]) << "trial " << trial << " (seed " << seed << "), frame " << f << ": forward vs backward";
      ASSERT_EQ(a[f], c[f]) << "trial " << trial << " (seed " << seed << "), frame " << f << ": forward vs shuffled";
    }
    differentBefore += bodies.back().speedQ16 != 0;
  }
  EXPECT_GE(differentBefore, 30);
}

// A body held by another that moves away by its own step falls (or moves on) in the same frame
// whatever the handles' order: a holder that has not stepped yet steps first, for a body at rest as
// for a moving one; a holder is what the body is pressed into (a crate that cannot be pushed on its
// head is none). Random families: towers of one to three crates (boxes, the top one maybe a
// random upright shape, at random offsets, a third of them not pushable) on a guard that stands a while and then walks
// off either way at its own speed; and, under gravity along the floor, a row of crates leaning on a guard that walks
// away along the gravity or into the row (a body waiting for its holder that the holder's move meets takes its step
// there, as it would have had it not stepped yet). The same scene made in three handle orders moves identically frame
// by frame (places, velocities, the normals of the contacts that hold each body), and so does it with every body's rest
// tested every frame (World::RestMode::Tested). Without the rule, a body at rest that steps before its holder sees it
// where it was and falls a frame late. Supports are flat: a body sliding down a slope into the guard that moves into it
// is the case of two bodies moving into each other, which no order of steps removes (docs/physics.md).
TEST(EntitySolids, ABodyHeldByAnotherThatMovesAwayMovesInTheSameFrameWhateverTheirHandleOrder) {
  std::mt19937_64 rng(89);
  int moved = 0;  // scenes whose guard moves away from what it holds
  for (int trial = 0; trial < 80; ++trial) {
    const uint64_t seed = rng();
    struct Body {
      Convex shape;
      Vec2 at;
      EntityFilter filter;
      Vec2w speedQ16;  // the guard's, set every frame from `start` on
    };
    std::mt19937_64 r(seed);
    const bool sideways = trial % 3 == 2;  // gravity along the floor, the row leaning on the guard
    const int dir = r() % 2 ? 1 : -1;
    const int64_t gravity = between(r, 8000, 60000);
    const int start = between(r, 0, 40);
    const EntityFilter guardFilter{kEnemy, kCrate, 0, false};
    // Crates pushable or not (one that is not holds the crate under it from above as well).
    auto crateFilter = [&] { return EntityFilter{kCrate, kCrate | kEnemy, 0, r() % 3 != 0}; };
    std::vector<Body> bodies;
    auto extent = [](const Convex& s, int32_t& x0, int32_t& x1, int32_t& y0, int32_t& y1) {
      x0 = y0 = INT32_MAX, x1 = y1 = INT32_MIN;
      for (const Vec2 v : s.vertices())
        x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
    };
    const int crates = between(r, 1, 3);
    if (!sideways) {
      const Convex guard = Convex::box(between(r, 15, 60), between(r, 8, 40));
      int32_t x0, x1, y0, y1;
      extent(guard, x0, x1, y0, y1);
      bodies.push_back({guard, {0, -y0}, guardFilter, {dir * int64_t{between(r, kUnit / 2, 20 * kUnit)}, 0}});
      int32_t top = -y0 + y1, lo = x0, hi = x1;  // the top so far, and the width of what is below
      for (int i = 0; i < crates; ++i) {
        // Flat tops where another stands (on a slope it would slide into the guard's way, and two
        // bodies moving into each other are the case no order removes); the top one any shape.
        const bool last = i == crates - 1;
        const Convex shape = last && r() % 2 ? uprightCrate(r) : Convex::box(between(r, 8, 40), between(r, 8, 40));
        int32_t c0, c1, d0, d1;
        extent(shape, c0, c1, d0, d1);
        const int32_t x = between(r, lo, hi), y = top + between(r, 1, 10) - d0;
        bodies.push_back({shape, {x, y}, crateFilter(), {}});
        top = y + d1, lo = x + c0, hi = x + c1;
      }
    } else {
      // Gravity towards -x: the guard stands at x = -2000, the row leans on its right side; the
      // guard walks away along the gravity, or into the row it holds (pushing it up the gravity).
      const Convex guard = Convex::box(between(r, 8, 40), between(r, 15, 60));
      int32_t x0, x1, y0, y1;
      extent(guard, x0, x1, y0, y1);
      const int64_t way = r() % 3 ? -1 : 1;
      bodies.push_back({guard, {-2000, -y0}, guardFilter, {way * between(r, kUnit / 2, 20 * kUnit), 0}});
      int32_t front = -2000 + x1;
      for (int i = 0; i < crates; ++i) {
        const Convex shape = Convex::box(between(r, 8, 40), between(r, 8, 40));
        int32_t c0, c1, d0, d1;
        extent(shape, c0, c1, d0, d1);
        const int32_t x = front + between(r, 0, 10) - c0;
        bodies.push_back({shape, {x, -d0}, crateFilter(), {}});
        front = x + c1;
      }
    }
    Vec2 guardFrom, guardTo;
    auto run = [&](const std::vector<size_t>& order, World::RestMode mode) {
      Room room;
      room.world.setRestMode(mode);
      room.part->setGravity(sideways ? Vec2w{-gravity, 0} : Vec2w{0, -gravity});
      std::vector<EntityId> ids(bodies.size());
      for (const size_t k : order) ids[k] = room.add(bodies[k].shape, bodies[k].at, bodies[k].filter);
      if (sideways) room.world.setGravityEnabled(ids[0], false);
      std::vector<std::string> path;  // per frame: each body's place, velocity and contacts' normals
      for (int f = 0; f < 160; ++f) {
        // The guard walks from `start` on; sideways, it floats (no gravity) and stands still till then.
        if (sideways) room.world.setVelocity(ids[0], f >= start ? bodies[0].speedQ16 : Vec2w{});
        if (!sideways && f >= start)
          room.world.setVelocity(ids[0], {bodies[0].speedQ16.x, room.world.entity(ids[0]).velocity().y});
        room.world.solve();
        EXPECT_EQ(room.world.countOverlaps(), 0u) << "trial " << trial << ", frame " << f;
        std::string at;
        for (const EntityId id : ids) {
          const EntityView e = room.world.entity(id);
          at += " (" + std::to_string(e.position().x) + ", " + std::to_string(e.position().y) + " v " +
                std::to_string(e.velocity().x) + ", " + std::to_string(e.velocity().y) + " n";
          // Its supports (what it is pressed onto): a neighbour only near it, not holding it, is a
          // contact or not as it steps before or after it.
          for (const Contact& c : e.contacts())
            if (sideways ? c.normal.x > 0 : c.normal.y > 0)
              at += " " + std::to_string(c.normal.x) + "," + std::to_string(c.normal.y);
          at += ")";
        }
        path.push_back(at);
        if (f == 0) guardFrom = room.world.entity(ids[0]).position();
        guardTo = room.world.entity(ids[0]).position();
      }
      return path;
    };
    const auto [forward, backward, shuffled] = handleOrders(bodies.size(), r);
    const auto a = run(forward, World::RestMode::Kept), b = run(backward, World::RestMode::Kept),
               c = run(shuffled, World::RestMode::Kept), d = run(backward, World::RestMode::Tested);
    for (size_t f = 0; f < a.size(); ++f) {
      ASSERT_EQ(a[f], b[f]) << "trial " << trial << " (seed " << seed << "), frame " << f
                            << ": forward vs backward; start " << start << (sideways ? ", sideways" : "")
                            << "; frame before" << (f > 0 ? a[f - 1] : "");
      ASSERT_EQ(a[f], c[f]) << "trial " << trial << " (seed " << seed << "), frame " << f << ": forward vs shuffled";
      ASSERT_EQ(a[f], d[f]) << "trial " << trial << " (seed " << seed << "), frame " << f
                            << ": kept rest vs every body tested every frame";
    }
    moved += guardFrom != guardTo;
  }
  EXPECT_GE(moved, 70);
}

// A body that jumps any way (up, up and sideways, nearly sideways) with a crate resting on its head
// lifts the crate (pushes it) and goes its way: its push goes along its contact with the crate, not
// along the floor it leaves, which it also touches at that instant. Random families of bodies and
// crates (boxes and regular polygons, the crate at random offsets). (Before, a jump with any
// sideways part pushed along the floor's normal, did not push at all, and slid along the floor
// nowhere: the body stood frozen with its velocity, frame after frame.)
TEST(EntitySolids, ABodyJumpingAnyWayWithACrateOnItsHeadLiftsIt) {
  std::mt19937_64 r(101);
  int jumps = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Room room;
    room.part->setGravity({0, -between(r, 8000, 60000)});
    const int32_t w = between(r, 20, 80), h = between(r, 10, 40);
    const EntityId body = room.add(Convex::box(w, h), {0, h}, {kPlayer, kCrate, 0, false});
    const Convex crate = r() % 2 ? Convex::box(between(r, 8, 40), between(r, 8, 30))
                                 : Convex::regular(between(r, 4, 8), between(r, 10, 30));
    int32_t bottom = INT32_MAX;
    for (const Vec2 v : crate.vertices()) bottom = std::min(bottom, v.y);
    const EntityId box = room.add(crate, {between(r, -w + 5, w - 5), 2 * h - bottom + between(r, 0, 3)},
                                  {kCrate, kCrate | kPlayer, 0, true});
    for (int f = 0; f < 20; ++f) room.world.solve();  // the crate settles on its head
    const Vec2 before = room.world.entity(body).position();
    const Vec2w jump{between(r, -8, 8) * kUnit + between(r, 0, kUnit), between(r, 3, 12) * kUnit};
    room.world.setVelocity(body, jump);
    room.world.solve();
    ASSERT_EQ(room.world.countOverlaps(), 0u) << "trial " << trial;
    const Vec2 after = room.world.entity(body).position();
    // Up by nearly its velocity (half a frame's gravity less, and a unit of rounding), sideways too.
    EXPECT_GE(after.y - before.y, jump.y / kUnit - 2) << "trial " << trial << ": jumped " << jump.x << "," << jump.y;
    EXPECT_LE(std::abs(after.x - before.x - jump.x / kUnit), 1)
        << "trial " << trial << ": jumped " << jump.x << "," << jump.y;
    EXPECT_GT(room.world.entity(box).position().y, 2 * h - bottom) << "trial " << trial << ": the crate was not lifted";
    ++jumps;
  }
  EXPECT_EQ(jumps, 300);
}
