// Bodies crossing the edges of every solid: over every edge in both directions, at several speeds,
// angles and shapes, and back again to where they started; and thrown at every corner, where three
// or more faces meet, never leaving the faces.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "platon/stage/mesh.h"
#include "platon/stage/stage.h"
#include "platon/stage/stage_error.h"
#include "platon/testing/rng.h"
#include "random_mesh.h"

using namespace platon;
using physics::Vec2;

namespace {

constexpr int64_t kQ16 = 65536;

double length(Vec2 a, Vec2 b) { return std::hypot(double(b.x) - a.x, double(b.y) - a.y); }

struct Built {
  physics::World world;
  stage::Stage stage;
};

std::unique_ptr<Built> build(stage::Solid solid, int32_t edge, int64_t gravityQ16) {
  auto b = std::make_unique<Built>();
  b->stage = stage::platonicStage(solid, edge);
  stage::addStageToWorld(b->stage, b->world, 0);
  for (size_t f = 0; f < b->stage.faceCount(); ++f) {
    b->world.mapPart(b->stage.part(f)).setGravity({0, -gravityQ16});
    b->world.mapPart(b->stage.part(f)).initialize();
  }
  return b;
}

// How far `p` lies outside the convex polygon `corners` (0 inside).
double outside(const std::vector<Vec2>& corners, Vec2 p) {
  double worst = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
    const double ex = double(b.x) - a.x, ey = double(b.y) - a.y;
    const double right = (ex * (double(p.y) - a.y) - ey * (double(p.x) - a.x)) / std::hypot(ex, ey);
    worst = std::max(worst, -right);  // negative: to the right of a counter-clockwise edge
  }
  return worst;
}

// Where each copy of an entity puts its centre on the solid, in 3D: the mean of its vertices,
// mapped by its face's frame, and how far off its face that centre is. (A copy's centre is off
// its face half the time it straddles an edge, and off the face its plane goes on off the solid:
// a point `off` units off its face is mapped within 2 * off of where it is on the solid. Near a
// vertex the copies disagree: the faces there leave less than a full turn.)
struct OnSolid {
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  double off = 0;
};

std::vector<OnSolid> centresIn3d(const stage::Stage& stage, const physics::EntityView& e) {
  std::vector<OnSolid> out;
  for (const physics::InstanceView i : e.instances()) {
    double x = 0, y = 0;
    for (const Vec2 p : i.shape) x += p.x, y += p.y;
    const double n = double(i.shape.size());
    const stage::StageFace& face = stage.faces[i.part - stage.firstPart];
    const double cx = i.position.x + x / n, cy = i.position.y + y / n;
    out.push_back({face.toWorld(cx, cy), outside(face.corners, {static_cast<int32_t>(std::lround(cx)),
                                                                static_cast<int32_t>(std::lround(cy))})});
  }
  return out;
}

// The most a frame can move a body that starts it with velocity v0 on a face that pulls with g:
// its speed and the pull, and the rounding of two copies (each placed within 2 units of its exact
// place and lifted up to 3 at a seam), and a unit each for the centres' rounding.
double frameReach(physics::Vec2w v0, physics::Vec2w g) {
  return (std::hypot(double(v0.x), double(v0.y)) + std::hypot(double(g.x), double(g.y))) / kQ16 + 12;
}

// How much further than `allowed` (the frame's motion) an entity's centre went over the solid,
// judged by the copies whose centres are on their faces (to within the 4 units of rounding warps
// allow; when none is, the one least off): from the one that comes nearest, to the one it comes
// nearest to.
double jumpBeyond(const std::vector<OnSolid>& was, const std::vector<OnSolid>& now, double allowed) {
  auto onFace = [](const std::vector<OnSolid>& copies) {
    double least = 1e300;
    for (const OnSolid& c : copies) least = std::min(least, c.off);
    std::vector<OnSolid> out;
    for (const OnSolid& c : copies)
      if (c.off <= std::max(4.0, least)) out.push_back(c);
    return out;
  };
  double least = 1e300;
  for (const OnSolid& a : onFace(was))
    for (const OnSolid& b : onFace(now)) least = std::min(least, (b.at - a.at).norm() - 2 * (a.off + b.off));
  return least - allowed;
}

physics::Convex shapeNumber(int k) { return k == 0 ? physics::Convex::regular(12, 60) : physics::Convex::box(50, 80); }

