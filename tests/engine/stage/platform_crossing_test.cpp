// Platforms that travel over the edges of every solid: a wall swept over every edge of every face
// of the five Platonic solids, at several speeds, pushes what stands beyond it and crosses onto the
// next face without a jump; a plank carries its rider over an edge; a platform driven straight on
// goes round the cube's belt and comes back to where it started.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "platon/physics/sweep.h"
#include "platon/stage/stage.h"
#include "platon/testing/rng.h"
#include "random_mesh.h"

using namespace platon;
using physics::Vec2;

namespace {

constexpr int32_t kEdge = 600;

struct Built {
  physics::World world;
  stage::Stage stage;
};

std::unique_ptr<Built> build(stage::Solid solid, int32_t edge = kEdge) {
  auto b = std::make_unique<Built>();
  b->stage = stage::platonicStage(solid, edge);
  stage::addStageToWorld(b->stage, b->world, 0);
  for (size_t f = 0; f < b->stage.faceCount(); ++f) b->world.mapPart(b->stage.part(f)).initialize();
  return b;
}

struct Vec2d {
  double x, y;
};
Vec2d unit(double x, double y) {
  const double n = std::hypot(x, y);
  return {x / n, y / n};
}
Vec2 rounded(double x, double y) {
  return {static_cast<int32_t>(std::lround(x)), static_cast<int32_t>(std::lround(y))};
}

// How far `p` lies outside the convex polygon `corners` (counter-clockwise; 0 inside).
double outside(const std::vector<Vec2>& corners, double x, double y) {
  double worst = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
    const double ex = double(b.x) - a.x, ey = double(b.y) - a.y;
    worst = std::max(worst, -(ex * (y - a.y) - ey * (x - a.x)) / std::hypot(ex, ey));
  }
  return worst;
}

// Where the middle of the platform's line 0 is on the solid, in 3D: in its own part or its copy's,
// whichever has it on its face (within 2 units); nothing when neither does (beyond an edge it has
// no copy over, beside a vertex).
std::optional<Eigen::Vector3d> middleOnSolid(const Built& b, const physics::PlatformView& p) {
  auto on = [&](physics::MapPartId part,
                std::span<const physics::PlatformLine> lines) -> std::optional<Eigen::Vector3d> {
    const physics::Segment& s = lines[0].segment;
    const stage::StageFace& face = b.stage.faces[part - b.stage.firstPart];
    const double x = (double(s.a.x) + s.b.x) / 2, y = (double(s.a.y) + s.b.y) / 2;
    if (outside(face.corners, x, y) > 2) return std::nullopt;
    return face.toWorld(x, y);
  };
  if (auto at = on(p.part, p.lines)) return at;
  for (const physics::PlatformCopyView& c : p.copies)
    if (auto at = on(c.part, c.lines)) return at;
  return std::nullopt;
}

// An instance in one of a platform's solid lines (a body may pass through a one-way line from behind).
struct Overlap {
  uint32_t entity = 0;
  physics::MapPartId part = 0;
  size_t line = 0;
  bool met = false;  // where the platform meets the body (the first of its parts the body is in)
  bool own = false;  // in the platform's own part
  std::string what;
};

// Every instance of every entity against every solid line of the platform in its part and its
// copy's. The platform meets a body in the first of its parts (its own, then its copy's) the body is
// in; the body's copies elsewhere are only lifted off its copy's lines where they can be.
std::vector<Overlap> overlapsOf(const physics::World& w, physics::PlatformId id) {
  const physics::PlatformView p = w.platform(id);
  std::vector<Overlap> found;
  std::vector<physics::MapPartId> parts{p.part};
  for (const physics::PlatformCopyView& c : p.copies) parts.push_back(c.part);
  for (const physics::EntityId e : w.entities()) {
    const physics::EntityView view = w.entity(e);
    std::optional<physics::MapPartId> meets;
    for (const physics::MapPartId part : parts)
      for (const physics::InstanceView i : view.instances())
        if (!meets && i.part == part) meets = part;
    for (const physics::InstanceView i : view.instances()) {
      const auto at = std::find(parts.begin(), parts.end(), i.part);
      if (at == parts.end()) continue;
      const std::span<const physics::PlatformLine> lines =
          at == parts.begin() ? p.lines : p.copies[static_cast<size_t>(at - parts.begin() - 1)].lines;
      std::vector<Vec2> verts;
      for (const Vec2 v : i.shape) verts.push_back({i.position.x + v.x, i.position.y + v.y});
      for (size_t k = 0; k < lines.size(); ++k) {
        const physics::Segment& s = lines[k].segment;
        if (lines[k].kind != physics::LineKind::Solid || !physics::overlapsInterior(verts, s)) continue;
        std::ostringstream what;
        what << "entity " << e.index << " at " << i.position.x << "," << i.position.y << " in part " << i.part
             << (i.part == p.part ? "" : " (a copy's)") << " overlaps " << s.a.x << "," << s.a.y << "-" << s.b.x << ","
             << s.b.y << "; ";
        found.push_back({e.index, i.part, k, i.part == meets, i.part == p.part, what.str()});
      }
    }
  }
  return found;
}

// The overlaps where the platform meets the body, or nothing.
std::string overlaps(const physics::World& w, physics::PlatformId id) {
  std::string out;
  for (const Overlap& o : overlapsOf(w, id))
    if (o.met) out += o.what;
  return out;
}

// Solves `frames` frames: the first with an overlap where the platform meets a body, or one
// countOverlaps sees ("" when none).
std::string overlapInFrames(physics::World& w, physics::PlatformId id, int frames) {
  for (int frame = 0; frame < frames; ++frame) {
    w.solve();
    const std::string found = overlaps(w, id);
    if (!found.empty() || w.countOverlaps() != 0)
      return "frame " + std::to_string(frame) + ": " + found + " countOverlaps " + std::to_string(w.countOverlaps());
  }
  return "";
}

struct Edge {
  physics::Segment seg;  // in the face's part, the face to its left
  physics::MapPartId target;
  physics::Segment targetSeg;  // the same edge in the target part, its face to the right
  Vec2d d, in;                 // along it and into the face, unit vectors in the face's part
  double length = 0;
  Vec2d td;  // along it in the target part (the same way as d)
};

std::vector<Edge> edgesOf(const physics::World& w, physics::MapPartId part) {
  std::vector<Edge> out;
  const physics::MapPart& p = w.mapPart(part);
  for (const physics::LineIndex line : p.faceLoop()) {
    const physics::Warp& warp = p.warps()[p.lines()[line].warp];
    const physics::Segment s = p.segments()[line], t = warp.targetSegment;
    const Vec2d d = unit(double(s.b.x) - s.a.x, double(s.b.y) - s.a.y);
    out.push_back({s,
                   warp.target,
                   t,
                   d,
                   {-d.y, d.x},
                   std::hypot(double(s.b.x) - s.a.x, double(s.b.y) - s.a.y),
                   unit(double(t.b.x) - t.a.x, double(t.b.y) - t.a.y)});
  }
  return out;
}

