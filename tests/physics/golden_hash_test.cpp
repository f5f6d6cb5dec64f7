// Golden state hashes: a spread of scenes (random maps and shapes, warps at many angles, rotation,
// rules that pierce and change velocities) stepped through the public API, their state hashes
// folded every 25 frames and compared with recorded values.
//
// Two uses. A refactoring that must not change behaviour keeps every value. And the same values in
// every build (Release, Debug, ASan+UBSan, gcc or clang) show that no result depends on the build.
// A change that is meant to change motion updates the table: run with PLATON_PRINT_GOLDEN=1 and
// say in the commit why the motion changed.
#include <cstdio>
#include <cstdlib>
#include <random>

#include <gtest/gtest.h>

#include "platon/physics/world.h"
#include "platon/testing/cube_faces.h"

using namespace platon::physics;

namespace {

constexpr int64_t kUnit = 65536;

struct Fold {
  uint64_t h = 1469598103934665603ull;
  void add(uint64_t v) { h = (h ^ v) * 1099511628211ull; }
};

// What the scenes did, so that the test shows they exercise contacts, warps and pierce events.
struct Activity {
  uint64_t hits = 0, warps = 0, pierceEvents = 0, cornerReturns = 0;
  void add(const SolveReport& r) {
    hits += r.hits, warps += r.warpsCreated, pierceEvents += r.pierceEvents, cornerReturns += r.cornerReturns;
  }
};
Activity activity;

int32_t in(std::mt19937_64& rng, int32_t lo, int32_t hi) {
  return lo + static_cast<int32_t>(rng() % static_cast<uint64_t>(hi - lo + 1));
}

Convex randomConvex(std::mt19937_64& rng, int32_t size) {
  for (;;) {
    std::vector<Vec2> points;
    const int n = 3 + static_cast<int>(rng() % 8);
    for (int i = 0; i < n; ++i) points.push_back({in(rng, -size, size), in(rng, -size, size)});
    std::vector<Vec2> hull = convexHull(points);
    if (hull.size() >= 3) return Convex(hull);
  }
}

// Rules that exercise every callback: lines tagged 7 pierce, a contact with a line tagged 3
// bounces (keeps its velocity, reversed across the normal), begin/end count into the hash.
class BouncyRules : public Rules {
 public:
  bool pierce(EntityId e, const LineRef& line) override { return line.tag == 7 || Rules::pierce(e, line); }
  void beginContact(const Contact& c) override { fold.add(0xb000 + c.line.index); }
  void endContact(const Contact& c) override { fold.add(0xe000 + c.line.index); }
  void contact(const Contact& c, ContactResponse& response) override {
    fold.add(static_cast<uint64_t>(c.fraction.scaledFloor(20)));
    if (c.line.tag != 3) return;
    response.removeNormalVelocity = false;
    response.slide = (c.line.index % 2) == 0;
  }
  void touchContact(const Contact& c) override { fold.add(0x7000 + c.line.index); }
  Fold fold;
};

uint64_t runRandomMap(uint64_t seed, bool withRules) {
  std::mt19937_64 rng(seed);
  World world;
  BouncyRules rules;
  if (withRules) world.setRules(&rules);
  MapPart& part = world.createMapPart(1);
  const int32_t h = 3000;
  part.line({-h, -h}, {h, -h});
  part.line({h, -h}, {h, h});
  part.line({h, h}, {-h, h});
  part.line({-h, h}, {-h, -h});
  for (int i = 0; i < 150; ++i) {
    const Vec2 a{in(rng, -h, h), in(rng, -h, h)};
    Vec2 b{in(rng, -h, h), in(rng, -h, h)};
    if (rng() % 3 == 0) b.y = a.y;
    if (rng() % 4 == 0) b = {a.x + in(rng, -30, 30), a.y + in(rng, -30, 30)};
    if (a != b) part.line(a, b, static_cast<uint32_t>(rng() % 9));
  }
  part.setGravity({in(rng, -20000, 20000), -30000});
  part.initialize();
  std::vector<EntityId> ids;
  for (int i = 0; i < 12; ++i) {
    const EntityId id = world.createEntity(randomConvex(rng, 10 + in(rng, 0, 60)));
    for (int tries = 0; tries < 60; ++tries) {
      try {
        world.insert(id, 1, {in(rng, -h, h), in(rng, -h, h)}, static_cast<Angle>(rng()));
        world.setVelocity(id, {in(rng, -40, 40) * kUnit + in(rng, 0, 65535), in(rng, -40, 40) * kUnit});
        if (i % 3 == 0) world.setAngularVelocity(id, in(rng, -30000000, 30000000));
        ids.push_back(id);
        break;
      } catch (const Error&) {}
    }
  }
  Fold fold;
  for (int f = 1; f <= 600; ++f) {
    activity.add(world.solve());
    if (f % 100 == 0 && !ids.empty()) {  // drive one entity, as a player would
      const EntityId id = ids[static_cast<size_t>(f / 100) % ids.size()];
      world.setVelocity(id, {in(rng, -20, 20) * kUnit, in(rng, 0, 30) * kUnit});
      (void)world.rotate(id, static_cast<Angle>(rng()));
    }
    if (f % 25 == 0) fold.add(world.stateHash());
  }
  fold.add(rules.fold.h);
  return fold.h;
}

uint64_t runWarpAngle(int64_t degrees, uint64_t seed) {
  std::mt19937_64 rng(seed * 1000 + static_cast<uint64_t>(degrees));
  World world;
  BouncyRules rules;
  world.setRules(&rules);
  MapPart& a = world.createMapPart(1);
  MapPart& b = world.createMapPart(2);
  const Rotation r = rotationOf(angleFromDegrees(degrees));
  auto turn = [&](Vec2 p) {
    const Vec2w q = rotateWide(r, wide(p));
    return Vec2{static_cast<int32_t>(q.x), static_cast<int32_t>(q.y)};
  };
  const Vec2 t0 = turn({6000, 0}), t1 = turn({6000, 6000});
  a.line({0, 0}, {6000, 0});
  a.line({6000, 6000}, {0, 6000});
  a.line({0, 6000}, {0, 0});
  a.warp({6000, 0}, {6000, 6000}, 2, t0, t1);
  b.warp(t1, t0, 1, {6000, 6000}, {6000, 0});
  const Vec2 far0 = turn({12000, 0}), far1 = turn({12000, 6000});
  b.line(t0, far0);
  b.line(far0, far1);
  b.line(far1, t1);
  for (int i = 0; i < 12; ++i) {
    const Vec2 p{6300 + in(rng, 0, 5000), 300 + in(rng, 0, 5400)};
    const Vec2 q{p.x + in(rng, -400, 400), p.y + in(rng, -400, 400)};
    if (p != q) b.line(turn(p), turn(q), static_cast<uint32_t>(rng() % 9));
    const Vec2 u{300 + in(rng, 0, 5000), 300 + in(rng, 0, 5400)};
    const Vec2 w{u.x + in(rng, -400, 400), u.y + in(rng, -400, 400)};
    if (u != w) a.line(u, w, static_cast<uint32_t>(rng() % 9));
  }
  a.setGravity({20000, 0});
  b.setGravity(rotateWide(r, {-20000, 0}));
  a.initialize();
  b.initialize();
  for (int i = 0; i < 5; ++i) {
    const EntityId id = world.createEntity(Convex::regular(3 + i, 40 + 20 * i));
    for (int tries = 0; tries < 50; ++tries) {
      try {
        world.insert(id, 1, {300 + in(rng, 0, 5400), 300 + in(rng, 0, 5400)}, static_cast<Angle>(rng()));
        world.setVelocity(id, {in(rng, -20, 60) * kUnit, in(rng, -30, 30) * kUnit});
        if (i == 2) world.setAngularVelocity(id, 5000000);
        break;
      } catch (const Error&) {}
    }
  }
  Fold fold;
  for (int f = 1; f <= 400; ++f) {
    activity.add(world.solve());
    if (f % 25 == 0) fold.add(world.stateHash());
  }
  fold.add(rules.fold.h);
  return fold.h;
}

// A cube's six faces joined edge to edge, entities rolling around it with their "down" changing.
uint64_t runCube(uint64_t seed) {
  std::mt19937_64 rng(seed);
  World world;
  const int32_t s = 2000;
  platon::testing::addCubeFaces(world, s);
  for (int f = 0; f < 6; ++f) {
    MapPart& part = world.mapPart(static_cast<MapPartId>(f));
    for (int i = 0; i < 6; ++i) {
      const Vec2 a{in(rng, 100, s - 100), in(rng, 100, s - 100)};
      const Vec2 b{a.x + in(rng, -500, 500), a.y + in(rng, -100, 100)};
      if (a != b) part.line(a, b);
    }
    part.setGravity({0, -12000});
    part.initialize();
  }
  std::vector<EntityId> ids;
  for (int i = 0; i < 6; ++i) {
    const EntityId id = world.createEntity(i % 2 ? Convex::regular(12, 40) : Convex::box(30, 20));
    for (int tries = 0; tries < 50; ++tries) {
      try {
        world.insert(id, static_cast<MapPartId>(i), {in(rng, 100, s - 100), in(rng, 100, s - 100)}, 0);
        ids.push_back(id);
        break;
      } catch (const Error&) {}
    }
  }
  Fold fold;
  for (int f = 1; f <= 1500; ++f) {
    for (size_t k = 0; k < ids.size(); ++k) {  // keep them moving along their face's x axis
      const int64_t vy = world.entity(ids[k]).velocity().y;
      if (f % 60 == static_cast<int>(k))
        world.setVelocity(ids[k], {(f / 300 + static_cast<int>(k)) % 2 ? 20 * kUnit : -20 * kUnit, vy + 10 * kUnit});
    }
    activity.add(world.solve());
    if (f % 25 == 0) fold.add(world.stateHash());
  }
  return fold.h;
}

struct Golden {
  const char* name;
  uint64_t (*run)();
  uint64_t expected;
};

const Golden kGolden[] = {
    // Warps and cubes recorded again when the anchor's face was judged by its shape's centre and a
    // copy that becomes the anchor went to its exact place (warp 252: 0x6089aa2ccc7fb7e2, cube 1:
    // 0x5eb35441f09d6bea before).
    {"random map 1", [] { return runRandomMap(1, false); }, 0xbc66e49b76b9a8f6ull},
    {"random map 2", [] { return runRandomMap(2, false); }, 0x33ff356694a748a9ull},
    {"random map 3 + rules", [] { return runRandomMap(3, true); }, 0x62a5fa87642c095bull},
    {"random map 4 + rules", [] { return runRandomMap(4, true); }, 0x10a8994a470e870dull},
    {"warp 252 degrees", [] { return runWarpAngle(252, 1); }, 0xe99c35c86fcfeb1bull},
    {"warp 120 degrees", [] { return runWarpAngle(120, 2); }, 0x868abcda8be58904ull},
    {"warp 144 degrees", [] { return runWarpAngle(144, 3); }, 0xfeac5c97e8e73094ull},
    {"warp 90 degrees", [] { return runWarpAngle(90, 4); }, 0x1c88f3a418247fe4ull},
    {"warp 37 degrees", [] { return runWarpAngle(37, 5); }, 0x67be40f3689acde0ull},
    // Recorded again when the world learnt faces (closed warp loops): bodies that went through a
    // cube's corners had left every face (0x62ed7e2e04d5b99e, 0x2ef9d555a1dc3f68 before). Again
    // when a body put back by a corner got the overlaps of its new place and room for the next
    // frame's motion (0x76ef9fb9be77e6c7, 0xf9d3916b9c36e9ca before; 221 corner returns, now 7).
    // Cube 1 again when a body through a vertex went on over the faces round it instead of being
    // put back by the corner (0x31dfc89e3fd54cb3 before; 7 corner returns, now 1), and when a copy
    // held off its place by a wall closed the gap as far as the way was free (0x81816b803f827bde).
    {"cube 1", [] { return runCube(1); }, 0xf69f2d328adffd58ull},
    {"cube 2", [] { return runCube(2); }, 0xeb68d7e3d185a66aull},
};

}  // namespace

TEST(GoldenHash, EveryBuildAndEveryRefactoringGivesTheRecordedMotion) {
  const bool print = std::getenv("PLATON_PRINT_GOLDEN") != nullptr;
  for (const Golden& g : kGolden) {
    const uint64_t got = g.run();
    if (print) std::printf("    {\"%s\", ..., 0x%016llxull},\n", g.name, static_cast<unsigned long long>(got));
    EXPECT_EQ(got, g.expected) << g.name;
  }
  EXPECT_GT(activity.hits, 10000u);
  EXPECT_GT(activity.warps, 100u);
  EXPECT_GT(activity.pierceEvents, 1000u);
  std::printf("golden scenes: %llu hits, %llu warps created, %llu pierce events, %llu corner returns\n",
              static_cast<unsigned long long>(activity.hits), static_cast<unsigned long long>(activity.warps),
              static_cast<unsigned long long>(activity.pierceEvents),
              static_cast<unsigned long long>(activity.cornerReturns));
}
