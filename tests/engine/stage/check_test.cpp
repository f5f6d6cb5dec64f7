// `platon check` over families of levels: walled-in goals are refused and open ones accepted on
// every solid at face sizes from 4,096 to 2^24 (the search's cells are sized by the walls, not the
// face); a start or goal near an edge needs room from the walls across it; faces too narrow for
// the player are warned of.
#include <gtest/gtest.h>

#include "platon/stage/level.h"
#include "platon/stage/level_check.h"
#include "platon/stage/mesh.h"
#include "platon/testing/rng.h"

using namespace platon;
using physics::Vec2;

namespace {

struct Point {
  double x, y;
};

Point centreOf(const stage::StageFace& face) {
  Point c{0, 0};
  for (const Vec2 p : face.corners) c.x += p.x, c.y += p.y;
  return {c.x / double(face.corners.size()), c.y / double(face.corners.size())};
}

Vec2 unit(Point p) { return {static_cast<int32_t>(std::lround(p.x)), static_cast<int32_t>(std::lround(p.y))}; }

stage::Level emptyLevel(stage::Solid solid, int32_t size, const stage::Stage& s) {
  stage::Level level;
  level.file = "c.level";
  level.solid = solid;
  level.size = size;
  level.faces.resize(s.faceCount());
  int line = 10;
  for (auto& f : level.faces) f.sourceLine = line++;
  level.start = {0, unit(centreOf(s.faces[0])), 2, 1};
  level.goal = {1, unit(centreOf(s.faces[1])), 3, 1};
  return level;
}

// A square of walls of half side `half` round the goal, turned by `angle`; `gap` > 0 leaves that
// much of one side open (optionally shut by a door instead).
void wallIn(stage::Level& level, double half, double angle, double gap, bool door) {
  const Point g{double(level.goal.position.x), double(level.goal.position.y)};
  auto at = [&](double u, double v) { return unit({g.x + u * std::cos(angle) - v * std::sin(angle), g.y + u * std::sin(angle) + v * std::cos(angle)}); };
  auto& lines = level.faces[size_t(level.goal.face)].lines;
  const Point square[4] = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
  for (int k = 0; k < 4; ++k) {
    const Point a = square[k], b = square[(k + 1) % 4];
    if (k == 0 && gap > 0) {  // the bottom side, with an opening in its middle
      lines.push_back({at(a.x, a.y), at(-gap / 2, a.y)});
      lines.push_back({at(gap / 2, a.y), at(b.x, b.y)});
      if (door) lines.push_back({at(-gap / 2, a.y), at(gap / 2, a.y), false, stage::kTagDoor + 1});
      continue;
    }
    lines.push_back({at(a.x, a.y), at(b.x, b.y)});
  }
  for (auto& l : lines) l.sourceLine = 20;
}

// The goal on face 1 walled in on every solid, at every face size the audit found wrong (the grid
// of size / 64 missed walls between its cell centres from 6,400 units, blocked nothing from 12,800,
// and missed the goal's own cell from 65,536), with random wall squares and turns: refused; the
// same with a gap of 400 units (a tenth of the side for sides of millions), or a door in the gap:
// accepted.
TEST(Check, WalledInGoalsAreRefusedAndOpenOnesAcceptedAtEverySize) {
  platon::testing::Rng rng{64};
  for (const int32_t size : {4096, 6400, 8192, 13000, 65536, 1 << 20, 1 << 24})
    for (const stage::Solid solid : stage::kSolids) {
      const stage::Stage s = stage::platonicStage(solid, size);
      for (int i = 0; i < 3; ++i) {
        SCOPED_TRACE(std::string(stage::solidName(solid)) + " size " + std::to_string(size) + " case " + std::to_string(i));
        // Wall squares from just round the goal to a fifth of the face (long walls at 2^24).
        const double inradius = 0.28 * size;  // the pentagon's and triangle's inner circles are wider
        const double half = i == 2 ? 0.2 * inradius : rng.uniform(300, std::min(1200.0, 0.5 * inradius));
        const double angle = rng.uniform(0, M_PI / 2);
        stage::Level sealed = emptyLevel(solid, size, s), open = sealed, door = sealed;
        const double gap = std::max(400.0, 0.1 * half);  // long walls are searched with coarser cells
        wallIn(sealed, half, angle, 0, false);
        wallIn(open, half, angle, gap, false);
        wallIn(door, half, angle, gap, true);
        for (const stage::Level* l : {&sealed, &open, &door}) {
          stage::checkLevelOnStage(*l, s);  // a valid level: only reachability is in question
        }
        const stage::CheckReport refused = stage::checkLevel(sealed, s);
        ASSERT_EQ(refused.errors.size(), 1u);
        EXPECT_NE(refused.errors[0].message.find("no path reaches the goal"), std::string::npos);
        EXPECT_TRUE(stage::checkLevel(open, s).errors.empty());
        EXPECT_TRUE(stage::checkLevel(door, s).errors.empty());
      }
    }
}

// The open level of the audit (floors on faces 0 and 1, the goal on face 1 over an edge) at every
// size from 64 units: accepted (from 65,536 units it was "no path reaches the goal").
TEST(Check, AnOpenLevelIsAcceptedAtEverySize) {
  for (const int32_t size : {64, 200, 1000, 4096, 6400, 8192, 13000, 65536, 1 << 20, 1 << 24})
    for (const stage::Solid solid : stage::kSolids) {
      const stage::Stage s = stage::platonicStage(solid, size);
      stage::Level level = emptyLevel(solid, size, s);
      const double floorY = std::min(0.1 * size, 512.0);
      for (int f = 0; f < 2; ++f) {
        const auto& c = s.faces[size_t(f)].corners;
        level.faces[size_t(f)].lines.push_back({unit({0.3 * c[1].x, floorY}), unit({0.7 * c[1].x, floorY}), false, 0, 20, 1});
      }
      if (size < 400) level.faces[0].lines.clear(), level.faces[1].lines.clear();  // no room for a floor and the player
      try {
        stage::checkLevelOnStage(level, s);
      } catch (const stage::StageError&) {
        continue;  // too small a face for the start or the goal's square: not this test's question
      }
      EXPECT_TRUE(stage::checkLevel(level, s).errors.empty()) << stage::solidName(solid) << " size " << size;
    }
}

// A start or goal near an edge of its face needs its room from the walls just across that edge
// too: on every edge of every solid, at random distances, a wall parallel to the edge on the
// neighbour is refused when the two distances add up to less than 100, and named there.
TEST(Check, TheStartNeedsRoomAcrossAnEdge) {
  platon::testing::Rng rng{21};
  int refused = 0, accepted = 0;
  for (const stage::Solid solid : stage::kSolids) {
    const stage::Stage s = stage::platonicStage(solid, 4096);
    for (size_t k = 0; k < s.faces[0].corners.size(); ++k) {
      const auto& c = s.faces[0].corners;
      const Vec2 a = c[k], b = c[(k + 1) % c.size()];
      const double ex = double(b.x) - a.x, ey = double(b.y) - a.y, len = std::hypot(ex, ey);
      const double nx = -ey / len, ny = ex / len;  // into the face
      const double here = rng.uniform(5, 95), there = rng.uniform(5, 95), t = rng.uniform(0.35, 0.65);
      stage::Level level = emptyLevel(solid, 4096, s);
      level.start.position = unit({a.x + t * ex + here * nx, a.y + t * ey + here * ny});
      const auto [g, j] = s.faces[0].neighbours[k];
      level.goal = {g == 1 ? 2 : 1, unit(centreOf(s.faces[size_t(g == 1 ? 2 : 1)])), 3, 1};
      // On the neighbour, its edge j runs b -> a: the start's foot is at 1 - t along it.
      const auto& d = s.faces[size_t(g)].corners;
      const Vec2 p = d[size_t(j)], q = d[(size_t(j) + 1) % d.size()];
      const double fx = double(q.x) - p.x, fy = double(q.y) - p.y, flen = std::hypot(fx, fy);
      const double mx = -fy / flen, my = fx / flen;
      const Point foot{p.x + (1 - t) * fx + there * mx, p.y + (1 - t) * fy + there * my};
      level.faces[size_t(g)].lines.push_back({unit({foot.x - 300 * fx / flen, foot.y - 300 * fy / flen}),
                                              unit({foot.x + 300 * fx / flen, foot.y + 300 * fy / flen}), false, 0, 30, 1});
      std::string why = "(accepted)";
      try {
        stage::checkLevelOnStage(level, s);
      } catch (const stage::StageError& e) {
        why = e.what();
      }
      SCOPED_TRACE(std::string(stage::solidName(solid)) + " edge " + std::to_string(k) + ": " + std::to_string(here) + " + " +
                   std::to_string(there) + ": " + why);
      if (here + there < 98) {
        EXPECT_NE(why.find("is inside a wall: "), std::string::npos);
        EXPECT_NE(why.find("from the segment on line 30 (on face " + std::to_string(g) + ", across the edge)"), std::string::npos);
        ++refused;
      } else if (here + there > 102) {
        EXPECT_EQ(why, "(accepted)");
        ++accepted;
      }
    }
  }
  EXPECT_GT(refused, 5);
  EXPECT_GT(accepted, 5);
}

// Faces narrower than the default player are warned of, once for the level, naming the narrowest:
// a needle of a mesh, and every face of a small stage.
TEST(Check, FacesTooNarrowForThePlayerAreWarnedOf) {
  stage::MeshData needle;
  needle.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.8, 0}, {0.5, 0.3, 1000}};
  needle.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  const stage::Stage s = stage::stageFromPolyhedron(stage::polyhedronFromMesh(needle, 4096));
  stage::Level level = stage::parseLevel("MESH needle.obj\n0 0 0\n1 0 0\n4096\n%\n%\n%\n%\n", "n.level");
  bool warned = false;
  for (const auto& w : stage::checkLevel(level, s).warnings)
    if (w.message.find("narrower than the default player") != std::string::npos) {
      warned = true;
      EXPECT_EQ(w.message.find("face"), 0u) << w.message;
    }
  EXPECT_TRUE(warned);
  const stage::Level small = stage::parseLevel("TETRAHEDRON\n0 10 10\n1 10 10\n150\n%\n%\n%\n%\n", "t.level");
  const auto report = stage::checkLevel(small, stage::platonicStageOf(small));
  bool all = false;
  for (const auto& w : report.warnings)
    all = all || (stage::describe(w.where) + w.message) ==
                     "t.level:5:1: faces 0, 1, 2, 3 are narrower than the default player (192 units across); the narrowest, face 0, "
                     "is 129 units wide";
  EXPECT_TRUE(all);
  const stage::Level big = stage::parseLevel("TETRAHEDRON\n0 1000 600\n1 1000 600\n4096\n%\n%\n%\n%\n", "t.level");
  for (const auto& w : stage::checkLevel(big, stage::platonicStageOf(big)).warnings)
    EXPECT_EQ(w.message.find("narrower"), std::string::npos) << w.message;
}

}  // namespace
