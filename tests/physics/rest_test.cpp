// Rest that costs nothing (world.h, World::RestMode): a body at rest that nothing disturbs keeps its
// answer without testing again, and every world goes bit for bit as one that tests every body
// every frame. Proved over families of scenes that disturb resting bodies in every way the world
// allows: piles and stacks of random shapes on floors, slopes and one-way lines, warp edges to a
// second part, moving platforms started and stopped, walkers pushing into piles, velocities,
// spins and gravity switches set on resting bodies, the parts' gravity turned, doors opened by
// the rules (refreshPierce) and the rules replaced, bodies inserted on top, erased and destroyed
// from under others, filters changed. Each scene runs three ways: kept (the default), tested every
// frame, and checked (kept and tested, each kept answer compared): the states are equal every
// frame and no kept answer is ever contradicted.
#include <random>

#include <gtest/gtest.h>

#include "platon/physics/world.h"
#include "platon/testing/random_shapes.h"

using namespace platon::physics;
using platon::testing::between;

namespace {

constexpr uint32_t kDoor = 7;

// Doors (lines tagged kDoor) pass while `open`.
struct DoorRules : Rules {
  bool open = false;
  bool pierce(EntityId, const LineRef& line) override {
    return line.kind == LineKind::Warp || (open && line.tag == kDoor);
  }
};

struct Outcome {
  std::vector<uint64_t> hashes;
  uint64_t kept = 0, mismatches = 0;
};

// One random scene of `seed`, run for `frames` in `mode`.
Outcome runScene(uint64_t seed, World::RestMode mode, int frames) {
  std::mt19937_64 r(seed);
  World world;
  world.setRestMode(mode);
  DoorRules rules, otherRules;
  world.setRules(&rules);
  // Part 1: a box with a floor, slopes and shelves; its right wall is a warp into part 2.
  MapPart& a = world.createMapPart(1);
  MapPart& b = world.createMapPart(2);
  a.line({-3000, 0}, {3000, 0});
  a.line({-3000, 4000}, {-3000, 0});
  a.warp({3000, 0}, {3000, 4000}, 2, {-3000, 0}, {-3000, 4000});
  a.line({3000, 4000}, {-3000, 4000});
  b.line({-3000, 0}, {3000, 0});
  b.warp({-3000, 4000}, {-3000, 0}, 1, {3000, 4000}, {3000, 0});
  b.line({3000, 0}, {3000, 4000});
  b.line({3000, 4000}, {-3000, 4000});
  for (MapPart* p : {&a, &b})
    for (int i = 0; i < 6; ++i) {
      const Vec2 s{between(r, -2700, 2700), between(r, 300, 3500)};
      const Vec2 e{s.x + between(r, -600, 600), s.y + between(r, -250, 250)};
      if (s == e) continue;
      const int kind = static_cast<int>(r() % 4);
      if (kind == 0)
        p->oneWay(s.x < e.x ? s : e, s.x < e.x ? e : s);
      else
        p->line(s, e, kind == 1 ? kDoor : 0);
    }
  a.setGravity({0, -between(r, 8000, 30000)});
  b.setGravity({between(r, -3000, 3000), -between(r, 8000, 30000)});
  a.initialize();
  b.initialize();
  const EntityFilter crate{1, 1, 0, true}, rock{1, 1, 0, false};
  std::vector<EntityId> ids;
  auto add = [&](MapPartId part, Vec2 at) {
    const EntityId id =
        world.createEntity(platon::testing::randomConvex(r, between(r, 20, 90), platon::testing::Turn::MaybeTurned));
    world.setFilter(id, r() % 2 ? crate : rock);
    try {
      world.insert(id, part, at, static_cast<Angle>(r() % 4 == 0 ? r() : 0));
      ids.push_back(id);
    } catch (const Error&) {
      world.destroyEntity(id);
    }
  };
  for (int i = 0; i < 40; ++i) add(r() % 3 ? 1 : 2, {between(r, -2800, 2800), between(r, 100, 3800)});
  for (int column = 0; column < 3; ++column)  // stacks
    for (int k = 0; k < 6; ++k) add(1, {-2000 + column * 900, 120 + k * 200});
  std::vector<PlatformId> platforms;
  for (int i = 0; i < 2; ++i) {
    const Vec2 c{between(r, -2500, 2500), between(r, 300, 3000)};
    const int32_t hw = between(r, 60, 300);
    try {
      platforms.push_back(world.createPlatform(
          1 + i, std::vector<PlatformLine>{{{{c.x - hw, c.y}, {c.x + hw, c.y}}, 0, LineKind::Solid}}));
    } catch (const Error&) {}
  }
  Outcome out;
  for (int f = 0; f < frames; ++f) {
    // The disturbances, each now and then (after a quiet start, so that bodies come to rest).
    const uint64_t roll = r() % 3000;  // about one disturbance in 50 frames
    if (f % 90 == 0)                   // platforms move in bursts
      for (const PlatformId p : platforms) world.setPlatformMotion(p, {0, 0});
    auto anyBody = [&]() -> std::optional<EntityId> {
      if (ids.empty()) return std::nullopt;
      const EntityId id = ids[r() % ids.size()];
      return world.valid(id) ? std::optional(id) : std::nullopt;
    };
    if (f > 120) {
      if (roll < 15) {
        if (auto id = anyBody()) world.setVelocity(*id, {between(r, -400000, 400000), between(r, 0, 600000)});
      } else if (roll < 20) {
        if (auto id = anyBody()) world.setGravityEnabled(*id, r() % 4 != 0);
      } else if (roll < 23) {
        if (auto id = anyBody()) world.setAngularVelocity(*id, r() % 2 ? 0 : between(r, -20000000, 20000000));
      } else if (roll < 28) {
        (r() % 2 ? a : b).setGravity({between(r, -6000, 6000), -between(r, 6000, 30000)});
      } else if (roll < 33 && !platforms.empty()) {
        world.setPlatformMotion(platforms[r() % platforms.size()],
                                r() % 3 ? Vec2{0, 0} : Vec2{between(r, -6, 6), between(r, -6, 6)});
      } else if (roll < 38) {
        rules.open = !rules.open;
        world.refreshPierce(kDoor);
      } else if (roll < 40) {
        world.setRules(r() % 2 ? &otherRules : &rules);
      } else if (roll < 46) {
        add(1, {between(r, -2800, 2800), between(r, 2000, 3900)});
      } else if (roll < 50) {
        if (auto id = anyBody()) {
          const EntityView v = world.entity(*id);
          if (v.inserted()) world.erase(*id, v.part());
        }
      } else if (roll < 53) {
        if (auto id = anyBody()) world.destroyEntity(*id);
      } else if (roll < 58) {
        if (auto id = anyBody()) {
          try {
            world.setFilter(*id, r() % 2 ? crate : rock);
          } catch (const Error&) {}
        }
      } else if (roll < 62) {
        if (auto id = anyBody()) world.setSubunit(*id, {between(r, -60000, 60000), between(r, -60000, 60000)});
      }
      if (f % 7 == 0 && f % 300 < 100 && ids.size() > 3 && world.valid(ids[3]))
        world.setVelocity(ids[3], {300000, 0});  // a walker, now and then
    }
    const SolveReport report = world.solve();
    out.kept += report.restsKept;
    out.mismatches += report.restMismatches;
    out.hashes.push_back(world.stateHash());
    EXPECT_EQ(world.countOverlaps(), 0u);
  }
  return out;
}

}  // namespace

