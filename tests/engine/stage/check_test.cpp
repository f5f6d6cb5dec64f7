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
  auto at = [&](double u, double v) {
    return unit({g.x + u * std::cos(angle) - v * std::sin(angle), g.y + u * std::sin(angle) + v * std::cos(angle)});
  };
  auto& lines = level.faces[size_t(level.goal.face)].lines;
  const Point square[4] = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};
  for (int k = 0; k < 4; ++k) {
    const Point a = square[k], b = square[(k + 1) % 4];
    if (k == 0 && gap > 0) {  // the bottom side, with an opening in its middle
      lines.push_back({at(a.x, a.y), at(-gap / 2, a.y)});
      lines.push_back({at(gap / 2, a.y), at(b.x, b.y)});
      if (door) lines.push_back({at(-gap / 2, a.y), at(gap / 2, a.y), false, stage::gameTags()->number("door") + 1});
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
        SCOPED_TRACE(std::string(stage::solidName(solid)) + " size " + std::to_string(size) + " case " +
                     std::to_string(i));
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
        ASSERT_EQ(refused.errors.size(), 1u) << (refused.warnings.empty() ? "" : refused.warnings.back().message);
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
        level.faces[size_t(f)].lines.push_back(
            {unit({0.3 * c[1].x, floorY}), unit({0.7 * c[1].x, floorY}), false, 0, 20, 1});
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
                                              unit({foot.x + 300 * fx / flen, foot.y + 300 * fy / flen}), false, 0, 30,
                                              1});
      std::string why = "(accepted)";
      try {
        stage::checkLevelOnStage(level, s);
      } catch (const stage::StageError& e) {
        why = e.what();
      }
      SCOPED_TRACE(std::string(stage::solidName(solid)) + " edge " + std::to_string(k) + ": " + std::to_string(here) +
                   " + " + std::to_string(there) + ": " + why);
      if (here + there < 98) {
        EXPECT_NE(why.find("is inside a wall: "), std::string::npos);
        EXPECT_NE(why.find("from the segment on line 30 (on face " + std::to_string(g) + ", across the edge)"),
                  std::string::npos);
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
                     "t.level:5:1: faces 0, 1, 2, 3 are narrower than the default player (192 units across); the "
                     "narrowest, face 0, "
                     "is 129 units wide";
  EXPECT_TRUE(all);
  const stage::Level big = stage::parseLevel("TETRAHEDRON\n0 1000 600\n1 1000 600\n4096\n%\n%\n%\n%\n", "t.level");
  for (const auto& w : stage::checkLevel(big, stage::platonicStageOf(big)).warnings)
    EXPECT_EQ(w.message.find("narrower"), std::string::npos) << w.message;
}

}  // namespace

namespace {

// The walls of a room's corner on the face of `p`, near its centre at a random place (so at every
// alignment to the search's cells): a floor from the corner, a wall up from it when `twoWalls`,
// each `length` long; `p` in the room, 100 to 110 units from each (a single floor: half way along
// it). `square`: turned by a multiple of 90 degrees and exactly 100 units from each, as the
// audit's room; otherwise at a random turn.
void putInACorner(stage::Level& level, const stage::Stage& s, stage::LevelPoint& p, bool twoWalls, bool square,
                  platon::testing::Rng& rng) {
  const double length = std::min(800.0, 0.12 * level.size);
  const Point c = centreOf(s.faces[size_t(p.face)]);
  const double angle = square ? rng.between(0, 3) * M_PI / 2 : rng.uniform(0, 2 * M_PI), spread = 0.02 * level.size;
  const Point o{c.x + rng.uniform(-spread, spread), c.y + rng.uniform(-spread, spread)};
  const double cosine = std::round(std::cos(angle) * 1e12) / 1e12, sine = std::round(std::sin(angle) * 1e12) / 1e12;
  const Vec2 corner = unit(o);
  auto at = [&](double u, double v) {
    return unit({corner.x + u * cosine - v * sine, corner.y + u * sine + v * cosine});
  };
  auto& lines = level.faces[size_t(p.face)].lines;
  lines.push_back({at(0, 0), at(length, 0), false, 0, 20, 1});
  if (twoWalls) lines.push_back({at(0, 0), at(0, length), false, 0, 21, 1});
  const double fromFloor = square ? 100 : rng.uniform(100.5, 110), fromWall = !twoWalls ? length / 2
                                                                              : square  ? 100
                                                                                        : rng.uniform(100.5, 110);
  p.position = at(fromWall, fromFloor);
}

std::string findings(const stage::CheckReport& report) {
  std::string out;
  for (const auto& e : report.errors) out += "error: " + e.message + "\n";
  for (const auto& w : report.warnings) out += "warning: " + w.message + "\n";
  return out;
}

bool undecided(const stage::CheckReport& report) {
  for (const auto& w : report.warnings)
    if (w.message.find("could not decide") != std::string::npos) return true;
  return false;
}

}  // namespace