// Over every edge of every solid (faces of 4,096 and of 2^24 units), from both faces (each face's every edge), at
// speeds 3, 17 and 61 units a frame, three headings, two places along the edge, a round body and a box (which meets the
// edge with a corner first); then the velocity reversed for as many frames: back where it started within 4 units
// (rounding at each warp: docs/level-format.md).
TEST(Crossing, EveryEdgeBothWaysAndBack) {
  int crossings = 0;
  double worstReturn = 0;
  for (const int32_t size : {4096, 1 << 24})  // a small face and the level format's largest
    for (const stage::Solid solid : stage::kSolids) {
      auto b = build(solid, size, 0);
      physics::World& world = b->world;
      for (size_t f = 0; f < b->stage.faceCount(); ++f) {
        const stage::StageFace& face = b->stage.faces[f];
        const size_t n = face.corners.size();
        for (size_t i = 0; i < n; ++i) {
          const Vec2 a = face.corners[i], c = face.corners[(i + 1) % n];
          const double ex = double(c.x) - a.x, ey = double(c.y) - a.y, len = std::hypot(ex, ey);
          const double ox = ey / len, oy = -ex / len;  // outward: right of the counter-clockwise edge
          for (const double along : {0.35, 0.6})
            for (const double heading : {-0.7, 0.0, 0.5})
              for (const int speed : {3, 17, 61})
                for (int shape = 0; shape < 2; ++shape) {
                  SCOPED_TRACE(std::string(stage::solidName(solid)) + " size " + std::to_string(size) + " face " +
                               std::to_string(f) + " edge " + std::to_string(i) + " along " + std::to_string(along) +
                               " heading " + std::to_string(heading) + " speed " + std::to_string(speed) + " shape " +
                               std::to_string(shape));
                  const Vec2 start{static_cast<int32_t>(std::lround(a.x + ex * along - ox * 300)),
                                   static_cast<int32_t>(std::lround(a.y + ey * along - oy * 300))};
                  const physics::EntityId body = world.createEntity(shapeNumber(shape));
                  world.insert(body, b->stage.part(f), start, 0);
                  const double vx = ox * std::cos(heading) - oy * std::sin(heading);
                  const double vy = ox * std::sin(heading) + oy * std::cos(heading);
                  world.setVelocity(body, {std::llround(vx * speed * kQ16), std::llround(vy * speed * kQ16)});
                  const physics::MapPartId target = b->stage.part(size_t(face.neighbours[i].face));
                  int frames = 0;
                  while (frames < 4000 &&
                         !(world.entity(body).instanceCount() == 1 && world.entity(body).part() == target)) {
                    world.solve();
                    ++frames;
                    ASSERT_TRUE(world.entity(body).inserted());
                  }
                  ASSERT_EQ(world.entity(body).part(), target) << "did not cross in " << frames << " frames";
                  const physics::Vec2w v = world.entity(body).velocity();
                  world.setVelocity(body, {-v.x, -v.y});
                  for (int k = 0; k < frames; ++k) world.solve();
                  const physics::EntityView e = world.entity(body);
                  ASSERT_EQ(e.part(), b->stage.part(f));
                  const double back = length(e.position(), start);
                  worstReturn = std::max(worstReturn, back);
                  EXPECT_LE(back, 4.0);
                  world.destroyEntity(body);
                  ++crossings;
                }
        }
      }
    }
  RecordProperty("crossings", crossings);
  std::printf("%d crossings, worst return %.2f units\n", crossings, worstReturn);
}

namespace {

// A random convex body: a regular polygon, a box, or the hull of random points, which may lie
// well away from the body's origin (a shape need not contain its origin).
physics::Convex randomBody(platon::testing::Rng& rng) {
  switch (rng.between(0, 3)) {
    case 0:
      return physics::Convex::regular(rng.between(3, 16), rng.between(20, 300));
    case 1:
      return physics::Convex::box(rng.between(10, 200), rng.between(10, 200));
    default:
      for (;;) {
        const int r = rng.between(20, 250), off = rng.between(0, 1) ? rng.between(-250, 250) : 0;
        std::vector<Vec2> points;
        for (int i = rng.between(3, 9); i > 0; --i)
          points.push_back({off + rng.between(-r, r), off / 2 + rng.between(-r, r)});
        std::vector<Vec2> hull = physics::convexHull(points);
        if (hull.size() >= 3) return physics::Convex(hull);
      }
  }
}

// The middle of an instance's shape and how far its farthest vertex lies from it.
std::pair<Vec2, double> centreAndReach(const physics::InstanceView& i) {
  double cx = 0, cy = 0;
  for (const Vec2 v : i.shape) cx += v.x, cy += v.y;
  cx /= double(i.shape.size()), cy /= double(i.shape.size());
  double reach = 0;
  for (const Vec2 v : i.shape) reach = std::max(reach, std::hypot(v.x - cx, v.y - cy));
  return {{static_cast<int32_t>(std::lround(i.position.x + cx)), static_cast<int32_t>(std::lround(i.position.y + cy))},
          reach};
}

// How far `p` lies inside the convex polygon `corners` (negative outside).
double depthInside(const std::vector<Vec2>& corners, Vec2 p) {
  double depth = 1e18;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
    const double ex = double(b.x) - a.x, ey = double(b.y) - a.y;
    depth = std::min(depth, (ex * (double(p.y) - a.y) - ey * (double(p.x) - a.x)) / std::hypot(ex, ey));
  }
  return depth;
}