class CountCrushes : public physics::Rules {
 public:
  int crushes = 0;
  std::string last;  // the latest crush: the body, the part, the line
  // The parts each body had an instance in at some moment since this was last cleared: an instance
  // over a warp line is in its part (its overlaps with warp lines begin, go on and end there).
  std::map<uint32_t, std::set<physics::MapPartId>> partsSeen;
  std::vector<uint32_t> crushedBy;  // the bodies named by crushed calls, since last cleared
  void crushed(const physics::Contact& c) override {
    ++crushes;
    crushedBy.push_back(c.entity.index);
    last = "entity " + std::to_string(c.entity.index) + " in part " + std::to_string(c.part) + " by line " +
           std::to_string(c.line.index);
  }
  void beginContact(const physics::Contact& c) override { seen(c); }
  void overContact(const physics::Contact& c) override { seen(c); }
  void endContact(const physics::Contact& c) override { seen(c); }

 private:
  void seen(const physics::Contact& c) {
    if (c.line.kind == physics::LineKind::Warp && !c.other.isSet()) partsSeen[c.entity.index].insert(c.part);
  }
};

// A random solid: one of the five, or a prism or bipyramid from a mesh.
std::unique_ptr<Built> randomSolid(platon::testing::Rng& rng) {
  auto b = std::make_unique<Built>();
  const int pick = rng.between(0, 5);
  b->stage = pick < 5 ? stage::platonicStage(stage::kSolids[pick], rng.between(800, 3000))
                      : stage::stageFromPolyhedron(stage::polyhedronFromMesh(stage::test::randomConvexMesh(rng), 3000));
  stage::addStageToWorld(b->stage, b->world, 0);
  for (size_t f = 0; f < b->stage.faceCount(); ++f) b->world.mapPart(b->stage.part(f)).initialize();
  return b;
}

// A random point well inside face f (a mean of its corners with random weights).
Vec2 insideFace(const stage::StageFace& face, platon::testing::Rng& rng) {
  double x = 0, y = 0, total = 0;
  for (const Vec2 c : face.corners) {
    const double w = rng.uniform(0.2, 1);
    x += w * c.x, y += w * c.y, total += w;
  }
  return rounded(x / total, y / total);
}

}  // namespace

// A wall parallel to an edge, a quarter of the face in from it, driven over it (straight at it, or
// slanted; up to 300 units a frame): a box beyond the edge is pushed ahead of it, never overlapped,
// nothing is crushed, the wall goes over onto the face beyond, and its middle moves over the solid
// by its motion every frame (on whichever face has it, its own or its copy's).
TEST(PlatformCrossing, AWallDrivenOverEveryEdgePushesWhatIsBeyondAndGoesOnWithoutAJump) {
  int runs = 0, crossed = 0, measured = 0;
  for (const stage::Solid solid : stage::kSolids) {
    auto b = build(solid);
    CountCrushes rules;
    b->world.setRules(&rules);
    for (size_t f = 0; f < b->stage.faceCount(); ++f)
      for (const Edge& edge : edgesOf(b->world, b->stage.part(f)))
        for (const auto& [speed, slant] :
             {std::pair{3, 0.0}, std::pair{17, 0.0}, std::pair{41, 0.0}, std::pair{41, 0.6}, std::pair{300, 0.6}}) {
          SCOPED_TRACE(::testing::Message() << "solid " << int(solid) << " face " << f << " to part " << edge.target
                                            << " speed " << speed << " slant " << slant);
          const Vec2d d = edge.d, in = edge.in;
          const double along = edge.length;
          auto at = [&](double t, double depth) {
            return rounded(edge.seg.a.x + d.x * along * t + in.x * depth,
                           edge.seg.a.y + d.y * along * t + in.y * depth);
          };
          const physics::PlatformLine wall{{at(0.35, 150), at(0.65, 150)}};
          const physics::PlatformId id = b->world.createPlatform(b->stage.part(f), std::span(&wall, 1));
          // Straight at the edge, or slanted along it (by 0.6 radians: the wall's reach towards the
          // edge is then not its motion's largest component).
          const Vec2 motion = rounded((-in.x * std::cos(slant) + d.x * std::sin(slant)) * speed,
                                      (-in.y * std::cos(slant) + d.y * std::sin(slant)) * speed);
          b->world.setPlatformMotion(id, motion);
          // A box beyond the edge, in the wall's way: 60 units into the next face.
          const Vec2d td = edge.td;
          // (Where the wall comes over: a slanted one has gone along the edge by then.)
          const double shift = 210 * std::tan(slant);
          const Vec2 boxAt = rounded((double(edge.targetSeg.a.x) + edge.targetSeg.b.x) / 2 + td.x * shift + td.y * 60,
                                     (double(edge.targetSeg.a.y) + edge.targetSeg.b.y) / 2 + td.y * shift - td.x * 60);
          const physics::EntityId box = b->world.createEntity(physics::Convex::box(20, 20));
          b->world.insert(box, edge.target, boxAt, 0);
          const double step = std::hypot(double(motion.x), double(motion.y));
          std::optional<Eigen::Vector3d> was = middleOnSolid(*b, b->world.platform(id));
          const int frames = (150 + 200) / speed + 4;
          bool over = false;
          for (int frame = 0; frame < frames; ++frame) {
            b->world.solve();
            const physics::PlatformView p = b->world.platform(id);
            ASSERT_EQ(overlaps(b->world, id), "") << "frame " << frame;
            const std::optional<Eigen::Vector3d> now = middleOnSolid(*b, p);
            if (now && was) {
              ASSERT_LE((*now - *was).norm(), step + 3) << "frame " << frame;
              ++measured;
            }
            was = now;
            over = over || p.part == edge.target;
          }
          EXPECT_TRUE(over) << "the wall never went over onto the face beyond";
          // Pushed ahead of it: the wall ends about 200 units into the face beyond, the box began 40
          // (a slow wall's motion, rounded to whole units, is up to 20 degrees off straight across;
          // a fast one pushes it on over the next edge, where its way is no longer straight).
          const physics::InstanceView i = b->world.entity(box).instances()[0];
          const Eigen::Vector3d boxNow =
              b->stage.faces[i.part - b->stage.firstPart].toWorld(i.position.x, i.position.y);
          const Eigen::Vector3d boxWas = b->stage.faces[edge.target - b->stage.firstPart].toWorld(boxAt.x, boxAt.y);
          EXPECT_GT((boxNow - boxWas).norm(), 100);
          crossed += over;
          ++runs;
          // A wall half a face a frame pushes the box over several faces and past vertices in a few
          // frames, where a push can be impossible (and says so); slower ones never are.
          if (speed < 100) {
            EXPECT_EQ(rules.crushes, 0) << rules.last;
          }
          rules.crushes = 0;
          b->world.destroyPlatform(id);
          b->world.destroyEntity(box);
        }
  }
  EXPECT_EQ(crossed, runs);
  EXPECT_EQ(runs, 900);
  EXPECT_GT(measured, 10 * runs);  // frames whose move was measured on the solid
}

