// Joints and creases over families of shapes, angles, speeds and gravities:
//  - a body slides over a joint between collinear lines exactly as over one line, whatever touches
//    the joint (a flat side or a vertex);
//  - over convex and concave bends it never stalls;
//  - pressed into a corner or a valley of any angle, tilt and gravity, it settles within a few
//    frames and then stays exactly still, and it can still walk or jump out.
#include <cmath>
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

// The point at `length` units from `from` in direction `angle`, rounded.
Vec2 along(Vec2 from, Angle angle, int64_t length) {
  const Rotation r = rotationOf(angle);
  return {from.x + static_cast<int32_t>(roundDiv(i128{r.c} * length, i128{1} << 30)),
          from.y + static_cast<int32_t>(roundDiv(i128{r.s} * length, i128{1} << 30))};
}

// Inserts somewhere above the line y = floorY (in a frame where the floor is the x axis) that is
// free; returns false if no place was found.
bool insertAbove(World& world, EntityId id, MapPartId part, Vec2 at, Angle angle) {
  for (int lift = 0; lift < 400; lift += 2) {
    try {
      world.insert(id, part, {at.x, at.y + lift}, angle);
      return true;
    } catch (const Error&) {}
  }
  return false;
}

}  // namespace

// A floor along an exact integer direction, once as one segment and once cut into pieces at
// random points of the same line: every shape, speed and tilt moves identically on both, frame by
// frame, driven every frame (a player walking) or pushed once (a slide).
TEST(Joints, ACollinearChainIsExactlyOneLine) {
  std::mt19937_64 rng(11);
  int cases = 0, vertexFirst = 0;
  for (int trial = 0; trial < 240; ++trial) {
    // Direction (dx, dy) with a slope of at most about 30 degrees either way; the body slides along it.
    const int32_t dx = between(rng, 3, 40), dy = between(rng, -dx / 2, dx / 2);
    const int32_t pieces = between(rng, 2, 40), steps = 2000 / dx + 4;
    const Convex shape = randomConvex(rng, between(rng, 3, 40), Turn::MaybeTurned);
    const bool driven = rng() % 2;
    const int64_t speed = between(rng, kUnit / 4, 12 * kUnit);
    const Vec2w gravity{0, -between(rng, 2000, 2 * kUnit)};
    std::vector<int32_t> cuts{0, steps};
    for (int k = 0; k < pieces; ++k) cuts.push_back(between(rng, 1, steps - 1));
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    const Vec2 origin{-1000, 500};
    auto point = [&](int32_t k) { return Vec2{origin.x + k * dx, origin.y + k * dy}; };

    World one, chain;
    MapPart& a = one.createMapPart(1);
    MapPart& b = chain.createMapPart(1);
    a.line(point(0), point(steps));
    for (size_t k = 0; k + 1 < cuts.size(); ++k) b.line(point(cuts[k]), point(cuts[k + 1]));
    for (MapPart* p : {&a, &b}) {
      p->setGravity(gravity);
      p->initialize();
    }
    // Start resting on the line, a little in from its start.
    const Vec2 start = point(2);
    const EntityId ea = one.createEntity(shape), eb = chain.createEntity(shape);
    if (!insertAbove(one, ea, 1, {start.x, start.y + 1}, 0) || !insertAbove(chain, eb, 1, one.entity(ea).position(), 0))
      continue;
    ASSERT_EQ(one.entity(ea).position(), chain.entity(eb).position());
    int lowestVertex = 0;
    for (int v = 1; v < shape.size(); ++v)
      if (shape.vertices()[v].y < shape.vertices()[lowestVertex].y) lowestVertex = v;
    const int n = shape.size();
    vertexFirst += shape.vertices()[(lowestVertex + 1) % n].y != shape.vertices()[lowestVertex].y &&
                   shape.vertices()[(lowestVertex + n - 1) % n].y != shape.vertices()[lowestVertex].y;
    ++cases;
    one.setVelocity(ea, {speed, 0});
    chain.setVelocity(eb, {speed, 0});
    for (int f = 1; f <= 250; ++f) {
      if (driven) {
        one.setVelocity(ea, {speed, one.entity(ea).velocity().y});
        chain.setVelocity(eb, {speed, chain.entity(eb).velocity().y});
      }
      one.solve();
      chain.solve();
      ASSERT_EQ(one.entity(ea).position(), chain.entity(eb).position())
          << "trial " << trial << ", frame " << f << ": direction (" << dx << ", " << dy << "), " << pieces
          << " cuts, speed " << speed << (driven ? " driven" : " once");
      ASSERT_EQ(one.entity(ea).velocity(), chain.entity(eb).velocity()) << "trial " << trial << ", frame " << f;
    }
    ASSERT_EQ(chain.countOverlaps(), 0u);
  }
  EXPECT_GT(cases, 200);
  EXPECT_GT(vertexFirst, 60) << "the family must include bodies that meet the joints with a vertex";
}