// A start in a room's corner 100 to 110 units from a floor and a wall (the least clearance the
// doc allows), or beside one floor; and a goal so placed too: reachable on every solid at face
// sizes from 1,000 to 2^24, at random places and turns. (With 100 units from both walls the start
// had 4 units of room, less than a cell's diagonal, and the level was called sealed off.)
TEST(Check, AStartOrGoalInARoomsCornerIsReachable) {
  platon::testing::Rng rng{97};
  int checked = 0;
  for (const int32_t size : {1000, 4096, 65536, 1 << 24})
    for (const stage::Solid solid : stage::kSolids) {
      const stage::Stage s = stage::platonicStage(solid, size);
      for (int i = 0; i < 24; ++i) {
        stage::Level level = emptyLevel(solid, size, s);
        putInACorner(level, s, level.start, i % 4 != 3, i % 3 == 0, rng);
        if (i % 2) putInACorner(level, s, level.goal, i % 5 != 0, i % 3 == 1, rng);
        try {
          stage::checkLevelOnStage(level, s);
        } catch (const stage::StageError&) {
          continue;  // rounded to whole units, 99 units from a wall: not this test's question
        }
        ++checked;
        const stage::CheckReport report = stage::checkLevel(level, s);
        EXPECT_TRUE(report.errors.empty() && !undecided(report))
            << stage::solidName(solid) << " size " << size << " case " << i << ": start (" << level.start.position.x
            << ", " << level.start.position.y << ")\n"
            << findings(report);
      }
    }
  EXPECT_GT(checked, 400);
  // The audit's rooms: a floor and a wall along the face's axes, the start exactly 100 units from
  // both, the corner moved a unit at a time over 16 units, so through every alignment to the
  // cells (one of every eight was called sealed off).
  for (const int32_t size : {1000, 4096, 65536, 1 << 24})
    for (const stage::Solid solid : stage::kSolids) {
      const stage::Stage s = stage::platonicStage(solid, size);
      const Vec2 base = unit(centreOf(s.faces[0]));
      const int32_t length = std::min(800, size / 8);
      for (int32_t w = 0; w < 16; ++w) {
        stage::Level level = emptyLevel(solid, size, s);
        const Vec2 corner{base.x + w, base.y + w};
        level.faces[0].lines = {{corner, {corner.x + length, corner.y}, false, 0, 20, 1},
                                {corner, {corner.x, corner.y + length}, false, 0, 21, 1}};
        level.start.position = {corner.x + 100, corner.y + 100};
        stage::checkLevelOnStage(level, s);
        const stage::CheckReport report = stage::checkLevel(level, s);
        EXPECT_TRUE(report.errors.empty() && !undecided(report))
            << stage::solidName(solid) << " size " << size << " corner moved " << w << "\n"
            << findings(report);
      }
    }
}

namespace {

// The audit's posts level: a cube of 2^24 units, on face 0 a floor and a bump between the start
// and the goal (so that no straight line joins them), on faces 1 to 5 `posts` posts of one unit
// on a lattice hundreds of thousands of units apart; `sealed` walls the goal in.
std::string postsLevel(int posts, bool sealed) {
  std::string text = "HEXAHEDRON\n0 150 200\n0 3000 260\n16777216\n%\n0 100 6000 100\n1500 100 1500 300\n";
  if (sealed) text += "2600 100 2600 700\n2600 700 3400 700\n3400 700 3400 100\n";
  const int perFace = posts / 5, k = static_cast<int>(std::sqrt(perFace)) + 1, step = ((1 << 24) - 800) / k;
  for (int f = 1; f < 6; ++f) {
    text += "%\n";
    for (int c = 0; c < perFace; ++c) {
      const int x = 400 + (c / k) * step, y = 400 + (c % k) * step;
      text +=
          std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(x + 1) + " " + std::to_string(y) + "\n";
    }
  }
  return text;
}

}  // namespace

// Many short walls far apart cost the search cells at every level from the face's size down (not
// length: 10,000 one-unit posts on faces of 2^24 were taken for "very long" walls, searched with
// cells of 64 units and called sealed off). With 0, 10,000 and 50,000 posts the open level is
// reachable and the walled-in one refused, each decided.
TEST(Check, ManyShortWallsFarApartLeaveTheAnswerDecided) {
  for (const int posts : {0, 10000, 50000}) {
    SCOPED_TRACE(std::to_string(posts) + " posts");
    const stage::Level open = stage::parseLevel(postsLevel(posts, false), "posts.level");
    const stage::CheckReport accepted = stage::checkLevel(open, stage::platonicStageOf(open));
    EXPECT_TRUE(accepted.errors.empty() && !undecided(accepted)) << findings(accepted);
    const stage::Level sealed = stage::parseLevel(postsLevel(posts, true), "posts.level");
    const stage::CheckReport refused = stage::checkLevel(sealed, stage::platonicStageOf(sealed));
    ASSERT_EQ(refused.errors.size(), 1u) << findings(refused);
    EXPECT_EQ(stage::describe(refused.errors[0].where) + refused.errors[0].message,
              "posts.level:3:1: no path reaches the goal from the start (walls seal it off; see docs/level-format.md, "
              "\"platon check\")");
  }
}