// An arm turning about a point 40 units in from the middle of an edge, lying along the edge at
// first, swings over it onto the face beyond (its copy there turns with it, about the pivot placed
// through the warp) and pushes the box standing there (50 units beyond the edge, or on it) out of
// its way: never overlapped, never crushed; every edge of every face of the five solids, two speeds.
TEST(PlatformCrossing, AnArmTurningOverEveryEdgeSweepsWhatIsBeyond) {
  int runs = 0;
  for (const stage::Solid solid : stage::kSolids) {
    auto b = build(solid);
    CountCrushes rules;
    b->world.setRules(&rules);
    for (size_t f = 0; f < b->stage.faceCount(); ++f)
      for (const Edge& edge : edgesOf(b->world, b->stage.part(f)))
        for (const auto& [spin, beyond] : {std::pair{-(1 << 24), 50}, std::pair{-(1 << 26), 50},
                                           std::pair{-(1 << 24), 0}, std::pair{-(1 << 26), 0}}) {
          // 1/256 and 1/64 of a turn a frame, outwards; the box 50 units beyond the edge, or on it
          // (in both parts: swept in one, it is pushed into the other, where it is met again).
          SCOPED_TRACE(::testing::Message() << "solid " << int(solid) << " face " << f << " to part " << edge.target
                                            << " spin " << spin << " beyond " << beyond);
          const double midX = (double(edge.seg.a.x) + edge.seg.b.x) / 2,
                       midY = (double(edge.seg.a.y) + edge.seg.b.y) / 2;
          const Vec2 pivot = rounded(midX + edge.in.x * 40, midY + edge.in.y * 40);
          const physics::PlatformLine arm{{pivot, rounded(pivot.x + edge.d.x * 150, pivot.y + edge.d.y * 150)}};
          const physics::PlatformId id = b->world.createPlatform(b->stage.part(f), std::span(&arm, 1));
          b->world.setPlatformSpin(id, pivot, spin);
          const Vec2d td = edge.td;
          const Vec2 boxAt = rounded((double(edge.targetSeg.a.x) + edge.targetSeg.b.x) / 2 + td.y * beyond,
                                     (double(edge.targetSeg.a.y) + edge.targetSeg.b.y) / 2 - td.x * beyond);
          const physics::EntityId box = b->world.createEntity(physics::Convex::box(10, 10));
          b->world.insert(box, edge.target, boxAt, 0);
          bool copied = false;
          const int frames = (1 << 30) / -spin + 30;  // a quarter turn and more
          for (int frame = 0; frame < frames; ++frame) {
            const physics::Angle before = b->world.platform(id).angle;
            b->world.solve();
            const physics::PlatformView p = b->world.platform(id);
            ASSERT_EQ(overlaps(b->world, id), "") << "frame " << frame;
            ASSERT_EQ(static_cast<physics::Angle>(p.angle - before), static_cast<physics::Angle>(spin))
                << "frame " << frame << ": " << rules.last;
            copied = copied || !p.copies.empty();
          }
          EXPECT_TRUE(copied) << "the arm never had a copy beyond the edge";
          const physics::InstanceView i = b->world.entity(box).instances()[0];
          const Eigen::Vector3d boxNow =
              b->stage.faces[i.part - b->stage.firstPart].toWorld(i.position.x, i.position.y);
          const Eigen::Vector3d boxWas = b->stage.faces[edge.target - b->stage.firstPart].toWorld(boxAt.x, boxAt.y);
          EXPECT_GT((boxNow - boxWas).norm(), 20) << "the box was not swept aside";
          EXPECT_EQ(rules.crushes, 0) << rules.last;
          rules.crushes = 0;
          ++runs;
          b->world.destroyPlatform(id);
          b->world.destroyEntity(box);
        }
  }
  EXPECT_EQ(runs, 720);
}

// An audit's case: on an octahedron a plank turning over an edge sweeps a 12-gon that stands only on
// the face beyond; pushed there, it comes into the platform's own part, where the turn had been
// cleared already, and was left in the plank's line. The places are gone over again until a round
// pushes nothing: no overlap, nothing crushed.
TEST(PlatformCrossing, ABodySweptFromTheFaceBeyondIntoThePlatformsOwnPartIsClearedThere) {
  auto b = build(stage::kSolids[2], 1043);
  physics::World& w = b->world;
  CountCrushes rules;
  w.setRules(&rules);
  const physics::PlatformLine plank{{{944, 196}, {895, 136}}};
  const physics::PlatformId id = w.createPlatform(b->stage.part(5), std::span(&plank, 1));
  const physics::EntityId e = w.createEntity(physics::Convex::regular(12, 28));
  w.insert(e, b->stage.part(6), {145, 195}, 0);
  w.setPlatformSpin(id, {906, 149}, 73075746);
  EXPECT_EQ(overlapInFrames(w, id, 30), "");
  EXPECT_EQ(rules.crushes, 0) << rules.last;
}

// An audit's case: a line driven at (-29, -31) a frame towards a resting triangle whose copy is
// beyond an edge of an octahedron; the copy's line pokes a few units into the triangle's copy there.
// Pushing the whole body out of the copy's line when its copy cannot be lifted off (tried) shoved it
// into the face beyond, where it was met inside the copy's line; it is pushed along at home.
TEST(PlatformCrossing, ABodyWhoseCopyALineEndPokesIntoIsNotShovedIntoTheFaceBeyond) {
  auto b = build(stage::kSolids[2], 988);
  physics::World& w = b->world;
  CountCrushes rules;
  w.setRules(&rules);
  const physics::PlatformLine line{{{168, 52}, {111, 28}}};
  const physics::PlatformId id = w.createPlatform(b->stage.part(7), std::span(&line, 1));
  const physics::EntityId e = w.createEntity(physics::Convex({{-14, -23}, {27, 0}, {-13, 23}}));
  w.insert(e, b->stage.part(7), {98, 19}, 3579012531u);
  w.setPlatformMotion(id, {-29, -31});
  EXPECT_EQ(overlapInFrames(w, id, 4), "");
}