// The example: a triangle standing on its tip walks over the joint of a floor of two
// pieces, driven one unit a frame, and with its velocity set only once.
TEST(Joints, ATriangleOnItsTipWalksOverAJoint) {
  for (const bool driven : {true, false}) {
    World world;
    MapPart& part = world.createMapPart(1);
    part.line({0, 0}, {100, 0});
    part.line({100, 0}, {200, 0});
    part.setGravity({0, -65536});
    part.initialize();
    const EntityId t = world.createEntity(Convex({{0, 0}, {3, 5}, {-3, 5}}));
    world.insert(t, 1, {50, 0}, 0);
    world.setVelocity(t, {3 * kUnit, 0});
    for (int f = 1; f <= 40; ++f) {
      if (driven) world.setVelocity(t, {kUnit, world.entity(t).velocity().y});
      world.solve();
      ASSERT_EQ(world.entity(t).position(), (Vec2{50 + (driven ? 1 : 3) * f, 0})) << "frame " << f;
    }
  }
}

// Floors that bend at their joints, convex (a hill) or concave (a valley), by up to 30 degrees at
// a time: a body driven along never stalls and reaches the far end.
// A box sliding along a floor meets a rise inside a frame: it keeps the velocity along the rise it
// met it with, v cos(a), and from that moment gravity slows it by g sin(a). Exactly: the part of
// the frame before the contact counts as floor (no slowing), the rest as rise. Rises of 5 to 60
// degrees, random speeds, gravities, box sizes and contact times.
TEST(Slides, ARiseMetInsideAFrameSlowsFromThatMomentOn) {
  std::mt19937_64 rng(41);
  for (int trial = 0; trial < 300; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    const double a = between(rng, 5, 60) * M_PI / 180;
    const int32_t kinkX = between(rng, 300, 900), half = between(rng, 5, 40);
    part.line({-2000, 0}, {kinkX, 0});
    part.line({kinkX, 0}, {kinkX + static_cast<int32_t>(std::lround(40000 * std::cos(a))),
                           static_cast<int32_t>(std::lround(40000 * std::sin(a)))});
    const int64_t g = between(rng, 2000, 40000);
    part.setGravity({0, -g});
    part.initialize();
    const EntityId box = world.createEntity(Convex::box(half, half));
    world.insert(box, 1, {0, half}, 0);
    const int64_t v = between(rng, 8 * kUnit, 40 * kUnit) + between(rng, 0, kUnit);
    world.setVelocity(box, {v, 0});
    // The exact answer, in units and frames: the front corner reaches the rise at t0.
    const double speed = static_cast<double>(v) / kUnit, gu = static_cast<double>(g) / kUnit;
    const double t0 = (kinkX - half) / speed;
    // The rise's line through whole units is a little off the exact angle: use the line as drawn.
    const Segment rise = world.mapPart(1).segments()[1];
    const double dx = rise.b.x - rise.a.x, dy = rise.b.y - rise.a.y, len = std::hypot(dx, dy);
    const double cd = dx / len, sd = dy / len;
    const int frames = static_cast<int>(t0) + 12;
    for (int f = 1; f <= frames; ++f) world.solve();
    const double tau = frames - t0;
    const double expected = speed * cd - gu * sd * tau;  // along the rise, units per frame
    const Vec2w vel = world.entity(box).velocity();
    const double along = (static_cast<double>(vel.x) * cd + static_cast<double>(vel.y) * sd) / kUnit;
    // The contact's time is known to the whole-unit position, 1/speed of a frame (the remainder below
    // a unit is carried, not swept); each frame's projection rounds to 1/65536 unit per frame. Before
    // the fix, the slowing started a whole frame early or not at all: g sin(a) t0 off.
    EXPECT_NEAR(along, expected, gu * sd / speed + 2e-3) << "trial " << trial << " rise " << a * 180 / M_PI;
    ASSERT_EQ(world.countOverlaps(), 0u);
  }
}