double distanceToSegment(Vec2 c, Vec2 a, Vec2 b) {
  const double dx = double(b.x) - a.x, dy = double(b.y) - a.y, l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((double(c.x) - a.x) * dx + (double(c.y) - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(a.x + t * dx - c.x, a.y + t * dy - c.y);
}

struct ReturnFigures {
  int trials = 0, clean = 0, overBound = 0, cornerReturnsWhenClean = 0;
  double worst = 0;
  std::string worstCase;
};

// Random bodies (shapes, turns, headings up to 83 degrees off the edge's normal, speeds of 1 to 150
// units a frame, places along the edge) sent over a random edge of a random face, stopped once they
// are wholly on the far face, then sent back for as many frames. A crossing is clean when the body
// only ever touched the two faces and its centre kept farther than its reach plus a frame's motion
// from every vertex (near a vertex the corner rule decides, docs/level-format.md); clean crossings
// must come back within `bound` units and never meet the corner rule.
ReturnFigures retraceRandomCrossings(Built* b, int trials, uint64_t seed, double bound) {
  platon::testing::Rng rng{seed};
  physics::World& world = b->world;
  ReturnFigures out;
  while (out.trials < trials) {
    const size_t f = static_cast<size_t>(rng.between(0, static_cast<int>(b->stage.faceCount()) - 1));
    const stage::StageFace& face = b->stage.faces[f];
    const size_t n = face.corners.size(), edge = static_cast<size_t>(rng.between(0, static_cast<int>(n) - 1));
    const Vec2 a = face.corners[edge], c = face.corners[(edge + 1) % n];
    const double ex = double(c.x) - a.x, ey = double(c.y) - a.y, len = std::hypot(ex, ey);
    const double ox = ey / len, oy = -ex / len;  // outward
    const double along = rng.uniform(0.02, 0.98), heading = rng.uniform(-1.45, 1.45), speed = rng.uniform(1, 150);
    const double back = rng.uniform(350, 700);
    const physics::Convex shape = randomBody(rng);
    const auto turn = static_cast<physics::Angle>(rng.next());
    const physics::EntityId body = world.createEntity(shape);
    const Vec2 start{static_cast<int32_t>(std::lround(a.x + ex * along - ox * back)),
                     static_cast<int32_t>(std::lround(a.y + ey * along - oy * back))};
    try {
      world.insert(body, b->stage.part(f), start, turn);
    } catch (const physics::Error&) {
      world.destroyEntity(body);
      continue;
    }
    const physics::EntityView e0 = world.entity(body);
    const auto [centre0, reach0] = centreAndReach(*e0.instances().begin());
    const double reach = reach0;  // a plain variable: the lambda below captures it
    if (e0.instanceCount() != 1 ||
        depthInside(face.corners, centre0) < reach + 2) {  // wholly inside its face to begin with
      world.destroyEntity(body);
      continue;
    }
    ++out.trials;
    const Vec2 from = e0.position();
    const double vx = ox * std::cos(heading) - oy * std::sin(heading),
                 vy = ox * std::sin(heading) + oy * std::cos(heading);
    world.setVelocity(body, {std::llround(vx * speed * kQ16), std::llround(vy * speed * kQ16)});
    const physics::MapPartId target = b->stage.part(size_t(face.neighbours[edge].face));
    std::vector<physics::MapPartId> touched;
    double nearestVertex = 1e18;
    int cornerReturns = 0;
    std::vector<std::pair<physics::MapPartId, Vec2>> last;
    auto step = [&] {
      cornerReturns += static_cast<int>(world.solve().cornerReturns);
      std::vector<std::pair<physics::MapPartId, Vec2>> now;
      for (const physics::InstanceView i : world.entity(body).instances()) {
        if (std::find(touched.begin(), touched.end(), i.part) == touched.end()) touched.push_back(i.part);
        const Vec2 centre = centreAndReach(i).first;
        Vec2 previous = centre;
        for (const auto& [p, at] : last)
          if (p == i.part) previous = at;
        for (const Vec2 corner : b->stage.faces[i.part - b->stage.firstPart].corners)
          nearestVertex = std::min(nearestVertex, distanceToSegment(corner, previous, centre) - reach - speed);
        now.push_back({i.part, centre});
      }
      last = std::move(now);
    };
    int frames = 0;
    while (frames < 400 && !(world.entity(body).instanceCount() == 1 && world.entity(body).part() == target))
      step(), ++frames;
    const bool crossed = world.entity(body).part() == target && world.entity(body).instanceCount() == 1;
    if (crossed) {
      const physics::Vec2w v = world.entity(body).velocity();
      world.setVelocity(body, {-v.x, -v.y});
      last.clear();
      for (int k = 0; k < frames; ++k) step();
    }
    const physics::EntityView e = world.entity(body);
    if (crossed && touched.size() == 2 && nearestVertex > 10 && e.part() == b->stage.part(f)) {
      ++out.clean;
      out.cornerReturnsWhenClean += cornerReturns > 0;
      const double error = length(e.position(), from);
      if (error > out.worst) {
        out.worst = error;
        out.worstCase = "face " + std::to_string(f) + " edge " + std::to_string(edge) + " along " +
                        std::to_string(along) + " heading " + std::to_string(heading) + " speed " +
                        std::to_string(speed) + " vertices " + std::to_string(shape.size());
      }
      out.overBound += error > bound;
    }
    world.destroyEntity(body);
  }
  return out;
}

}  // namespace

// Random bodies over random edges of every solid (faces of 4,096 and 2^24 units), retracing their
// paths: every clean crossing comes back within the documented 5 units and never meets the corner
// rule, whatever the shape (also one whose origin lies outside it), turn, heading and speed. (Before
// the anchor's face was judged by the shape's centre, a body whose origin lay off its shape was
// taken for one gone through a vertex and put back by a corner, over 1,000 units away; before a copy
// that became the anchor went to its exact place, returns reached 4.5 units.)
TEST(Crossing, RandomBodiesOverRandomEdgesComeBack) {
  for (const int32_t size : {4096, 1 << 24})
    for (const stage::Solid solid : stage::kSolids) {
      const ReturnFigures r = retraceRandomCrossings(build(solid, size, 0).get(), size == 4096 ? 1500 : 300,
                                                     77 + static_cast<uint64_t>(solid), 5.0);
      SCOPED_TRACE(std::string(stage::solidName(solid)) + " size " + std::to_string(size) + ", worst: " + r.worstCase);
      std::printf("%s, faces of %d: %d trials, %d clean crossings, worst return %.2f units\n",
                  stage::solidName(solid).data(), size, r.trials, r.clean, r.worst);
      EXPECT_GT(r.clean, r.trials / 2);
      EXPECT_EQ(r.overBound, 0);
      EXPECT_EQ(r.cornerReturnsWhenClean, 0);
    }
}

// The same over stages that are not Platonic: random prisms and bipyramids (faces of 3 to 10
// sides meeting at many angles), built from meshes as a mesh file would give them.
TEST(Crossing, RandomBodiesOverRandomMeshStagesComeBack) {
  platon::testing::Rng rng{2027};
  int stages = 0;
  for (int k = 0; k < 12; ++k) {
    auto b = std::make_unique<Built>();
    try {
      b->stage = stage::stageFromPolyhedron(stage::polyhedronFromMesh(stage::test::randomConvexMesh(rng), 4096));
    } catch (const stage::StageError& e) {
      ADD_FAILURE() << "a convex mesh was refused: " << e.what();
      continue;
    }
    stage::addStageToWorld(b->stage, b->world, 0);
    for (size_t f = 0; f < b->stage.faceCount(); ++f) b->world.mapPart(b->stage.part(f)).initialize();
    const ReturnFigures r = retraceRandomCrossings(b.get(), 400, 500 + static_cast<uint64_t>(k), 5.0);
    SCOPED_TRACE("mesh stage " + std::to_string(k) + " (" + std::to_string(b->stage.faceCount()) +
                 " faces), worst: " + r.worstCase);
    std::printf("mesh stage %d, %zu faces: %d trials, %d clean crossings, worst return %.2f units\n", k,
                b->stage.faceCount(), r.trials, r.clean, r.worst);
    EXPECT_GT(r.clean, r.trials / 3);
    EXPECT_EQ(r.overBound, 0);
    EXPECT_EQ(r.cornerReturnsWhenClean, 0);
    ++stages;
  }
  EXPECT_EQ(stages, 12);
}

// Bodies thrown at every corner of every solid from every face that has it (straight at the vertex,
// then three times more at random headings, speeds, spins and shapes), with and without the
// faces' gravity, and for 400 frames after: always on the stage, every instance's origin inside its
// face or within the body's reach of it. (Without the world's corner rule, a body through a vertex
// left every face at once and flew on outside them all.)
TEST(Crossing, ThrownAtEveryCornerNeverLeavesTheFaces) {
  platon::testing::Rng rng{42};
  for (const stage::Solid solid : stage::kSolids)
    for (const int64_t gravity : {int64_t{0}, int64_t{20000}}) {
      auto b = build(solid, 4096, gravity);
      physics::World& world = b->world;
      for (size_t f = 0; f < b->stage.faceCount(); ++f) {
        const stage::StageFace& face = b->stage.faces[f];
        const size_t n = face.corners.size();
        for (size_t trial = 0; trial < 4 * n; ++trial) {
          const size_t k = trial % n;
          const Vec2 corner = face.corners[k];
          double cx = 0, cy = 0;
          for (const Vec2 c : face.corners) cx += c.x / double(n), cy += c.y / double(n);
          const double dx = cx - corner.x, dy = cy - corner.y, d = std::hypot(dx, dy);
          const double turn = trial < n ? 0.0 : rng.uniform(-0.15, 0.15);  // first straight at the vertex
          const int speed = rng.between(4, 50);
          const int shape = rng.between(0, 1);
          SCOPED_TRACE(std::string(stage::solidName(solid)) + " face " + std::to_string(f) + " corner " +
                       std::to_string(k) + " gravity " + std::to_string(gravity) + " speed " + std::to_string(speed));
          const Vec2 start{static_cast<int32_t>(std::lround(corner.x + dx / d * 500)),
                           static_cast<int32_t>(std::lround(corner.y + dy / d * 500))};
          const physics::EntityId body = world.createEntity(shapeNumber(shape));
          world.insert(body, b->stage.part(f), start, 0);
          const double vx = -(dx * std::cos(turn) - dy * std::sin(turn)) / d,
                       vy = -(dx * std::sin(turn) + dy * std::cos(turn)) / d;
          world.setVelocity(body, {std::llround(vx * speed * kQ16), std::llround(vy * speed * kQ16)});
          world.setAngularVelocity(body, rng.between(-3000000, 3000000));
          std::vector<OnSolid> was = centresIn3d(b->stage, world.entity(body));
          for (int frame = 1; frame <= 400; ++frame) {
            const physics::Vec2w v0 = world.entity(body).velocity();
            const physics::Vec2w g = world.mapPart(world.entity(body).part()).gravity();
            world.solve();
            const physics::EntityView e = world.entity(body);
            ASSERT_TRUE(e.inserted()) << "frame " << frame;
            // Through a vertex too, it moves on as far as its speed takes it, no further (and a
            // few units of rounding at warps).
            const std::vector<OnSolid> now = centresIn3d(b->stage, e);
            const double allowed = frameReach(v0, g);
            ASSERT_LE(jumpBeyond(was, now, allowed), 0) << "frame " << frame << ": the centre jumped";
            was = now;
            const physics::Vec2w v = e.velocity();
            const double reach = 100 + std::hypot(double(v.x), double(v.y)) / kQ16;
            std::string all;
            for (const physics::InstanceView i : e.instances())
              all += " face " + std::to_string(i.part) + " (" + std::to_string(i.position.x) + ", " +
                     std::to_string(i.position.y) + ")";
            for (const physics::InstanceView i : e.instances()) {
              const auto& corners = b->stage.faces[i.part - b->stage.firstPart].corners;
              ASSERT_LE(outside(corners, i.position), reach)
                  << "frame " << frame << ": an instance at (" << i.position.x << ", " << i.position.y << ") in face "
                  << i.part << " is off its face; instances:" << all;
            }
          }
          world.destroyEntity(body);
        }
      }
    }
}

// Walking: on every solid, each face with a floor a little above its floor edge and gravity down
// its own frame, bodies kept walking right (or left) for 3,000 frames go over edges, fall onto
// other faces and walk on; every frame every copy stays on its face (or within the body's reach).
// Each face gets a floor across it a little above its lowest point (its floor edge, y = 0) and
// gravity down its own frame; six bodies kept walking right or left for 3,000 frames go over
// edges, fall onto other faces and walk on; every frame every copy stays on its face (or within
// the body's reach).
void walkAcross(Built& b, platon::testing::Rng& rng, const std::string& label) {
  for (size_t f = 0; f < b.stage.faceCount(); ++f) {
    physics::MapPart& part = b.world.mapPart(b.stage.part(f));
    const auto& c = b.stage.faces[f].corners;
    double top = 0;
    for (const Vec2 p : c) top = std::max(top, double(p.y));
    const double y = std::min(400.0, top / 4);
    double lo = 1e9, hi = -1e9;  // the polygon's width at y, less 40 units each side
    for (size_t k = 0; k < c.size(); ++k) {
      const Vec2 p = c[k], q = c[(k + 1) % c.size()];
      if ((p.y - y) * (q.y - y) > 0 || p.y == q.y) continue;
      const double x = p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y);
      lo = std::min(lo, x), hi = std::max(hi, x);
    }
    if (hi - lo > 200)
      part.line({static_cast<int32_t>(lo + 40), static_cast<int32_t>(y)},
                {static_cast<int32_t>(hi - 40), static_cast<int32_t>(y)});
    part.setGravity({0, -22938});
    part.initialize();
  }
  for (int walker = 0; walker < 6; ++walker) {
    const size_t face = static_cast<size_t>(rng.between(0, static_cast<int>(b.stage.faceCount()) - 1));
    const int64_t speed = int64_t{walker % 2 ? -1 : 1} * rng.between(3, 14) * kQ16;
    const physics::EntityId body = b.world.createEntity(shapeNumber(walker % 2));
    double cx = 0, cy = 0;
    for (const Vec2 p : b.stage.faces[face].corners) cx += p.x, cy += p.y;
    cx /= double(b.stage.faces[face].corners.size()), cy /= double(b.stage.faces[face].corners.size());
    try {
      b.world.insert(body, b.stage.part(face), {static_cast<int32_t>(cx), static_cast<int32_t>(cy)}, 0);
    } catch (const physics::Error&) {
      b.world.destroyEntity(body);  // a face too small for the body here
      continue;
    }
    SCOPED_TRACE(label + " walker " + std::to_string(walker));
    for (int frame = 1; frame <= 3000; ++frame) {
      b.world.setVelocity(body, {speed, b.world.entity(body).velocity().y});
      b.world.solve();
      const physics::EntityView e = b.world.entity(body);
      ASSERT_TRUE(e.inserted()) << "frame " << frame;
      const double reach = 100 + std::hypot(double(e.velocity().x), double(e.velocity().y)) / kQ16;
      for (const physics::InstanceView i : e.instances())
        ASSERT_LE(outside(b.stage.faces[i.part - b.stage.firstPart].corners, i.position), reach)
            << "frame " << frame << ": a copy at (" << i.position.x << ", " << i.position.y << ") is off face "
            << i.part;
    }
    b.world.destroyEntity(body);
  }
}