// A plank pointing at an edge, driven over it with a box standing on it; each face pulls the box
// onto the plank (the same way on both sides of the edge, as a level's gravity does), the others not
// at all. The box rides it over the edge, never overlapping it and never crushed, and stands on it
// on the face beyond as it did before.
TEST(PlatformCrossing, APlankCarriesItsRiderOverEveryEdge) {
  constexpr int64_t kPull = 20000;  // Q16 units a frame, about 0.3 units a frame squared
  int runs = 0;
  for (const stage::Solid solid : stage::kSolids) {
    auto b = build(solid);
    CountCrushes rules;
    b->world.setRules(&rules);
    for (size_t f = 0; f < b->stage.faceCount(); ++f)
      for (const Edge& edge : edgesOf(b->world, b->stage.part(f)))
        for (const int speed : {4, 11}) {
          SCOPED_TRACE(::testing::Message()
                       << "solid " << int(solid) << " face " << f << " to part " << edge.target << " speed " << speed);
          const Vec2d d = edge.d, in = edge.in, td = edge.td;
          for (size_t g = 0; g < b->stage.faceCount(); ++g) b->world.mapPart(b->stage.part(g)).setGravity({0, 0});
          b->world.mapPart(b->stage.part(f)).setGravity({std::llround(-d.x * kPull), std::llround(-d.y * kPull)});
          b->world.mapPart(edge.target).setGravity({std::llround(-td.x * kPull), std::llround(-td.y * kPull)});
          const double mx = (double(edge.seg.a.x) + edge.seg.b.x) / 2, my = (double(edge.seg.a.y) + edge.seg.b.y) / 2;
          auto at = [&](double depth, double up) {
            return rounded(mx + in.x * depth + d.x * up, my + in.y * depth + d.y * up);
          };
          const physics::PlatformLine plank{{at(250, 0), at(100, 0)}};
          const physics::PlatformId id = b->world.createPlatform(b->stage.part(f), std::span(&plank, 1));
          // A square let down onto the plank's middle, its sides along the plank and across it.
          const Vec2 centre = at(175, 16);
          std::vector<Vec2> square;
          for (const auto& [u, v] : {std::pair{-1, -1}, std::pair{1, -1}, std::pair{1, 1}, std::pair{-1, 1}})
            square.push_back(rounded(d.x * 15 * u + in.x * 15 * v, d.y * 15 * u + in.y * 15 * v));
          const physics::EntityId box = b->world.createEntity(physics::Convex(square));
          b->world.insert(box, b->stage.part(f), centre, 0);
          for (int frame = 0; frame < 10; ++frame) b->world.solve();
          b->world.setPlatformMotion(id, rounded(-in.x * speed, -in.y * speed));
          const int frames = 400 / speed + 4;
          for (int frame = 0; frame < frames; ++frame) {
            b->world.solve();
            ASSERT_EQ(overlaps(b->world, id), "") << "frame " << frame;
          }
          const physics::PlatformView p = b->world.platform(id);
          EXPECT_EQ(p.part, edge.target) << "the plank did not go over";
          // Standing on it: its centre 15 units over the plank (and up to two for whole units on a
          // tilted line), not slid off it (the plank's ends are rounded, so it slopes a little).
          bool standing = false;
          for (const physics::InstanceView i : b->world.entity(box).instances()) {
            if (i.part != p.part) continue;
            const physics::Segment& s = p.lines[0].segment;
            const double ax = s.a.x, ay = s.a.y, dx = s.b.x - ax, dy = s.b.y - ay, len = std::hypot(dx, dy);
            const double along = ((i.position.x - ax) * dx + (i.position.y - ay) * dy) / len;
            const double across = std::abs((i.position.x - ax) * dy - (i.position.y - ay) * dx) / len;
            standing = along > 15 && along < len - 15 && across > 14 && across < 17.5;
            if (!standing) ADD_FAILURE() << "the box is " << across << " off the plank, " << along << " along it";
          }
          EXPECT_TRUE(standing) << "the box is not on the plank's face";
          EXPECT_EQ(rules.crushes, 0);
          ++runs;
          b->world.destroyPlatform(id);
          b->world.destroyEntity(box);
        }
  }
  EXPECT_GT(runs, 300);
}

// Driven straight across a face of the cube, a platform goes round the cube's belt (four edges, four
// faces) and comes back to its own face where it started, to the unit: its motion is turned exactly
// at each edge (whole units a frame that add up to it), its lines move rigidly.
TEST(PlatformCrossing, AroundTheCubesBeltAndBackToTheUnit) {
  auto b = build(stage::Solid::Hexahedron);
  int runs = 0;
  for (size_t f = 0; f < b->stage.faceCount(); ++f)
    for (const Vec2 direction : {Vec2{1, 0}, Vec2{0, 1}, Vec2{-1, 0}, Vec2{0, -1}})
      for (const int speed : {5, 15, 40}) {
        SCOPED_TRACE(::testing::Message()
                     << "face " << f << " direction " << direction.x << "," << direction.y << " speed " << speed);
        // A short wall across the way it goes, near the face's middle.
        const std::vector<Vec2>& c = b->stage.faces[f].corners;
        ASSERT_EQ(c.size(), 4u);
        const Vec2 mid{(c[0].x + c[2].x) / 2, (c[0].y + c[2].y) / 2};
        const physics::PlatformLine wall{{{mid.x - 40 * direction.y, mid.y - 40 * direction.x},
                                          {mid.x + 40 * direction.y, mid.y + 40 * direction.x}}};
        const physics::PlatformId id = b->world.createPlatform(b->stage.part(f), std::span(&wall, 1));
        b->world.setPlatformMotion(id, {direction.x * speed, direction.y * speed});
        std::vector<physics::MapPartId> visited{b->stage.part(f)};
        for (int frame = 0; frame < 4 * kEdge / speed; ++frame) {
          b->world.solve();
          if (b->world.platform(id).part != visited.back()) visited.push_back(b->world.platform(id).part);
        }
        const physics::PlatformView p = b->world.platform(id);
        EXPECT_EQ(visited.size(), 5u) << "four edges crossed";
        EXPECT_EQ(p.part, b->stage.part(f));
        EXPECT_EQ(p.lines[0].segment.a, wall.segment.a);
        EXPECT_EQ(p.lines[0].segment.b, wall.segment.b);
        EXPECT_EQ(p.motion, (Vec2{direction.x * speed, direction.y * speed}));
        EXPECT_TRUE(p.copies.empty());
        b->world.destroyPlatform(id);
        ++runs;
      }
  EXPECT_EQ(runs, 72);
}