TEST(Rest, AKeptAnswerIsNeverContradictedAndStatesMatchAWorldThatTestsEveryFrame) {
  std::mt19937_64 seeds(2025);
  uint64_t kept = 0;
  for (int scene = 0; scene < 12; ++scene) {
    const uint64_t seed = seeds();
    SCOPED_TRACE("scene seed " + std::to_string(seed));
    const Outcome keptRun = runScene(seed, World::RestMode::Kept, 1500);
    const Outcome tested = runScene(seed, World::RestMode::Tested, 1500);
    const Outcome checked = runScene(seed, World::RestMode::Checked, 1500);
    EXPECT_EQ(checked.mismatches, 0u);
    EXPECT_EQ(tested.kept, 0u);
    ASSERT_EQ(keptRun.hashes.size(), tested.hashes.size());
    for (size_t f = 0; f < tested.hashes.size(); ++f)
      ASSERT_EQ(keptRun.hashes[f], tested.hashes[f])
          << "frame " << f + 1 << " differs from a world that tests every body";
    EXPECT_EQ(checked.hashes, tested.hashes);
    kept += keptRun.kept;
  }
  EXPECT_GT(kept, 100000u) << "the scenes must rest a lot for this to prove anything";
  std::printf("[  STATS   ] %llu kept rest answers over 12 scenes of 1,500 frames, none contradicted\n",
              static_cast<unsigned long long>(kept));
}

// A body rests only touching what it is pressed into: one touching a ceiling (a fixed line, or a
// crate that cannot be pushed) while a unit above the floor falls that unit and rests on the floor.
// (Before, touching anything and within 1.5 units of a floor was rest: it hung there, and whether
// it hung by a crate above depended on whether the crate had stepped yet.) Random boxes and
// regular polygons, gaps of one unit, ceilings as lines and as crates.
TEST(Rest, ABodyTouchingOnlyACeilingFallsTheUnitToTheFloor) {
  std::mt19937_64 r(103);
  for (int trial = 0; trial < 200; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    part.line({-3000, 0}, {3000, 0});
    part.setGravity({0, -platon::testing::between(r, 2000, 40000)});
    const Convex shape = r() % 2
                             ? Convex::box(platon::testing::between(r, 5, 40), platon::testing::between(r, 5, 40))
                             : Convex::regular(platon::testing::between(r, 3, 9), platon::testing::between(r, 6, 40));
    int32_t bottom = INT32_MAX, top = INT32_MIN;
    for (const Vec2 v : shape.vertices()) bottom = std::min(bottom, v.y), top = std::max(top, v.y);
    const Vec2 at{0, 1 - bottom};  // one unit above the floor
    const bool lineCeiling = trial % 2 == 0;
    if (lineCeiling) part.line({300, at.y + top}, {-300, at.y + top});
    part.initialize();
    const EntityId body = world.createEntity(shape);
    world.setFilter(body, {1, 1, 0, true});
    world.insert(body, 1, at, 0);
    if (!lineCeiling) {  // a slab that cannot be pushed, floating on no gravity of its own
      const EntityId slab = world.createEntity(Convex::box(200, 10));
      world.setFilter(slab, {1, 1, 0, false});
      world.setGravityEnabled(slab, false);
      world.insert(slab, 1, {0, at.y + top + 10}, 0);
    }
    world.solve();
    world.solve();
    ASSERT_EQ(world.countOverlaps(), 0u) << "trial " << trial;
    EXPECT_EQ(world.entity(body).position().y, at.y - 1) << "trial " << trial << ": hung a unit above the floor";
  }
}