TEST(Crossing, WalkingAndFallingAcrossEveryShapeStaysOnTheFaces) {
  platon::testing::Rng rng{9};
  for (const stage::Solid solid : stage::kSolids) {
    auto b = std::make_unique<Built>();
    b->stage = stage::platonicStage(solid, 4096);
    stage::addStageToWorld(b->stage, b->world, 0);
    walkAcross(*b, rng, std::string(stage::solidName(solid)));
  }
  for (int k = 0; k < 12; ++k) {  // and random prisms and bipyramids
    auto b = std::make_unique<Built>();
    b->stage = stage::stageFromPolyhedron(stage::polyhedronFromMesh(stage::test::randomConvexMesh(rng), 4096));
    stage::addStageToWorld(b->stage, b->world, 0);
    walkAcross(*b, rng, "mesh stage " + std::to_string(k));
  }
}

}  // namespace

// The case found by a level: a body that slid down a leaning wall walks right, falling fast, into a
// cube's bottom right vertex where no floor is. Each frame its motion carried it out past the
// vertex, the corner rule put it back beside the same corner, and it froze there while its velocity
// grew with gravity (4 in 600 before the corner rule kept the next frame's motion clear of the
// vertex).
TEST(Crossing, ABodyPushedIntoACubeVertexNeverFreezes) {
  platon::testing::Rng rng{7};
  int frozen = 0;
  for (int trial = 0; trial < 600; ++trial) {
    auto b = std::make_unique<Built>();
    b->stage = stage::platonicStage(stage::Solid::Hexahedron, 4096);
    stage::addStageToWorld(b->stage, b->world, 0);
    const double lean = rng.between(5, 70) * M_PI / 180;
    const int foot = rng.between(1500, 3500);
    for (size_t f = 0; f < b->stage.faceCount(); ++f) {
      physics::MapPart& p = b->world.mapPart(b->stage.part(f));
      if (f == 0)
        p.line({foot, 0},
               {foot + static_cast<int32_t>(3000 * std::sin(lean)), static_cast<int32_t>(3000 * std::cos(lean))});
      p.setGravity({0, -int64_t{rng.between(15000, 40000)}});
      p.initialize();
    }
    const physics::EntityId e =
        b->world.createEntity(physics::Convex::regular(rng.between(8, 24), rng.between(40, 160)));
    const int h = rng.between(1200, 2400);
    try {
      b->world.insert(e, 0, {foot + static_cast<int32_t>(h * std::tan(lean)) - 400, h}, 0);
    } catch (const physics::Error&) {
      continue;
    }
    b->world.setVelocity(e, {int64_t{rng.between(2, 20)} * kQ16, -int64_t{rng.between(10, 60)} * kQ16});
    int still = 0;
    Vec2 last{};
    for (int f = 0; f < 400; ++f) {
      const physics::Vec2w v = b->world.entity(e).velocity();
      b->world.setVelocity(e, {std::min<int64_t>(v.x + kQ16 / 2, 9 * kQ16), v.y});  // walking right, as the player does
      b->world.solve();
      const Vec2 p = b->world.entity(e).position();
      still = p == last && b->world.entity(e).contacts().empty() ? still + 1 : 0;
      last = p;
    }
    frozen += still > 50;
  }
  EXPECT_EQ(frozen, 0);
}