namespace {

// Whether lines that reach over one edge of the platform's face (by more than 6 units: the copy's
// reach and rounding), and over no other at all, are also on the face beyond: it has a copy there.
bool onTheFaceBeyond(const physics::World& w, const physics::PlatformView& p) {
  std::optional<physics::MapPartId> over;
  double deepest = 0;
  for (const physics::PlatformLine& l : p.lines)
    for (const Vec2 q : {l.segment.a, l.segment.b}) {
      for (const Edge& e : edgesOf(w, p.part)) {
        const double depth = -((double(q.x) - e.seg.a.x) * e.in.x + (double(q.y) - e.seg.a.y) * e.in.y);
        if (depth <= 0) continue;
        if (over && *over != e.target) return true;  // over two edges: one copy, either way
        over = e.target, deepest = std::max(deepest, depth);
      }
    }
  return deepest <= 6 || std::any_of(p.copies.begin(), p.copies.end(),
                                     [&](const physics::PlatformCopyView& c) { return c.part == *over; });
}

// The parts a body has an instance in.
std::set<physics::MapPartId> partsOf(const physics::World& w, uint32_t index) {
  std::set<physics::MapPartId> parts;
  for (const physics::EntityId e : w.entities())
    if (e.index == index)
      for (const physics::InstanceView& i : w.entity(e).instances()) parts.insert(i.part);
  return parts;
}

// Where a copy in part `to` made at the frame's start was placed: the platform's lines then (in part
// `from`), carried over the warp edge between the two parts (along it and across it, as the face
// beyond lies; the engine maps them exactly and rounds to the nearest unit).
std::vector<physics::Segment> placedCopy(const physics::World& w, const std::vector<physics::PlatformLine>& lines,
                                         physics::MapPartId from, physics::MapPartId to) {
  std::vector<physics::Segment> placed;
  for (const Edge& e : edgesOf(w, from)) {
    if (e.target != to) continue;
    const Vec2d inBeyond{e.td.y, -e.td.x};  // into the face beyond (to the edge's right there)
    auto map = [&](Vec2 q) {
      const double x = double(q.x) - e.seg.a.x, y = double(q.y) - e.seg.a.y;
      const double along = x * e.d.x + y * e.d.y, depth = x * e.in.x + y * e.in.y;
      return rounded(e.targetSeg.a.x + along * e.td.x - depth * inBeyond.x,
                     e.targetSeg.a.y + along * e.td.y - depth * inBeyond.y);
    };
    for (const physics::PlatformLine& l : lines)
      if (l.kind == physics::LineKind::Solid) placed.push_back({map(l.segment.a), map(l.segment.b)});
    break;
  }
  return placed;
}

// Whether the polygon is in one of a copy's lines as placed (placedCopy), to within a unit: the
// engine maps in Q30, the test in doubles.
bool inPlacedCopy(std::span<const Vec2> verts, std::span<const physics::Segment> placed) {
  for (const physics::Segment& l : placed)
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        if (physics::overlapsInterior(verts, {{l.a.x + dx, l.a.y + dy}, {l.b.x + dx, l.b.y + dy}})) return true;
  return false;
}

// Each body's instances: their parts and world vertices.
using Instances = std::map<uint32_t, std::vector<std::pair<physics::MapPartId, std::vector<Vec2>>>>;
Instances instancesOf(const physics::World& w) {
  Instances all;
  for (const physics::EntityId e : w.entities())
    for (const physics::InstanceView i : w.entity(e).instances()) {
      std::vector<Vec2> verts;
      for (const Vec2 v : i.shape) verts.push_back({i.position.x + v.x, i.position.y + v.y});
      all[e.index].push_back({i.part, verts});
    }
  return all;
}

struct SceneCounts {
  int crossings = 0, frames = 0, copyOverlaps = 0, passedThrough = 0, crushed = 0;
  int copyOverlapsCrushed = 0;  // in frames the platform said it was crushed
  int uncopiedCrossings = 0;    // crossings that left lines over another edge with no copy there
  int placedOver = 0;           // bodies a new copy was placed over (in its lines already)
  void add(const SceneCounts& o) {
    crossings += o.crossings, frames += o.frames, copyOverlaps += o.copyOverlaps, passedThrough += o.passedThrough;
    crushed += o.crushed, copyOverlapsCrushed += o.copyOverlapsCrushed, uncopiedCrossings += o.uncopiedCrossings;
    placedOver += o.placedOver;
  }
};

// Random platforms (one to three lines, solid or one-way, at any angle) driven every way over random
// solids (the five, random prisms and bipyramids) among random bodies, with random gravity, their
// motion changed now and then (in the part they are in): no body ever overlaps a solid platform
// line where the platform meets it (beside a vertex, one already in a copy's line is passed
// through, as is one a new copy is placed over), a platform is stopped only by a body it meets, and
// it moves its whole motion every frame unless Rules::crushed is called (one
// that crossed an edge since its motion was set: to within the unit its turned motion is rounded
// to, two the frame after it crossed). Turning ones also spin, about a point near their first line,
// by 1/16,384 to 1/32 of a turn a frame (set with the motion), and turn by all of it every frame
// unless Rules::crushed is called.
SceneCounts randomPlatformScenes(uint64_t seed, int scenes, bool turning) {
  platon::testing::Rng rng{seed};
  SceneCounts counts;
  int& crossings = counts.crossings;
  int& frames = counts.frames;
  int& copyOverlaps = counts.copyOverlaps;
  int& passedThrough = counts.passedThrough;
  for (int scene = 0; scene < scenes; ++scene) {
    SCOPED_TRACE(::testing::Message() << "scene " << scene);
    auto b = randomSolid(rng);
    CountCrushes rules;
    b->world.setRules(&rules);
    const size_t faces = b->stage.faceCount();
    for (size_t f = 0; f < faces; ++f) {
      const double a = rng.uniform(0, 2 * M_PI), g = rng.between(0, 2) == 0 ? 0 : rng.uniform(5000, 30000);
      b->world.mapPart(b->stage.part(f)).setGravity({std::llround(std::cos(a) * g), std::llround(std::sin(a) * g)});
    }
    // The platform first, then bodies wherever they fit.
    const size_t home = static_cast<size_t>(rng.between(0, static_cast<int>(faces) - 1));
    const Vec2 at = insideFace(b->stage.faces[home], rng);
    std::vector<physics::PlatformLine> lines;
    const physics::LineKind kind = rng.between(0, 3) == 0 ? physics::LineKind::OneWay : physics::LineKind::Solid;
    if (rng.between(0, 2) == 0) {  // a cup, turned any way: bodies sit in it
      const double a = rng.uniform(0, 2 * M_PI), w = rng.uniform(60, 240), h = rng.uniform(30, 120);
      auto corner = [&](double u, double v) {
        return rounded(at.x + std::cos(a) * u - std::sin(a) * v, at.y + std::sin(a) * u + std::cos(a) * v);
      };
      const Vec2 c[4] = {corner(-w / 2, h), corner(-w / 2, 0), corner(w / 2, 0), corner(w / 2, h)};
      for (int k = 0; k < 3; ++k) lines.push_back({{c[k], c[k + 1]}, 0, kind});
    } else {
      const int n = rng.between(1, 3);
      for (int k = 0; k < n; ++k) {
        const double a = rng.uniform(0, 2 * M_PI), len = rng.uniform(40, 300);
        const Vec2 p{at.x + rng.between(-60, 60), at.y + rng.between(-60, 60)};
        lines.push_back({{p, rounded(p.x + std::cos(a) * len, p.y + std::sin(a) * len)}, 0, kind});
      }
    }
    const physics::PlatformId id = b->world.createPlatform(b->stage.part(home), lines);
    for (int k = 0; k < 12; ++k) {
      const size_t f = static_cast<size_t>(rng.between(0, static_cast<int>(faces) - 1));
      const physics::EntityId e =
          b->world.createEntity(rng.between(0, 1) ? physics::Convex::box(rng.between(6, 40), rng.between(6, 40))
                                                  : physics::Convex::regular(rng.between(3, 8), rng.between(8, 40)));
      try {
        b->world.insert(e, b->stage.part(f), insideFace(b->stage.faces[f], rng), 0);
      } catch (const physics::Error&) {
        b->world.destroyEntity(e);
      }
    }
    bool crossedSinceSet = false, crossed = false;
    std::vector<Overlap> was;
    for (int frame = 0; frame < 500; ++frame, ++frames) {
      if (frame % 97 == 0) {
        const double a = rng.uniform(0, 2 * M_PI),
                     speed = rng.between(0, 3) ? rng.uniform(1, 30) : rng.uniform(30, 600);
        b->world.setPlatformMotion(id, rounded(std::cos(a) * speed, std::sin(a) * speed));
        crossedSinceSet = false;
        if (turning) {
          const physics::PlatformView now = b->world.platform(id);
          const physics::Segment& s = now.lines[0].segment;
          const int32_t spin = rng.between(1 << 18, 1 << 27) * (rng.between(0, 1) ? 1 : -1);
          try {
            b->world.setPlatformSpin(id, {s.a.x + rng.between(-40, 40), s.a.y + rng.between(-40, 40)}, spin);
          } catch (const physics::Error&) {  // too costly a turn about a far point: slower
            b->world.setPlatformSpin(id, s.a, spin / 16);
          }
        }
      }
      const physics::PlatformView before = b->world.platform(id);
      const int crushesBefore = rules.crushes;
      rules.partsSeen.clear();
      rules.crushedBy.clear();
      const Instances atStart = instancesOf(b->world);
      // (a view's span follows the world's lines)
      const std::vector<physics::PlatformLine> linesBefore(before.lines.begin(), before.lines.end());
      b->world.solve();
      const physics::PlatformView p = b->world.platform(id);
      // The parts a body was in at the frame's start or is in at its end.
      auto partsAtEnds = [&](uint32_t body) {
        std::set<physics::MapPartId> parts = partsOf(b->world, body);
        if (const auto first = atStart.find(body); first != atStart.end())
          for (const auto& instance : first->second) parts.insert(instance.first);
        return parts;
      };
      // A body a new copy was placed over: in the lines there at the frame's start (they had come over
      // that edge with no copy, beside a vertex or just after crossing, when a body was in the way).
      auto placedOver = [&](const Overlap& o) {
        if (p.part != before.part || o.own) return false;
        const auto c = std::find_if(p.copies.begin(), p.copies.end(),
                                    [&](const physics::PlatformCopyView& q) { return q.part == o.part; });
        if (c == p.copies.end() || std::any_of(before.copies.begin(), before.copies.end(),
                                               [&](const physics::PlatformCopyView& q) { return q.part == o.part; }))
          return false;
        const auto body = atStart.find(o.entity);
        if (body == atStart.end()) return false;
        const std::vector<physics::Segment> placed = placedCopy(b->world, linesBefore, p.part, c->part);
        return std::any_of(body->second.begin(), body->second.end(), [&](const auto& instance) {
          return instance.first == o.part && inPlacedCopy(instance.second, placed);
        });
      };
      // Where the platform meets a body: never in its own part; in its copy's, only a body whose copy
      // was already in that line, that is or was beside a vertex (its copies there disagree with each
      // other, and with the platform's, by more than rounding: it left the platform's own part with
      // its copy there), or that a new copy was placed over: the platform passes through it.
      // Elsewhere: counted.
      const std::vector<Overlap> now = overlapsOf(b->world, id);
      size_t met = 0;
      const bool crushedNow = rules.crushes != crushesBefore;
      // Stopped only by what it meets: a body in a part where it has lines, its own or a copy's (at
      // the frame's start or end, or within it: it may cross, change its copy, or push the body over
      // an edge).
      for (const uint32_t body : rules.crushedBy) {
        std::set<physics::MapPartId> linesIn{before.part, p.part};
        for (const auto* v : {&before, &p})
          for (const physics::PlatformCopyView& c : v->copies) linesIn.insert(c.part);
        std::set<physics::MapPartId> bodyIn = partsAtEnds(body);
        bodyIn.insert(rules.partsSeen[body].begin(), rules.partsSeen[body].end());
        const bool meets =
            std::any_of(bodyIn.begin(), bodyIn.end(), [&](physics::MapPartId q) { return linesIn.count(q); });
        EXPECT_TRUE(meets) << "frame " << frame << ": crushed by entity " << body << ", nowhere the platform has lines";
        if (!meets) return counts;
      }
      for (const Overlap& o : now) {
        if (!o.met) {
          ++(crushedNow ? counts.copyOverlapsCrushed : copyOverlaps);
          continue;
        }
        ++met;
        // Already in one of its lines there (the whole platform passes through such a body where it
        // meets it; met there only since, it left the platform's own part with its copy there).
        const bool already = std::any_of(was.begin(), was.end(),
                                         [&](const Overlap& q) { return q.entity == o.entity && q.part == o.part; });
        // Beside a vertex: in three faces' parts at the frame's start or its end, over the frame (on
        // one face at its start and across another edge at its end: pushed or carried past a vertex
        // within the frame), or within it (pushed to a vertex by the platform, then off it on its
        // own step: its warp contacts say where it was).
        const std::set<physics::MapPartId> parts = partsAtEnds(o.entity);
        const std::set<physics::MapPartId>& within = rules.partsSeen[o.entity];
        const bool atVertex = parts.size() >= 3 || within.size() >= 3;
        const bool placed = !already && !atVertex && placedOver(o);
        EXPECT_TRUE(!o.own && (already || atVertex || placed)) << "frame " << frame << ": " << o.what;
        if (o.own || !(already || atVertex || placed)) return counts;
        ++passedThrough;
        counts.placedOver += placed;
      }
      was = now;
      EXPECT_EQ(b->world.countOverlaps(), met) << "frame " << frame;  // bodies, fixed lines, the platform
      if (b->world.countOverlaps() != met) return counts;
      const bool justCrossed = crossed;
      crossed = p.part != before.part;
      if (crossed) {
        ++crossings;
        crossedSinceSet = true;
        // Its copy over another edge of the face it came to is made at once, unless a body is in its
        // way (counted: the next frame places it, over the body).
        if (!onTheFaceBeyond(b->world, p)) ++counts.uncopiedCrossings;
        continue;
      }
      if (crushedNow) {
        ++counts.crushed;
        continue;
      }
      EXPECT_TRUE(onTheFaceBeyond(b->world, p)) << "frame " << frame << ": lines over an edge with no copy there";
      EXPECT_EQ(static_cast<physics::Angle>(p.angle - before.angle), static_cast<physics::Angle>(p.spin))
          << "frame " << frame << ": turned short of its spin, and no crushed call";
      const Vec2 moved{p.offset.x - before.offset.x, p.offset.y - before.offset.y};
      // Crossed: whole units a frame about its turned motion (the first frame after the crossing
      // also moves what the frame before left below a unit, turned with it).
      if (crossedSinceSet)
        EXPECT_LE(std::max(std::abs(moved.x - p.motion.x), std::abs(moved.y - p.motion.y)), justCrossed ? 2 : 1)
            << "frame " << frame;
      else
        EXPECT_EQ(moved, p.motion) << "frame " << frame << ": moved short of its motion, and no crushed call";
    }
  }
  return counts;
}

// The scenes of each seed, summed; what holds for both families: a body's copy in a copy's line,
// where the platform meets the body elsewhere, only where rounding in two frames leaves no free
// place to lift it to (20 frames in 300,000 over 600 scenes; counted apart: frames the platform is
// crushed, a body wedged between two of its lines at an edge holding it there, its copy in the
// copy's lines, until the platform's motion changes); a crossing that leaves lines over another edge
// uncopied only for a body in the copy's way (a copy made only the next frame left about 3 crossings
// in 10 so); a copy placed over a body (its lines came over the edge with no copy) a few times in
// 100,000 frames.
SceneCounts randomFamily(std::initializer_list<std::pair<uint64_t, int>> seeds, bool turning) {
  SceneCounts c;
  for (const auto& [seed, scenes] : seeds) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    c.add(randomPlatformScenes(seed, scenes, turning));
  }
  EXPECT_LE(c.copyOverlaps, c.frames / 1000);
  EXPECT_LE(c.uncopiedCrossings, c.crossings / 20);
  EXPECT_LE(c.placedOver, c.frames / 5000);
  std::printf(
      "%d frames, %d crossings (%d with lines over another edge uncopied), %d crushed, %d overlaps of a body's copy "
      "elsewhere (%d more in frames it was crushed), %d frames a body in a copy's line was passed through (%d copies "
      "placed over one)\n",
      c.frames, c.crossings, c.uncopiedCrossings, c.crushed, c.copyOverlaps, c.copyOverlapsCrushed, c.passedThrough,
      c.placedOver);
  return c;
}

}  // namespace