// A body that lands moving slower sideways than a unit a frame keeps that sideways velocity: its
// whole-unit step may point straight into the floor, but its exact motion does not, so the landing
// is no crease. (It was: slow landings stopped dead.) Random shapes, flat and sloped floors.
TEST(Slides, ASlowLandingKeepsTheVelocityAlongTheFloor) {
  std::mt19937_64 rng(43);
  int cases = 0;
  for (int trial = 0; trial < 300; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    const int32_t rise = trial % 2 ? 0 : between(rng, -300, 300);
    part.line({-4000, -rise}, {4000, rise});
    const int64_t g = between(rng, 2000, 60000);
    part.setGravity({0, -g});
    part.initialize();
    const EntityId body = world.createEntity(randomConvex(rng, between(rng, 4, 40), Turn::MaybeTurned));
    if (!insertAbove(world, body, 1, {between(rng, -200, 200), between(rng, 350, 900)}, 0)) continue;
    ++cases;
    const int64_t vx = between(rng, -kUnit + 1, kUnit - 1);
    world.setVelocity(body, {vx, 0});
    bool landed = false;
    for (int f = 0; f < 2000 && !landed; ++f) {
      world.solve();
      landed = !world.entity(body).contacts().empty();
    }
    ASSERT_TRUE(landed) << "trial " << trial;
    // Along the floor it keeps what it had, plus what gravity gives along a slope.
    const Vec2w v = world.entity(body).velocity();
    if (rise == 0)
      EXPECT_EQ(v.x, vx) << "trial " << trial;
    else
      EXPECT_NE(v, (Vec2w{})) << "trial " << trial << ": stopped dead";
    ASSERT_EQ(world.countOverlaps(), 0u);
  }
  EXPECT_GT(cases, 250);
}

// Down a slope a body never stops, however slowly it starts and however weak the gravity: the
// remainder it carries along the line may round its whole-unit step straight into the line, which
// is no crease. (It was, at low resolutions and high frame rates: a 45 degree slope at 64 units/m
// and 240 Hz held a box for 20 frames at a time.)
TEST(Slides, ASlideDownASlopeNeverStops) {
  std::mt19937_64 rng(47);
  for (int trial = 0; trial < 200; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    // Half of them at exactly 45 degrees, where a step of (-1, -1) points straight into the line.
    const int32_t drop = trial % 2 ? 3000 : between(rng, 300, 3000);
    part.line({-3000, drop}, {3000, -drop});
    const int64_t g = between(rng, 200, 8000);
    part.setGravity({0, -g});
    part.initialize();
    const EntityId body = world.createEntity(Convex::box(between(rng, 4, 30), between(rng, 4, 30)));
    const int32_t x = between(rng, -1500, -500);
    if (!insertAbove(world, body, 1, {x, -x * drop / 3000}, 0)) continue;
    for (int f = 0; f < 600; ++f) {
      world.solve();
      if (f > 20 && !world.entity(body).contacts().empty()) {
        ASSERT_NE(world.entity(body).velocity(), (Vec2w{})) << "trial " << trial << " frame " << f;
      }
    }
    ASSERT_EQ(world.countOverlaps(), 0u);
  }
}