namespace {

// Whether a body sat still (same position, no contact) while moving for more than 50 frames in a
// row, and the longest run of frames in which the corner rule put it back while it moved. (At rest
// in a pit, where every face's gravity leans into a vertex, a body may be put back every frame.)
struct Stuck {
  int stillFrames = 0, longestStill = 0, cornerRun = 0, longestCornerRun = 0;
  void frame(bool still, bool cornerReturn) {
    stillFrames = still ? stillFrames + 1 : 0;
    cornerRun = cornerReturn ? cornerRun + 1 : 0;
    longestStill = std::max(longestStill, stillFrames);
    longestCornerRun = std::max(longestCornerRun, cornerRun);
  }
};

struct VertexRuns {
  int runs = 0, returns = 0, frozen = 0, putBackRunning = 0, worstCornerRun = 0, inWalls = 0;
  // Frames in which the vertex rule moved a body and its centre went (over the solid) further than
  // the frame's motion allows, and the largest excess; and such frames without the vertex rule
  // (a copy a wall held back from its exact place, in a walled pocket at a vertex: not promised).
  int jumps = 0, otherJumps = 0, holds = 0;
  double worstJump = 0;
  int deadFrames = 0;  // frames a moving body ended where it was with no contact (a stall, however short)
  std::string firstFailure;
  void fail(const std::string& what) {
    if (firstFailure.empty()) firstFailure = what;
  }
};

// Every vertex of every solid, with each face's gravity turned at random (so some vertices are
// pits every gravity leans into, others are passes) and, in odd layouts, short walls across or
// beside the corners; bodies of random shapes driven at a vertex from a face that has it by a
// steady push in their own frame (as a player holding a key), 400 frames each. Counts the bodies
// that sat frozen beside a vertex (more than 50 frames still with no contact, while their velocity
// says they move), that the corner rule put back more than 3 frames running while they moved, and
// that had a copy overlap a wall.
VertexRuns driveBodiesIntoVertices(uint64_t seed, int layouts) {
  platon::testing::Rng rng{seed};
  VertexRuns out;
  for (const stage::Solid solid : stage::kSolids)
    for (int layout = 0; layout < layouts; ++layout) {
      auto b = std::make_unique<Built>();
      b->stage = stage::platonicStage(solid, 4096);
      stage::addStageToWorld(b->stage, b->world, 0);
      std::vector<std::vector<physics::Segment>> walls(b->stage.faceCount());
      for (size_t f = 0; f < b->stage.faceCount(); ++f) {
        physics::MapPart& part = b->world.mapPart(b->stage.part(f));
        const auto& corners = b->stage.faces[f].corners;
        for (size_t k = 0; layout % 2 == 1 && k < corners.size(); ++k) {
          const Vec2 c = corners[k], next = corners[(k + 1) % corners.size()],
                     prev = corners[(k + corners.size() - 1) % corners.size()];
          auto at = [&](Vec2 toward, double distance) {
            const double d = length(c, toward);
            return Vec2{static_cast<int32_t>(std::lround(c.x + (toward.x - c.x) * distance / d)),
                        static_cast<int32_t>(std::lround(c.y + (toward.y - c.y) * distance / d))};
          };
          // Across the corner from one edge to the other, or a stub standing on one edge.
          const Vec2 a = at(next, rng.uniform(40, 400));
          const Vec2 e = rng.between(0, 1) ? at(prev, rng.uniform(40, 400))
                                           : Vec2{(a.x + at(prev, 200).x) / 2, (a.y + at(prev, 200).y) / 2};
          if (a == e) continue;
          part.line(a, e);
          walls[f].push_back({a, e});
        }
        const double turn = rng.uniform(-M_PI, M_PI), g = rng.between(8000, 40000);
        part.setGravity({std::llround(g * std::sin(turn)), -std::llround(g * std::cos(turn))});
        part.initialize();
      }
      for (int trial = 0; trial < 40; ++trial) {
        const size_t f = static_cast<size_t>(rng.between(0, static_cast<int>(b->stage.faceCount()) - 1));
        const auto& corners = b->stage.faces[f].corners;
        const size_t n = corners.size();
        const Vec2 corner = corners[static_cast<size_t>(rng.between(0, static_cast<int>(n) - 1))];
        double cx = 0, cy = 0;
        for (const Vec2 c : corners) cx += c.x / double(n), cy += c.y / double(n);
        const double dx = cx - corner.x, dy = cy - corner.y, d = std::hypot(dx, dy);
        const double from = rng.uniform(150, 900), aim = rng.uniform(-0.35, 0.35);
        const Vec2 start{static_cast<int32_t>(std::lround(corner.x + dx / d * from)),
                         static_cast<int32_t>(std::lround(corner.y + dy / d * from))};
        const physics::EntityId body = b->world.createEntity(
            rng.between(0, 2) == 0 ? physics::Convex::box(rng.between(20, 90), rng.between(20, 90))
                                   : physics::Convex::regular(rng.between(3, 16), rng.between(30, 140)));
        try {
          b->world.insert(body, b->stage.part(f), start, 0);
        } catch (const physics::Error&) {
          b->world.destroyEntity(body);
          continue;
        }
        // The push: toward the vertex as seen from the start, kept in whatever frame the body is in.
        const double px = -(dx * std::cos(aim) - dy * std::sin(aim)) / d,
                     py = -(dx * std::sin(aim) + dy * std::cos(aim)) / d;
        const int64_t push = rng.between(6000, 40000), top = int64_t{rng.between(3, 60)} * kQ16;
        const std::string name = std::string(stage::solidName(solid)) + " layout " + std::to_string(layout) +
                                 " trial " + std::to_string(trial);
        Stuck stuck;
        Vec2 last = start;
        bool inWall = false;
        std::vector<OnSolid> was = centresIn3d(b->stage, b->world.entity(body));
        for (int frame = 0; frame < 400; ++frame) {
          const physics::Vec2w v = b->world.entity(body).velocity();
          const double along = double(v.x) * px + double(v.y) * py;
          if (along < double(top))
            b->world.setVelocity(body, {v.x + std::llround(px * double(push)), v.y + std::llround(py * double(push))});
          const physics::Vec2w v0 = b->world.entity(body).velocity();
          const double allowed = frameReach(v0, b->world.mapPart(b->world.entity(body).part()).gravity());
          const physics::SolveReport report = b->world.solve();
          const physics::EntityView e = b->world.entity(body);
          if (e.inserted()) {
            const std::vector<OnSolid> now = centresIn3d(b->stage, e);
            // Held at a walled vertex, it is put back inside the face (2 units in, placed within 2
            // units) from up to 4 units beyond it: up to 8 units more.
            const bool atVertex = report.cornerReturns + report.vertexHolds > 0;
            const double beyond = jumpBeyond(was, now, allowed + (report.vertexHolds > 0 ? 8 : 0));
            if (beyond > 0 && !atVertex) ++out.otherJumps;
            if (beyond > 0 && atVertex) {
              ++out.jumps;
              out.worstJump = std::max(out.worstJump, beyond);
              out.fail(name + ", frame " + std::to_string(frame) + ": the centre jumped " +
                       std::to_string(beyond + allowed) + " units (the frame's motion allows " +
                       std::to_string(allowed) + ")");
            }
            was = now;
          }
          if (!e.inserted()) {
            out.fail(name + ": left the world");
            break;
          }
          for (const physics::InstanceView i : e.instances()) {
            std::vector<Vec2> verts;
            for (const Vec2 p : i.shape) verts.push_back({i.position.x + p.x, i.position.y + p.y});
            for (const physics::Segment& wall : walls[i.part - b->stage.firstPart])
              if (physics::overlapsInterior(verts, wall)) {
                inWall = true;
                out.fail(name + ", frame " + std::to_string(frame) + ": a copy in a wall at (" +
                         std::to_string(i.position.x) + ", " + std::to_string(i.position.y) + ")");
              }
          }
          // Moving: faster than one frame's push and gravity can make a body from rest.
          const bool moving = std::hypot(double(e.velocity().x), double(e.velocity().y)) >= 2.0 * kQ16;
          // Still: where it was, with no contact, going the same way. (A path straight into a
          // vertex whose faces leave half a turn, a tetrahedron's, goes on straight back out: a frame
          // later it is where it was, going the other way.)
          const bool sameWay = double(e.velocity().x) * double(v0.x) + double(e.velocity().y) * double(v0.y) > 0;
          const bool still = moving && e.position() == last && e.contacts().empty() && sameWay;
          stuck.frame(still, moving && report.cornerReturns > 0);
          out.deadFrames += still;
          if (still)
            out.fail(name + ", frame " + std::to_string(frame) +
                     ": moving, it ended the frame where it was with no contact");
          out.returns += static_cast<int>(report.cornerReturns);
          out.holds += static_cast<int>(report.vertexHolds);
          last = e.position();
        }
        out.inWalls += inWall;
        if (stuck.longestStill > 50) ++out.frozen, out.fail(name + ": frozen beside a vertex");
        if (stuck.longestCornerRun > 3)
          ++out.putBackRunning, out.fail(name + ": put back by the corner rule frame after frame");
        out.worstCornerRun = std::max(out.worstCornerRun, stuck.longestCornerRun);
        b->world.destroyEntity(body);
        ++out.runs;
      }
    }
  return out;
}

}  // namespace