TEST(PlatformCrossing, RandomPlatformsOverRandomSolidsNeverOverlapAndNeverStopSilently) {
  // Seed 9101's 153rd scene and 31337's 206th push a body to a vertex (in three faces' parts after
  // the platform moves), and the body's own step then takes it off the face the platform meets it
  // on, into the copy's line there: passed through, as beside a vertex.
  const SceneCounts c = randomFamily({{4242, 100}, {9101, 160}, {31337, 210}}, false);
  EXPECT_GT(c.crossings, 2000);
}

// The same with the platforms turning as they go: their copies turn with them over the edges.
TEST(PlatformCrossing, RandomTurningPlatformsOverRandomSolidsNeverOverlapAndNeverStopSilently) {
  // Seed 9101's fifth scene carries a rider through a vertex into the copy's line; 31337's 127th
  // pushes a body beside a vertex out of the line's place in one part and back in from the other;
  // 4242's 120th carries a rider from one face past a vertex onto two others within a frame (a
  // copy of it lands in the cup's copy line: passed through, as beside a vertex).
  const SceneCounts c = randomFamily({{4343, 100}, {9101, 60}, {31337, 130}, {4242, 130}}, true);
  EXPECT_GT(c.crossings, 300);
  EXPECT_LE(c.crushed, c.frames / 10);
}