TEST(Joints, BendsNeverStallADrivenBody) {
  std::mt19937_64 rng(23);
  int cases = 0;
  for (int trial = 0; trial < 160; ++trial) {
    World world;
    MapPart& part = world.createMapPart(1);
    // A polyline of pieces 40-200 units long whose heading stays within 35 degrees of +x.
    std::vector<Vec2> points{{0, 0}};
    int64_t heading = 0;  // degrees
    for (int k = 0; k < 12; ++k) {
      heading = std::clamp<int64_t>(heading + between(rng, -30, 30), -35, 35);
      points.push_back(along(points.back(), angleFromDegrees(heading), between(rng, 40, 200)));
    }
    part.line({-400, points[0].y}, points[0]);
    for (size_t k = 0; k + 1 < points.size(); ++k) part.line(points[k], points[k + 1]);
    part.setGravity({0, -between(rng, 4000, kUnit)});
    part.initialize();
    const EntityId id = world.createEntity(randomConvex(rng, between(rng, 4, 25), Turn::MaybeTurned));
    if (!insertAbove(world, id, 1, {-200, 1}, 0)) continue;
    ++cases;
    const int64_t speed = between(rng, 2 * kUnit, 8 * kUnit);
    int32_t lastX = world.entity(id).position().x;
    int stalled = 0;
    for (int f = 1; f <= 3000 && world.entity(id).position().x < points.back().x - 60; ++f) {
      world.setVelocity(id, {speed, world.entity(id).velocity().y});
      world.solve();
      const int32_t x = world.entity(id).position().x;
      stalled = x > lastX ? 0 : stalled + 1;
      lastX = x;
      ASSERT_LT(stalled, 4) << "trial " << trial << ": stalled at x = " << x << ", frame " << f;
    }
    EXPECT_GE(world.entity(id).position().x, points.back().x - 60) << "trial " << trial;
    ASSERT_EQ(world.countOverlaps(), 0u);
  }
  EXPECT_GT(cases, 140);
}

namespace {

struct Crease {
  World world;
  EntityId body;
  Vec2w gravity;
};

// Two lines from an apex opening against gravity, half-angles alpha1 and alpha2 either side of
// straight up (against gravity), gravity tilted by `tilt` degrees; the body dropped in from above.
bool makeCrease(Crease& c, std::mt19937_64& rng, int64_t alpha1, int64_t alpha2, int64_t tilt, const Convex& shape) {
  MapPart& part = c.world.createMapPart(1);
  const Angle up = angleFromDegrees(90 + tilt);
  const Vec2 apex{between(rng, -5000, 5000), between(rng, -5000, 5000)};
  const int64_t length = 40000;
  part.line(apex, along(apex, static_cast<Angle>(up - angleFromDegrees(alpha1)), length));
  part.line(along(apex, static_cast<Angle>(up + angleFromDegrees(alpha2)), length), apex);
  const Rotation down = rotationOf(static_cast<Angle>(up + kHalfTurn));
  const int64_t g = between(rng, 3000, 2 * kUnit);
  c.gravity = {static_cast<int64_t>(roundDiv(i128{down.c} * g, i128{1} << 30)),
               static_cast<int64_t>(roundDiv(i128{down.s} * g, i128{1} << 30))};
  part.setGravity(c.gravity);
  part.initialize();
  c.body = c.world.createEntity(shape);
  for (int64_t d = 150; d < 30000; d += 150) {
    try {
      c.world.insert(c.body, 1, along(apex, up, d), static_cast<Angle>(rng()));
      return true;
    } catch (const Error&) {}
  }
  return false;
}

// Runs until the body has not moved for `quiet` frames (or `limit` frames pass); returns the frame
// of its last move, or -1 if it never settled (then `path` says where it went last).
int settle(Crease& c, int quiet, int limit, std::string* path = nullptr) {
  Vec2 last = c.world.entity(c.body).position();
  int lastMove = 0;
  for (int f = 1; f <= limit; ++f) {
    c.world.solve();
    const Vec2 p = c.world.entity(c.body).position();
    if (p != last) lastMove = f, last = p;
    if (f - lastMove >= quiet) return lastMove;
    if (path && f > limit - 12) *path += " " + toString(p);
  }
  return -1;
}

}  // namespace