// Bodies driven into any vertex never freeze there: none ends a single frame where it was with no
// contact while its velocity says it moves, none is put back by the corner rule frame after frame
// while it moves, and none enters a wall. (Before the corner rule gave room for the next frame's
// motion and found the overlaps of the place it put a body, 94 of the first 1,136 bodies froze;
// before a failed seam lift re-planned its sub-move, 10 in 34,108 had a copy stepped into a wall;
// before a copy was lifted at a seam at most once a frame, 411 frames of these 3,799 bodies were
// spent lifting it a unit a sub-move until the sub-moves ran out.)
TEST(Crossing, BodiesDrivenIntoAnyVertexNeverFreeze) {
  const VertexRuns r = driveBodiesIntoVertices(2026, 20);
  std::printf(
      "%d bodies, %d corner returns, %d frozen, %d put back running (longest %d frames), %d in a wall, %d stalled "
      "frames, %d jumps at a vertex (worst %.1f units past the frame's motion), %d elsewhere\n",
      r.runs, r.returns, r.frozen, r.putBackRunning, r.worstCornerRun, r.inWalls, r.deadFrames, r.jumps, r.worstJump,
      r.otherJumps);
  RecordProperty("bodies", r.runs);
  EXPECT_GT(r.runs, 3000);
  EXPECT_EQ(r.frozen, 0) << r.firstFailure;
  EXPECT_EQ(r.deadFrames, 0) << r.firstFailure;
  EXPECT_EQ(r.putBackRunning, 0) << r.firstFailure;
  EXPECT_EQ(r.inWalls, 0) << r.firstFailure;
  EXPECT_EQ(r.jumps, 0) << r.firstFailure;
}