// A plank across a vertex's corner, over both its edges (further over the first: its copy is
// there), with a box where its lines reach beyond the second: one copy at most, so the box is in its
// lines with no copy there. Driven further over the second edge, its copy goes there, over the box
// (cleared off its line, or passed through, as a body left in a copy's line); driven back, it comes
// back. Before, that copy was not made, and the plank
// stopped with a crushed call every frame, whichever way it was driven, for as long as the box
// stayed. Every vertex of every face of the five solids.
TEST(PlatformCrossing, APlankOverTwoEdgesAtAVertexIsNotHeldByABoxItReachesBeyondTheSecond) {
  int corners = 0, placedOver = 0;
  for (const stage::Solid solid : stage::kSolids) {
    auto b = build(solid);
    CountCrushes rules;
    b->world.setRules(&rules);
    for (size_t f = 0; f < b->stage.faceCount(); ++f) {
      const std::vector<Edge> edges = edgesOf(b->world, b->stage.part(f));
      for (size_t k = 0; k < edges.size(); ++k) {
        const Edge& e1 = edges[k];
        const Edge& e2 = edges[(k + 1) % edges.size()];  // from the vertex e1 ends at
        SCOPED_TRACE(::testing::Message() << "solid " << int(solid) << " face " << f << " vertex " << k);
        // 80 units from the vertex along each edge: 35 beyond the first, 30 beyond the second, where
        // a box 40 units wide is (its line still in it when the copy goes there).
        const Vec2 p1 = rounded(e1.seg.b.x - e1.d.x * 80 - e1.in.x * 35, e1.seg.b.y - e1.d.y * 80 - e1.in.y * 35);
        const Vec2 p2 = rounded(e2.seg.a.x + e2.d.x * 80 - e2.in.x * 30, e2.seg.a.y + e2.d.y * 80 - e2.in.y * 30);
        const Vec2d inB{e2.td.y, -e2.td.x};  // into the face beyond the second edge
        const Vec2 boxAt =
            rounded(e2.targetSeg.a.x + e2.td.x * 80 + inB.x * 30, e2.targetSeg.a.y + e2.td.y * 80 + inB.y * 30);
        const physics::PlatformLine plank{{p1, p2}};
        const physics::PlatformId id = b->world.createPlatform(b->stage.part(f), std::span(&plank, 1));
        const physics::EntityId box = b->world.createEntity(physics::Convex::box(20, 20));
        b->world.insert(box, e2.target, boxAt, 0);
        ASSERT_EQ(b->world.platform(id).copies.size(), 1u);
        ASSERT_EQ(b->world.platform(id).copies[0].part, e1.target);
        const int crushesBefore = rules.crushes;
        // Over the second edge until its copy is there (and two frames more), then back as far.
        int shortFrames = 0;  // frames it did not move its motion on its face
        bool boxInCopy = false;
        auto drive = [&](Vec2 motion) {
          b->world.setPlatformMotion(id, motion);
          const physics::PlatformView before = b->world.platform(id);
          const std::vector<physics::PlatformLine> linesBefore(before.lines.begin(), before.lines.end());
          const Instances boxBefore = instancesOf(b->world);
          b->world.solve();
          const physics::PlatformView p = b->world.platform(id);
          shortFrames +=
              p.part != before.part || Vec2{p.offset.x - before.offset.x, p.offset.y - before.offset.y} != motion;
          const bool there = !p.copies.empty() && p.copies[0].part == e2.target;
          const bool made = there && (before.copies.empty() || before.copies[0].part != e2.target);
          if (made)  // the copy as placed, over the box
            boxInCopy = boxInCopy || inPlacedCopy(boxBefore.at(box.index)[0].second,
                                                  placedCopy(b->world, linesBefore, p.part, p.copies[0].part));
          return there;
        };
        const Vec2 out = rounded(-e2.in.x * 5, -e2.in.y * 5);
        int frames = 0, after = -1;
        while (frames < 40 && after < 2) {
          ++frames;
          if (drive(out) || after >= 0) ++after;
        }
        for (int frame = 0; frame < frames; ++frame) drive({-out.x, -out.y});
        EXPECT_EQ(shortFrames, 0);
        EXPECT_EQ(rules.crushes, crushesBefore) << rules.last;
        EXPECT_EQ(b->world.platform(id).offset, (Vec2{0, 0}));
        placedOver += boxInCopy;
        ++corners;
        b->world.destroyPlatform(id);
        b->world.destroyEntity(box);
      }
    }
  }
  EXPECT_EQ(corners, 4 * 3 + 6 * 4 + 8 * 3 + 12 * 5 + 20 * 3);
  EXPECT_EQ(placedOver, corners);  // the copy went over the box every time
}