// Where the search has to stop coarse (here 60,000 posts on faces of 2^24), a goal behind a gap it
// cannot resolve (260 units, wider than the 216 the finest cells resolve) far from the start and
// the goal is undecided: a warning saying so, never "no path". Without the posts the same level is
// searched with the finest cells and reachable.
TEST(Check, AGapTheCoarseCellsCannotResolveIsUndecidedNotSealed) {
  auto level = [](int posts) {
    // A box of 6,000 units round the goal, its only way in a gap of 260 units 3,000 units away.
    std::string text = postsLevel(posts, false);
    const std::string box = "8000 100 8000 3040\n8000 3300 8000 6100\n8000 6100 14000 6100\n14000 6100 14000 100\n";
    text.replace(text.find("0 3000 260"), 10, "0 11000 3000");
    text.replace(text.find("0 100 6000 100\n"), 15, "0 100 14000 100\n" + box);
    return stage::parseLevel(text, "gap.level");
  };
  const stage::Level few = level(0);
  const stage::CheckReport open = stage::checkLevel(few, stage::platonicStageOf(few));
  EXPECT_TRUE(open.errors.empty() && !undecided(open)) << findings(open);
  const stage::Level many = level(60000);
  const stage::CheckReport report = stage::checkLevel(many, stage::platonicStageOf(many));
  EXPECT_TRUE(report.errors.empty()) << findings(report);
  EXPECT_TRUE(undecided(report)) << findings(report);
}

// The search takes walls on one line that overlap or touch as one (a floor drawn in thousands of
// one-unit pieces, or drawn twice): a square round the goal drawn in pieces of 1 to 10 units,
// each twice and some overlapping, seals the goal as the whole square does; the same with one
// piece of each side left out (a hole of a few units, too narrow for the player) seals it too;
// with 300 units of one side left out the goal is reachable.
TEST(Check, WallsDrawnInPiecesSealAsWholeWallsDo) {
  platon::testing::Rng rng{5};
  for (const int32_t size : {4096, 65536})
    for (const stage::Solid solid : {stage::Solid::Hexahedron, stage::Solid::Icosahedron}) {
      const stage::Stage s = stage::platonicStage(solid, size);
      const Vec2 g = unit(centreOf(s.faces[1]));
      for (const int open : {0, 5, 300}) {
        stage::Level level = emptyLevel(solid, size, s);
        level.goal.position = g;
        auto& lines = level.faces[1].lines;
        const Vec2 corners[4] = {
            {g.x - 400, g.y - 400}, {g.x + 400, g.y - 400}, {g.x + 400, g.y + 400}, {g.x - 400, g.y + 400}};
        for (int k = 0; k < 4; ++k) {
          const Vec2 a = corners[k], b = corners[(k + 1) % 4];
          const int32_t dx = (b.x - a.x) / 800, dy = (b.y - a.y) / 800;  // a unit step along the side
          for (int32_t t = 0; t < 800;) {
            const int32_t piece = std::min(800 - t, rng.between(1, 10));
            const Vec2 from{a.x + dx * t, a.y + dy * t}, to{a.x + dx * (t + piece), a.y + dy * (t + piece)};
            const bool left = open > 0 && t >= 200 && t < 200 + open;  // the hole, on every side
            if (!left) {
              lines.push_back({from, to, false, 0, 30, 1});
              lines.push_back({to, from, false, 0, 31, 1});  // again, the other way
              if (piece > 2)
                lines.push_back({{from.x + dx, from.y + dy}, {to.x + dx, to.y + dy}, false, 0, 32, 1});  // overlapping
            }
            t += piece;
          }
        }
        stage::checkLevelOnStage(level, s);
        const stage::CheckReport report = stage::checkLevel(level, s);
        SCOPED_TRACE(std::string(stage::solidName(solid)) + " size " + std::to_string(size) + ", " +
                     std::to_string(open) + " units left out");
        if (open < 100) {
          ASSERT_EQ(report.errors.size(), 1u) << findings(report);
          EXPECT_NE(report.errors[0].message.find("no path reaches the goal"), std::string::npos);
        } else {
          EXPECT_TRUE(report.errors.empty() && !undecided(report)) << findings(report);
        }
      }
    }
}