// The example: perpendicular walls tilted by 36.87 degrees, a box dropped in. It settles and
// then does not move by a unit, or by a fraction of one, for a million frames.
TEST(Creases, ATiltedCornerHoldsABoxStillForAMillionFrames) {
  World world;
  MapPart& part = world.createMapPart(1);
  part.line({0, 0}, {60000, 80000});
  part.line({0, 0}, {-80000, 60000});
  part.setGravity({0, -65536});
  part.initialize();
  const EntityId box = world.createEntity(Convex::box(20, 10));
  world.insert(box, 1, {0, 500}, 0);
  for (int f = 0; f < 100; ++f) world.solve();
  const Vec2 rest = world.entity(box).position();
  for (int f = 0; f < 1000000; ++f) {
    world.solve();
    if (world.entity(box).position() != rest || world.entity(box).velocity() != Vec2w{})
      FAIL() << "moved at frame " << f;
  }
  EXPECT_EQ(world.entity(box).contacts().size(), 2u) << "it rests against both walls";
}

// Valleys and corners of every opening (20 to 170 degrees), asymmetric, tilted, with random shapes
// at random angles and gravities: the body settles within a few frames of reaching the bottom, then
// holds exactly still, and a jump or a walk takes it out again.
TEST(Creases, EveryCornerAndValleyHoldsStillAndLetsGo) {
  std::mt19937_64 rng(31);
  int cases = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int32_t alpha1 = between(rng, 10, 85), alpha2 = between(rng, 10, 85);
    const int32_t tilt = between(rng, -std::min(alpha1, alpha2) + 5, std::min(alpha1, alpha2) - 5);
    Crease c;
    if (!makeCrease(c, rng, alpha1, alpha2, tilt, randomConvex(rng, between(rng, 3, 50), Turn::MaybeTurned))) continue;
    ++cases;
    // Falling in takes a while (in a wide valley a frictionless body swings through the bottom many
    // times, losing speed at each pass); once it stops, it must stay stopped.
    const int lastMove = settle(c, 200, 20000);
    ASSERT_GE(lastMove, 0) << "trial " << trial << ": never settled (" << alpha1 << "/" << alpha2 << " tilt " << tilt
                           << ")";
    const Vec2 rest = c.world.entity(c.body).position();
    for (int f = 0; f < 20000; ++f) {
      c.world.solve();
      ASSERT_EQ(c.world.entity(c.body).position(), rest) << "trial " << trial << " moved again after " << f;
    }
    ASSERT_EQ(c.world.countOverlaps(), 0u);
    // Walk out: up along either line, faster than gravity pulls it back, every frame.
    for (const Segment& seg : c.world.mapPart(1).segments()) {
      const Vec2 apex = c.world.mapPart(1).segments()[0].a;
      const Vec2w away = seg.a == apex ? seg.b - seg.a : seg.a - seg.b;  // along the line, from the apex
      const double length = std::hypot(static_cast<double>(away.x), static_cast<double>(away.y));
      const double speed = 3.0 * std::hypot(static_cast<double>(c.gravity.x), static_cast<double>(c.gravity.y)) + kUnit;
      const Vec2w v{static_cast<int64_t>(static_cast<double>(away.x) / length * speed),
                    static_cast<int64_t>(static_cast<double>(away.y) / length * speed)};
      for (int f = 0; f < 10; ++f) {
        c.world.setVelocity(c.body, v);
        c.world.solve();
      }
      EXPECT_NE(c.world.entity(c.body).position(), rest) << "trial " << trial << ": could not walk out";
      ASSERT_EQ(c.world.countOverlaps(), 0u);
      // Back into the corner: a frictionless body swings through it, losing speed at each pass.
      ASSERT_GE(settle(c, 200, 20000), 0) << "trial " << trial << ": did not settle again";
    }
    // Jump out: a strong push against gravity moves it at once.
    const Vec2 settled = c.world.entity(c.body).position();
    c.world.setVelocity(c.body, {-c.gravity.x * 40, -c.gravity.y * 40});
    for (int f = 0; f < 3; ++f) c.world.solve();
    EXPECT_NE(c.world.entity(c.body).position(), settled) << "trial " << trial << ": could not jump out";
  }
  EXPECT_GT(cases, 250);
}