// An audit's case: a two-line platform beside a tetrahedron's vertex, a box resting at the vertex in
// the two faces beyond. Driven back the frame after it came near, its copy moves to the other face
// and is made where the box is (the box in one of its lines). The whole platform passes through
// such a body until it is out of its lines: before, its other line met the box there and the
// platform was stopped by it every frame, driven either way, for good.
TEST(PlatformCrossing, ABodyInACopysLineIsPassedThroughByTheWholePlatform) {
  for (const Vec2 back : {Vec2{-47, 18}, Vec2{-30, -10}, Vec2{-40, 0}, Vec2{-47, -5}, Vec2{-40, 10}}) {
    SCOPED_TRACE(::testing::Message() << "driven back " << back.x << "," << back.y);
    auto b = build(stage::Solid::Tetrahedron, 530);
    CountCrushes rules;
    b->world.setRules(&rules);
    const std::vector<physics::PlatformLine> lines{{{{441, -9}, {483, 85}}}, {{{483, 85}, {486, 23}}}};
    const physics::PlatformId id = b->world.createPlatform(b->stage.part(0), lines);
    const physics::EntityId box = b->world.createEntity(physics::Convex::box(16, 13));
    b->world.insert(box, b->stage.part(0), {521, 11}, 0);
    b->world.setPlatformMotion(id, {47, -18});
    b->world.solve();
    b->world.setPlatformMotion(id, back);
    int frames = 0;
    bool crossed = false, boxInCopy = false;
    for (; frames < 12 && rules.crushes == 0; ++frames) {
      const physics::PlatformView before = b->world.platform(id);
      const std::vector<physics::PlatformLine> linesBefore(before.lines.begin(), before.lines.end());
      const Instances boxBefore = instancesOf(b->world);
      b->world.solve();
      const physics::PlatformView p = b->world.platform(id);
      // A copy made this frame over the box (in its lines as placed), where the platform meets it.
      for (const physics::PlatformCopyView& c : p.copies) {
        const bool made = p.part == before.part && std::none_of(before.copies.begin(), before.copies.end(),
                                                                [&](const auto& q) { return q.part == c.part; });
        for (const auto& [part, verts] : boxBefore.at(box.index))
          boxInCopy = boxInCopy || (made && part == c.part &&
                                    inPlacedCopy(verts, placedCopy(b->world, linesBefore, p.part, c.part)));
      }
      // Its whole motion (once it crossed, whole units about its motion turned through the warp).
      const Vec2 moved{p.offset.x - before.offset.x, p.offset.y - before.offset.y};
      crossed = crossed || p.part != before.part;
      if (p.part == before.part) {
        EXPECT_LE(std::max(std::abs(moved.x - p.motion.x), std::abs(moved.y - p.motion.y)), crossed ? 2 : 0)
            << "frame " << frames;
      }
    }
    EXPECT_EQ(rules.crushes, 0) << rules.last << " at frame " << frames;
    EXPECT_TRUE(boxInCopy) << "no copy was made over the box";
  }
}

// A platform made already over an edge, where a body stands on the face beyond, is refused (an
// Error naming the line, the body and the part), as one made over a body of its own part is; the
// world is as it was. Every edge of every solid.
TEST(PlatformCrossing, APlatformMadeOverABodyBeyondAnEdgeIsRefused) {
  int refused = 0;
  for (const stage::Solid solid : stage::kSolids) {
    auto b = build(solid);
    for (size_t f = 0; f < b->stage.faceCount(); ++f)
      for (const Edge& edge : edgesOf(b->world, b->stage.part(f))) {
        // A box 80 units into the face beyond, and a line from 100 units inside this face to 150
        // beyond the edge, through where the box is.
        const double mx = (double(edge.seg.a.x) + edge.seg.b.x) / 2, my = (double(edge.seg.a.y) + edge.seg.b.y) / 2;
        const double tx = (double(edge.targetSeg.a.x) + edge.targetSeg.b.x) / 2,
                     ty = (double(edge.targetSeg.a.y) + edge.targetSeg.b.y) / 2;
        const physics::EntityId box = b->world.createEntity(physics::Convex::box(10, 10));
        b->world.insert(box, edge.target, rounded(tx + edge.td.y * 80, ty - edge.td.x * 80), 0);
        const physics::PlatformLine line{
            {rounded(mx + edge.in.x * 100, my + edge.in.y * 100), rounded(mx - edge.in.x * 150, my - edge.in.y * 150)}};
        const uint64_t hash = b->world.stateHash();
        const size_t platforms = b->world.platforms().size();
        try {
          b->world.createPlatform(b->stage.part(f), std::span(&line, 1));
          ADD_FAILURE() << "made over a body beyond the edge to part " << edge.target;
        } catch (const physics::Error& e) {
          EXPECT_NE(std::string(e.what()).find("createPlatform: line 0 would overlap entity " +
                                               std::to_string(box.index) + " in map part " +
                                               std::to_string(edge.target) + ", beyond a warp edge its lines reach"),
                    std::string::npos)
              << e.what();
          ++refused;
        }
        EXPECT_EQ(b->world.stateHash(), hash);
        EXPECT_EQ(b->world.platforms().size(), platforms);
        b->world.destroyEntity(box);
      }
  }
  EXPECT_EQ(refused, 180);
}