// The same over a larger sample, three more seeds of 60 layouts (34,108 bodies, about 25 s in a
// Release build). Seed 3 holds the case of a warp hit pulled back while a copy still moved a unit
// (the anchor did not): counted as progress, the same sub-move came again from the same place
// until the frame's sub-moves ran out (2 stalled frames; 1,400 a seed before the seam lift rule).
TEST(Crossing, ManyMoreBodiesDrivenIntoAnyVertexNeverFreeze) {
  for (const uint64_t seed : {1, 2, 3}) {
    const VertexRuns r = driveBodiesIntoVertices(seed, 60);
    std::printf(
        "seed %llu: %d bodies, %d frozen, %d put back running, %d in a wall, %d stalled frames, %d jumps at a vertex, "
        "%d elsewhere\n",
        static_cast<unsigned long long>(seed), r.runs, r.frozen, r.putBackRunning, r.inWalls, r.deadFrames, r.jumps,
        r.otherJumps);
    EXPECT_EQ(r.frozen, 0) << r.firstFailure;
    EXPECT_EQ(r.deadFrames, 0) << r.firstFailure;
    EXPECT_EQ(r.putBackRunning, 0) << r.firstFailure;
    EXPECT_EQ(r.inWalls, 0) << r.firstFailure;
    EXPECT_EQ(r.jumps, 0) << r.firstFailure;
  }
}