// How fast "settles" is: from the first frame a body is pressed into the corner (within 1.5 units
// of both lines, moving slower than one unit a frame) to its last move, for every opening, tilt and
// gravity, falling in from above. (In a wide valley it first swings through the corner, as a
// frictionless body does, losing speed at every pass; that swing is not counted, the test above
// waits for it.)
TEST(Creases, SettlingTakesAFewFramesOnceInTheCorner) {
  std::mt19937_64 rng(37);
  int worst = 0, cases = 0;
  std::string worstCase;
  for (int trial = 0; trial < 300; ++trial) {
    const int32_t alpha1 = between(rng, 10, 85), alpha2 = between(rng, 10, 85);
    const int32_t tilt = between(rng, -std::min(alpha1, alpha2) + 5, std::min(alpha1, alpha2) - 5);
    Crease c;
    if (!makeCrease(c, rng, alpha1, alpha2, tilt, randomConvex(rng, between(rng, 3, 50), Turn::MaybeTurned))) continue;
    // Within 1.5 units of both lines, slower than a quarter unit a frame, gravity pointing into both
    // (floating point is fine for telling when to start counting).
    auto pressed = [&] {
      const InstanceView inst = c.world.entity(c.body).instance(0);
      const Vec2w v = c.world.entity(c.body).velocity();
      const double wx = static_cast<double>(c.gravity.x), wy = static_cast<double>(c.gravity.y);
      if (std::hypot(static_cast<double>(v.x), static_cast<double>(v.y)) > static_cast<double>(kUnit) / 4) return false;
      std::vector<Vec2> poly;
      for (const Vec2 p : inst.shape) poly.push_back({inst.position.x + p.x, inst.position.y + p.y});
      for (const Segment& seg : c.world.mapPart(1).segments()) {
        // The distance between the polygon and the segment (they never overlap): the least of
        // vertex-to-segment and endpoint-to-edge distances.
        auto pointToSegment = [](double px, double py, Vec2 a, Vec2 b) {
          const double dx = b.x - a.x, dy = b.y - a.y;
          const double t = std::clamp(((px - a.x) * dx + (py - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
          return std::hypot(px - a.x - t * dx, py - a.y - t * dy);
        };
        double gap = 1e300;
        for (size_t k = 0; k < poly.size(); ++k) {
          gap = std::min(gap, pointToSegment(poly[k].x, poly[k].y, seg.a, seg.b));
          for (const Vec2 e : {seg.a, seg.b})
            gap = std::min(gap, pointToSegment(e.x, e.y, poly[k], poly[(k + 1) % poly.size()]));
        }
        // The line's normal towards the body; w must point against it.
        const double dx = seg.b.x - seg.a.x, dy = seg.b.y - seg.a.y;
        const double side = (poly[0].x - seg.a.x) * -dy + (poly[0].y - seg.a.y) * dx;
        const double nx = side > 0 ? -dy : dy, ny = side > 0 ? dx : -dx;
        if (gap >= 1.5 || wx * nx + wy * ny >= 0) return false;
      }
      return true;
    };
    int since = -1, lastMove = 0;
    std::string pressedAt;
    Vec2 last = c.world.entity(c.body).position();
    for (int f = 1; f <= 4000; ++f) {
      c.world.solve();
      if (c.world.entity(c.body).position() != last) lastMove = f, last = c.world.entity(c.body).position();
      if (since < 0 && pressed()) {
        since = f;
        const EntityView e = c.world.entity(c.body);
        pressedAt = "frame " + std::to_string(f) + " at " + toString(e.position()) + " velocity (" +
                    std::to_string(e.velocity().x) + ", " + std::to_string(e.velocity().y) + ")";
      }
    }
    if (since < 0) continue;  // wedged above the apex by its own width: held by one line and a vertex
    ++cases;
    if (lastMove - since > worst) {
      worst = lastMove - since;
      worstCase = "trial " + std::to_string(trial) + " (" + std::to_string(alpha1) + "/" + std::to_string(alpha2) +
                  " tilt " + std::to_string(tilt) + ", gravity " + std::to_string(c.gravity.x) + ", " +
                  std::to_string(c.gravity.y) + "), pressed from " + pressedAt;
    }
  }
  EXPECT_GT(cases, 200);
  EXPECT_LE(worst, 20) << "frames from being pressed into the corner to the last move, worst: " << worstCase;
}
