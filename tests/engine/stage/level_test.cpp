// The level format: seed files load, every malformed input is refused with file:line:column and
// a reason, written levels read back the same, and built levels hold what the file says.
#include "platon/stage/level.h"

#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "platon/stage/level_check.h"
#include "platon/stage/net.h"
#include "platon/testing/rng.h"

using namespace platon;
using physics::Vec2;

namespace {

// A plain seed file: no comments, no tags, no options.
constexpr const char* kSeedCube =
    "HEXAHEDRON\n0 600 700 0\n3 2000 2000\n4096\n"
    "%\n256 512 2600 512\n3000 512 3800 900\n%\n%\n100 100 200 200\n%\n%\n%\n";

std::string errorOf(const std::string& text) {
  try {
    const stage::Level level = stage::parseLevel(text, "t.level");
    const stage::Stage s = stage::platonicStageOf(level);
    stage::checkLevelOnStage(level, s);
  } catch (const stage::StageError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(LevelFormat, APlainSeedFileLoads) {
  const stage::Level level = stage::parseLevel(kSeedCube, "seed.level");
  EXPECT_EQ(level.solid, stage::Solid::Hexahedron);
  EXPECT_EQ(level.start.face, 0);
  EXPECT_EQ(level.start.position, (Vec2{600, 700}));
  EXPECT_EQ(level.goal.face, 3);
  EXPECT_EQ(level.size, 4096);
  ASSERT_EQ(level.faces.size(), 6u);
  EXPECT_EQ(level.faces[0].lines.size(), 2u);
  EXPECT_EQ(level.faces[2].lines.size(), 1u);
  EXPECT_EQ(errorOf(kSeedCube), "(accepted)");
}

TEST(LevelFormat, CommentsTagsGravityAndDecimals) {
  const stage::Level level = stage::parseLevel(
      "# a comment line\n\nTETRAHEDRON   # the solid\n1 500.4 600.5 90.25\n2000 1000\n4096\n"
      "% gravity 0.5 -0.25\n100 100 900 100 hazard\n100 300 900 300 oneway\n100 500 900 500 oneway door 7\n"
      "%\n%\t\n% \n200 200 300 300 switch 12\n300 300 400 300 tag 77\n",
      "t.level");
  EXPECT_EQ(level.start.position, (Vec2{500, 601}));  // decimals round to the nearest unit
  EXPECT_EQ(level.startMillidegrees, 90250);
  EXPECT_EQ(level.goal.face, 1);  // two numbers: on the start face
  EXPECT_EQ(level.faces[0].gravityQ16, (physics::Vec2w{32768, -16384}));
  EXPECT_EQ(level.faces[0].lines[0].tag, stage::gameTags()->number("hazard"));
  EXPECT_TRUE(level.faces[0].lines[1].oneWay);
  EXPECT_EQ(level.faces[0].lines[2].tag, stage::gameTags()->number("door") + 7);
  EXPECT_EQ(level.faces[3].lines[0].tag, stage::gameTags()->number("switch") + 12);
  EXPECT_EQ(level.faces[3].lines[1].tag, 77u);
  EXPECT_EQ(level.faces[3].lines[1].sourceLine, 15);
}

TEST(LevelFormat, EveryMistakeNamesFileLineColumnAndWhy) {
  const std::string header = "HEXAHEDRON\n0 600 700\n0 2000 2000\n4096\n";
  const std::string empty6 = "%\n%\n%\n%\n%\n%\n";
  const struct {
    std::string text, expected;
  } cases[] = {
      {"", "t.level:1:1: the file ends before the solid (the first line)"},
      {"CUBE\n",
       "t.level:1:1: unknown solid 'CUBE' (known: TETRAHEDRON, HEXAHEDRON, OCTAHEDRON, DODECAHEDRON, ICOSAHEDRON, or "
       "MESH file)"},
      {"HEXAHEDRON extra\n", "t.level:1:12: solid: unexpected 'extra'"},
      {"MESH ../../etc/passwd\n",
       "t.level:1:6: the mesh file must be a path inside the level's folder (no '/' at the start, no '..')"},
      {"HEXAHEDRON\n", "t.level:2:1: the file ends before the start line (face x y [degrees])"},
      {"HEXAHEDRON\n0 600\n", "t.level:2:6: start (face x y [degrees]): too few values"},
      {"HEXAHEDRON\n0 6o0 700\n", "t.level:2:3: start x: '6o0' is not a number"},
      {"HEXAHEDRON\n0 nan 700\n", "t.level:2:3: start x: 'nan' is not a number"},
      {"HEXAHEDRON\n0 1e300 700\n", "t.level:2:3: start x: 1e300 is out of range (-536870912 to 536870912)"},
      {"HEXAHEDRON\n0.5 600 700\n", "t.level:2:1: start face: 0.5 is not a whole number"},
      {"HEXAHEDRON\n0 600 700\n", "t.level:3:1: the file ends before the goal line ([face] x y)"},
      {"HEXAHEDRON\n0 600 700\n1 2 3 4\n", "t.level:3:7: goal ([face] x y): unexpected '4'"},
      {"HEXAHEDRON\n0 600 700\n0 2000 2000\n", "t.level:4:1: the file ends before the face size line"},
      {"HEXAHEDRON\n0 600 700\n0 2000 2000\n10\n",
       "t.level:4:1: face size (units): 10 is out of range (64 to 16777216)"},
      {header, "t.level:5:1: HEXAHEDRON has 6 faces; the file describes 0"},
      {header + "1 2 3 4\n", "t.level:5:1: expected '%', which starts face 0 (after the four header lines)"},
      {header + "%\n%\n%\n%\n%\n", "t.level:10:1: HEXAHEDRON has 6 faces; the file describes 5"},
      {header + empty6 + "%\n", "t.level:11:1: HEXAHEDRON has 6 faces; this '%' starts one more"},
      {header + "% spin 1\n", "t.level:5:3: unknown face option 'spin' (known: gravity gx gy)"},
      {header + "% gravity 1\n", "t.level:5:3: gravity needs two numbers: gx gy (units per frame per frame)"},
      {header + "% gravity 0 -0.5 0.1\n",
       "t.level:5:18: one value too many: gravity takes two numbers, gx gy (units per frame per frame)"},
      {header + "%\n1 2 3\n", "t.level:6:6: a segment is x0 y0 x1 y1 [oneway] [tag]: too few values"},
      {header + "%\n1 2 1 2\n", "t.level:6:1: the segment has no length (both ends at one point)"},
      {header + "%\n1 2 3 4 lava\n",
       "t.level:6:9: unknown segment word 'lava' (known: oneway, solid, hazard, goal, checkpoint, door N, switch N, "
       "tag N)"},
      {header + "%\n1 2 3 4 hazard goal\n", "t.level:6:16: a segment has one tag at most"},
      {header + "%\n1 2 3 4 door\n", "t.level:6:9: door needs a number"},
      {header + "%\n1 2 3 4 door 1000\n", "t.level:6:14: door: 1000 is out of range (1 to 999)"},
      {header + "%\n100 100 5000 100\n%\n%\n%\n%\n%\n",
       "t.level:6:9: the segment leaves face 0: (5000, 100) is outside it (its corners: (0, 0) (4096, 0) (4096, 4096) "
       "(0, 4096))"},
      {header + "%\n  -5 100 500 100\n%\n%\n%\n%\n%\n",
       "t.level:6:3: the segment leaves face 0: (-5, 100) is outside it (its corners: (0, 0) (4096, 0) (4096, 4096) "
       "(0, 4096))"},
      {header + "%\n100 650 1000 650\n%\n%\n%\n%\n%\n",
       "t.level:2:1: start (600, 700) is inside a wall: 50 units from the segment on line 6 (the player needs 100)"},
      {header + "%\n1950 2000 2050 2000\n%\n%\n%\n%\n%\n",
       "t.level:3:1: goal (2000, 2000) is inside a wall: 0 units from the segment on line 6 (the player needs 100)"},
      {"HEXAHEDRON\n7 600 700\n0 2000 2000\n4096\n" + empty6,
       "t.level:2:1: start face 7 does not exist (faces 0 to 5)"},
      {"HEXAHEDRON\n0 -600 700\n0 2000 2000\n4096\n" + empty6, "t.level:2:1: start (-600, 700) is outside face 0"},
      {"HEXAHEDRON\n0 600 700\n0 4000 2000\n4096\n" + empty6,
       "t.level:3:1: the goal's square (300 units wide) reaches over the edge of face 0"},
  };
  for (const auto& c : cases) EXPECT_EQ(errorOf(c.text), c.expected) << c.text;
}

// What the text itself can hide: a byte order mark (skipped), CR-only line ends (refused, saying
// so), bytes a terminal does not show (escaped as \x{HH}, a NUL included, which used to end the
// message), very long tokens (cut to 40 bytes), a gravity too small to keep; and every message
// has a column, also for what is missing (the column just past the line's last value).
TEST(LevelFormat, WhatTheTextHidesIsShownInTheMessage) {
  using namespace std::string_literals;
  const std::string header = "HEXAHEDRON\n0 600 700\n0 2000 2000\n4096\n";
  const std::string faces = "%\n%\n%\n%\n%\n%\n";
  const std::string digits(10000, '7'), letters(100, 'a');
  const struct {
    std::string text, expected;
  } cases[] = {
      {"\xEF\xBB\xBF" + header + faces, "(accepted)"},
      {"\xEF\xBB\xBF"
       "CUBE\n",
       "t.level:1:1: unknown solid 'CUBE' (known: TETRAHEDRON, HEXAHEDRON, OCTAHEDRON, DODECAHEDRON, ICOSAHEDRON, or "
       "MESH file)"},
      {"\xEF\xBB\xBF\xEF\xBB\xBF"
       "HEXAHEDRON\n",
       "t.level:1:1: unknown solid '\\x{EF}\\x{BB}\\x{BF}HEXAHEDRON' (known: TETRAHEDRON, HEXAHEDRON, OCTAHEDRON, "
       "DODECAHEDRON, ICOSAHEDRON, or MESH file)"},
      {"HEXAHEDRON\r0 600 700\r0 2000 2000\r4096\r",
       "t.level:1:11: a CR (\\r) ends a line here without an LF: lines must end with LF or CR LF (CR-only line ends, "
       "as old Mac files have, are not read)"},
      {"HEXAHEDRON\r\n0 600\r700\r\n",
       "t.level:2:6: a CR (\\r) ends a line here without an LF: lines must end with LF or CR LF (CR-only line ends, as "
       "old Mac files have, are not read)"},
      {"HEXAHEDRON\r\n0 600 700 \r \r\n0\r2000 2000\r\n",
       "t.level:3:2: a CR (\\r) ends a line here without an LF: lines must end with LF or CR LF (CR-only line ends, as "
       "old Mac files have, are not read)"},
      {"HEXAHEDRON\r\n0 600 700\r\n0 2000 2000 \r\r\n4096\r\n" + faces, "(accepted)"},
      {"HEXAHEDRON\n0 600\0 700\n"s, "t.level:2:3: start x: '600\\x{00}' is not a number"},
      {"HEXAHEDRON\n0 \xE2\x88\x92"
       "600 700\n",
       "t.level:2:3: start x: '\\x{E2}\\x{88}\\x{92}"
       "600' is not a number"},
      {"HEXA\xC3\x89"
       "DRON\n",
       "t.level:1:1: unknown solid 'HEXA\\x{C3}\\x{89}"
       "DRON' (known: TETRAHEDRON, HEXAHEDRON, OCTAHEDRON, DODECAHEDRON, ICOSAHEDRON, or MESH file)"},
      {"HEXAHEDRON\n0 " + digits + " 700\n",
       "t.level:2:3: start x: " + digits.substr(0, 40) + "... is out of range (-536870912 to 536870912)"},
      {"HEXAHEDRON\n0 " + letters + " 700\n",
       "t.level:2:3: start x: '" + letters.substr(0, 40) + "...' is not a number"},
      {header + "%\n1 2 3 4 " + letters + "\n",
       "t.level:6:9: unknown segment word '" + letters.substr(0, 40) +
           "...' (known: oneway, solid, hazard, goal, checkpoint, door N, switch N, tag N)"},
      {header + "% gravity 0 -0.000001\n",
       "t.level:5:3: gravity 0 -0.000001 rounds to none: gravity is kept in steps of 1/65536 unit per frame per frame "
       "(write 0 0 for none)"},
      {header + "% gravity 0 -0.00001\n%\n%\n%\n%\n%\n", "(accepted)"},  // 0.65 of a step: one step
      {"MESH\n", "t.level:1:5: MESH needs a file name"},
      {"HEXAHEDRON\n12000 600 700\n0 2000 2000\n4096\n" + faces,
       "t.level:2:1: start face 12000 does not exist (faces 0 to 5)"},
      // A face number out of range names the level's faces, below 0 too (it said "0 to 2147483647").
      {"HEXAHEDRON\n-1 600 700\n0 2000 2000\n4096\n" + faces,
       "t.level:2:1: start face -1 does not exist (faces 0 to 5)"},
      {"HEXAHEDRON\n1e10 600 700\n0 2000 2000\n4096\n" + faces,
       "t.level:2:1: start face 1e10 does not exist (faces 0 to 5)"},
      {"TETRAHEDRON\n0 600 700\n-3 2000 800\n4096\n%\n%\n%\n%\n",
       "t.level:3:1: goal face -3 does not exist (faces 0 to 3)"},
      {"MESH m.obj\n-1 10 10\n0 10 10\n4096\n%\n%\n%\n%\n%\n",
       "t.level:2:1: start face -1 does not exist (faces 0 to 4)"},
      {"MESH m.obj\n0 10 10\n-2 10 10\n4096\n", "t.level:3:1: goal face -2 does not exist (faces are numbered from 0)"},
      {"HEXAHEDRON\n-0.5 600 700\n", "t.level:2:1: start face: -0.5 is not a whole number"},
      // A NUL before digits: the braces end the escape ('2\x0000' read as one four-digit escape).
      {header + "%\n100 200 300 2\0"
                "00\n"s,
       "t.level:6:13: y1: '2\\x{00}00' is not a number"},
      // A vertical tab looks like a separator but is a value's byte: named where it is.
      {header + "%\n100\v200 300 200\n",
       "t.level:6:4: a segment is x0 y0 x1 y1 [oneway] [tag]: too few values: '100\\x{0B}200' is one value; it holds a "
       "vertical tab (\\x{0B}), which does not separate values (only spaces and tabs do)"},
      {header + "%\n100\v200 300 200 400\n",
       "t.level:6:1: x0: '100\\x{0B}200' is not a number (it holds a vertical tab (\\x{0B}), which does not separate "
       "values: "
       "only spaces and tabs do)"},
      {"HEXAHEDRON\n0 600\f700\n",
       "t.level:2:6: start (face x y [degrees]): too few values: '600\\x{0C}700' is one value; it holds a form feed "
       "(\\x{0C}), "
       "which does not separate values (only spaces and tabs do)"},
  };
  for (const auto& c : cases) EXPECT_EQ(errorOf(c.text), c.expected) << c.text;
  // Face numbers go as far as the level's faces: a mesh level of 20,480 faces may start on the last.
  std::string mesh = "MESH sphere.stl\n20479 10 10\n20000 10 10\n4096\n";
  for (int f = 0; f < 20480; ++f) mesh += "%\n";
  const stage::Level big = stage::parseLevel(mesh, "m.level");
  EXPECT_EQ(big.start.face, 20479);
  EXPECT_EQ(big.goal.face, 20000);
}

// A random level on a random solid: segments inside their faces, tags, one-way lines, gravity.
stage::Level randomLevel(platon::testing::Rng& rng) {
  stage::Level level;
  level.file = "r.level";
  level.solid = stage::kSolids[rng.between(0, 4)];
  level.size = rng.between(64, 20000);
  const stage::Stage s = stage::platonicStage(*level.solid, level.size);
  auto inside = [&](size_t f) {  // a point inside face f: a random mix of its corners
    const auto& c = s.faces[f].corners;
    double wx = 0, wy = 0, total = 0;
    for (const Vec2 p : c) {
      const double w = rng.uniform(0.1, 1);
      wx += w * p.x, wy += w * p.y, total += w;
    }
    return Vec2{static_cast<int32_t>(wx / total), static_cast<int32_t>(wy / total)};
  };
  for (size_t f = 0; f < s.faceCount(); ++f) {
    stage::LevelFace face;
    if (rng.between(0, 3) == 0)
      face.gravityQ16 = physics::Vec2w{rng.between(-90000, 90000), rng.between(-90000, 90000)};
    const int count = rng.between(0, 6);
    for (int i = 0; i < count; ++i) {
      stage::LevelLine l{inside(f), inside(f)};
      if (l.a == l.b) continue;
      l.oneWay = rng.between(0, 3) == 0;
      const uint32_t tags[] = {0,
                               stage::gameTags()->number("hazard"),
                               stage::gameTags()->number("goal"),
                               stage::gameTags()->number("checkpoint"),
                               stage::gameTags()->number("door") + 5,
                               stage::gameTags()->number("switch") + 999,
                               4242};
      l.tag = tags[rng.between(0, 6)];
      face.lines.push_back(l);
    }
    level.faces.push_back(face);
  }
  level.start = {rng.between(0, static_cast<int>(s.faceCount()) - 1), {}};
  level.start.position = inside(static_cast<size_t>(level.start.face));
  level.startMillidegrees = rng.between(-360000, 360000);
  level.goal = {rng.between(0, static_cast<int>(s.faceCount()) - 1), {}};
  level.goal.position = inside(static_cast<size_t>(level.goal.face));
  return level;
}

TEST(LevelFormat, WrittenLevelsReadBackTheSame) {
  platon::testing::Rng rng{7};
  for (int i = 0; i < 300; ++i) {
    const stage::Level level = randomLevel(rng);
    const std::string text = stage::writeLevel(level);
    const stage::Level back = stage::parseLevel(text, "r.level");
    ASSERT_EQ(back, level) << text;
    EXPECT_EQ(stage::writeLevel(back), text);
  }
  // And the seed file: parse, write, parse gives the same level.
  const stage::Level seed = stage::parseLevel(kSeedCube, "seed.level");
  EXPECT_EQ(stage::parseLevel(stage::writeLevel(seed), "seed.level"), seed);
}

TEST(LevelFormat, BuildPutsEveryLineGravityAndTheGoalInTheWorld) {
  const stage::Level level = stage::parseLevel(
      "OCTAHEDRON\n0 1500 800\n5 1500 1000\n4096\n% gravity 0.25 0\n100 100 3000 100 hazard\n%\n%\n%\n%\n"
      "%\n1000 300 2000 300 oneway\n%\n%\n",
      "t.level");
  stage::Stage s = stage::platonicStageOf(level);
  stage::checkLevelOnStage(level, s);
  physics::World world;
  stage::buildLevel(level, s, world, 0, 22938);
  const physics::MapPart& f0 = world.mapPart(0);
  EXPECT_EQ(f0.gravity(), (physics::Vec2w{16384, 0}));
  EXPECT_EQ(world.mapPart(1).gravity(), (physics::Vec2w{0, -22938}));
  EXPECT_EQ(f0.lines().size(), 3u + 1u);  // three warp edges, one line
  EXPECT_EQ(f0.lines()[3].tag, stage::gameTags()->number("hazard"));
  const physics::MapPart& f5 = world.mapPart(5);
  ASSERT_EQ(f5.lines().size(), 3u + 1u + 4u);  // edges, the one-way line, the goal's square
  EXPECT_EQ(f5.lines()[3].kind, physics::LineKind::OneWay);
  for (size_t i = 4; i < 8; ++i) EXPECT_EQ(f5.lines()[i].tag, stage::gameTags()->number("goal"));
}

}  // namespace

namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Every shipped level parses, has no errors in `platon check`'s sense, and writes back the same.
TEST(LevelFormat, EveryShippedLevelChecksAndRoundTrips) {
  int count = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(PLATON_SOURCE_ROOT) + "/levels")) {
    if (entry.path().extension() != ".level") continue;
    SCOPED_TRACE(entry.path().string());
    const stage::Level level = stage::parseLevel(readFile(entry.path()), entry.path());
    if (!level.solid) continue;  // mesh levels: the mesh plugin's tests
    const stage::CheckReport report = stage::checkLevel(level, stage::platonicStageOf(level));
    for (const auto& e : report.errors) ADD_FAILURE() << stage::describe(e.where) << e.message;
    EXPECT_EQ(stage::parseLevel(stage::writeLevel(level), "again"), level);
    ++count;
  }
  EXPECT_GE(count, 3);
}

// The nets in docs/level-format.md are what `platon net` draws today.
TEST(LevelFormat, TheDocumentedNetsAreTheStages) {
  for (const stage::Solid solid : stage::kSolids) {
    std::string name(stage::solidName(solid));
    const stage::Stage s = stage::platonicStage(solid, 1000);
    const std::string title = name + ": " + std::to_string(s.faceCount()) + " faces";
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    EXPECT_EQ(readFile(std::string(PLATON_SOURCE_ROOT) + "/docs/nets/" + name + ".svg"),
              stage::netSvg(s, stage::unfold(s), title))
        << name << ": run `platon net " << stage::solidName(solid) << " -o docs/nets/" << name << ".svg`";
  }
}

// A level's net draws what the level holds: every line once, coloured by its tag (one-way dashed),
// the start and the goal on their faces, and a face's own gravity as its "down" with its value.
TEST(LevelFormat, ALevelsNetShowsItsLinesStartGoalAndGravity) {
  std::string text = "HEXAHEDRON\n0 600 700\n1 2000 800\n4096\n";
  text += "%\n0 512 4096 512\n1000 900 1400 900 hazard\n2000 900 2400 900 oneway\n";
  text += "% gravity 0.5 0\n0 512 4096 512 checkpoint\n%\n%\n%\n%\n";
  const stage::Level level = stage::parseLevel(text, "t.level");
  const stage::Stage s = stage::platonicStage(*level.solid, level.size);
  const std::string svg = stage::netSvg(s, stage::unfold(s), "t", &level);
  auto count = [&](const std::string& part) {
    size_t n = 0;
    for (size_t at = svg.find(part); at != std::string::npos; at = svg.find(part, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("stroke-width=\"2\""), 4u) << "one line element a level line";
  EXPECT_EQ(count("stroke=\"#d55e00\" stroke-width=\"2\""), 1u) << "the hazard";
  EXPECT_EQ(count("stroke=\"#009e73\" stroke-width=\"2\""), 1u) << "the checkpoint";
  EXPECT_EQ(count("stroke-dasharray"), 1u) << "the one-way line";
  EXPECT_EQ(count("<circle"), 2u) << "start and goal";
  EXPECT_EQ(count(">start<"), 1u);
  EXPECT_EQ(count(">goal<"), 1u);
  EXPECT_EQ(count(">g 0.5 0<"), 1u) << "face 1's gravity";
  // Without a level the net is the bare solid's, as the docs show it.
  EXPECT_EQ(stage::netSvg(s, stage::unfold(s), "t").find("<circle"), std::string::npos);
}

// The tables of docs/level-format.md ("Across each edge") are today's neighbours: what
// stage::neighbourTable writes, between the doc's markers, for every solid.
TEST(LevelFormat, TheDocumentedNeighbourTablesAreTheStages) {
  const std::string doc = readFile(std::string(PLATON_SOURCE_ROOT) + "/docs/level-format.md");
  for (const stage::Solid solid : stage::kSolids) {
    const std::string marker = "<!-- neighbours " + std::string(stage::solidName(solid)) + " -->\n";
    const size_t at = doc.find(marker);
    ASSERT_NE(at, std::string::npos) << marker;
    const size_t table = doc.find("| face |", at), end = doc.find("<!-- end -->", at);
    ASSERT_LT(table, end);
    const std::string want = stage::neighbourTable(stage::platonicStage(solid, 1000));
    EXPECT_EQ(doc.substr(table, end - table), want) << stage::solidName(solid) << ": the doc should show\n" << want;
  }
  // Any size gives the same table (frames and numbering do not depend on it).
  for (const stage::Solid solid : stage::kSolids)
    for (const int32_t size : {64, 4096, 1 << 24})
      EXPECT_EQ(stage::neighbourTable(stage::platonicStage(solid, size)),
                stage::neighbourTable(stage::platonicStage(solid, 1000)));
}

// Nets never overlap, and every face joins the face it was unfolded from along their shared edge.
TEST(Net, FacesJoinTheirNeighboursAndNeverOverlap) {
  for (const stage::Solid solid : stage::kSolids) {
    const stage::Stage s = stage::platonicStage(solid, 1000);
    const std::vector<stage::NetFace> net = stage::unfold(s);
    for (size_t f = 1; f < s.faceCount(); ++f) {
      const int parent = net[f].attachedTo;
      ASSERT_GE(parent, 0) << stage::solidName(solid) << " face " << f << " was not unfolded";
      // Some edge of f lies on an edge of its parent, ends swapped.
      bool joined = false;
      const auto& c = s.faces[f].corners;
      for (size_t j = 0; j < c.size(); ++j) {
        const auto [g, i] = s.faces[f].neighbours[j];
        if (g != parent) continue;
        const auto& pc = s.faces[size_t(g)].corners;
        const Eigen::Vector2d a = net[f].place(c[j].x, c[j].y);
        const Eigen::Vector2d b =
            net[size_t(g)].place(pc[(size_t(i) + 1) % pc.size()].x, pc[(size_t(i) + 1) % pc.size()].y);
        joined = joined || (a - b).norm() < 2;
      }
      EXPECT_TRUE(joined) << stage::solidName(solid) << " face " << f;
    }
  }
}

}  // namespace

namespace {

stage::CheckReport checkText(const std::string& text) {
  const stage::Level level = stage::parseLevel(text, "c.level");
  return stage::checkLevel(level, stage::platonicStageOf(level));
}

// A goal walled in is unreachable; opened by a door it is reachable; the same goal on another face
// reached over an edge is reachable; a wall along an edge and empty faces are warnings.
TEST(Check, ReachabilityAndWarnings) {
  const std::string header = "HEXAHEDRON\n0 600 700\n";
  const std::string box = "1500 1500 2500 1500\n2500 1500 2500 2500\n2500 2500 1500 2500\n";
  const stage::CheckReport sealed =
      checkText(header + "0 2000 2000\n4096\n%\n" + box + "1500 2500 1500 1500\n%\n%\n%\n%\n%\n");
  ASSERT_EQ(sealed.errors.size(), 1u);
  EXPECT_EQ(stage::describe(sealed.errors[0].where), "c.level:3:1: ");
  EXPECT_NE(sealed.errors[0].message.find("no path reaches the goal"), std::string::npos);
  EXPECT_EQ(
      checkText(header + "0 2000 2000\n4096\n%\n" + box + "1500 2500 1500 1500 door 1\n%\n%\n%\n%\n%\n").errors.size(),
      0u);
  // Face 0 walled all round: a goal on face 2 cannot be reached; with one side open it can.
  const std::string walls = "50 50 4046 50\n4046 50 4046 4046\n4046 4046 50 4046\n";
  EXPECT_EQ(checkText(header + "2 2000 2000\n4096\n%\n" + walls + "50 4046 50 50\n%\n%\n%\n%\n%\n").errors.size(), 1u);
  const stage::CheckReport open = checkText(header + "2 2000 2000\n4096\n%\n" + walls + "%\n%\n%\n%\n%\n");
  EXPECT_EQ(open.errors.size(), 0u);
  ASSERT_EQ(open.warnings.size(), 1u);  // faces 1, 3, 4, 5 are empty (2 holds the goal)
  EXPECT_EQ(stage::describe(open.warnings[0].where) + open.warnings[0].message,
            "c.level:9:1: faces 1, 3, 4, 5 have no lines");
  const std::string small = "0 0 10 10\n";
  const stage::CheckReport along = checkText(header + "0 2000 2000\n4096\n%\n4096 100 4096 3000\n%\n" + small + "%\n" +
                                             small + "%\n" + small + "%\n" + small + "%\n" + small);
  ASSERT_EQ(along.warnings.size(), 1u);
  EXPECT_EQ(stage::describe(along.warnings[0].where) + along.warnings[0].message,
            "c.level:6:1: the segment lies along edge 1 of face 0: it blocks the way to face 1");
}

}  // namespace

namespace {

// A table with a mod's kinds on top of the game's: a word alone and a numbered one.
std::shared_ptr<const stage::TagTable> withModTags() {
  auto t = std::make_shared<stage::TagTable>(*stage::gameTags());
  t->add({"spring", stage::kFirstModTag, 0, stage::Passage::Wall, {204, 121, 167, true}, "springs.lua"});
  t->add({"bumper", stage::kFirstModTag + stage::kModTagStep, 999, stage::Passage::Through, {}, "bumpers.lua"});
  return t;
}

TEST(Tags, TheTableRefusesWhatWouldMakeAWordOrANumberMeanTwoThings) {
  stage::TagTable t = *stage::gameTags();
  const std::pair<stage::TagKind, std::string> refused[] = {
      {{"hazard", 5000}, "the tag 'hazard' is already the game's"},
      {{"lava", 1}, "overlaps 'hazard'"},
      {{"lava", 1500}, "overlaps 'door'"},       // inside door's numbers
      {{"lava", 990, 20}, "overlaps 'door'"},    // a range reaching into them
      {{"lava", 2999, 5}, "overlaps 'switch'"},  // the last switch
      {{"tag", 9000}, "the level format's own word"},
      {{"oneway", 9000}, "the level format's own word"},
      {{"", 9000}, "is no tag word"},
      {{"9lives", 9000}, "is no tag word"},
      {{"la va", 9000}, "is no tag word"},
      {{std::string(33, 'a'), 9000}, "is no tag word"},
      {{"lava", 4294967290u, 10}, "runs past the largest tag number"},
  };
  for (const auto& [kind, why] : refused) {
    SCOPED_TRACE(kind.word);
    try {
      t.add(kind);
      ADD_FAILURE() << "added";
    } catch (const stage::TagError& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(t.kinds().size(), stage::gameTags()->kinds().size());
  t.add({"lava", 3000, 0});  // just past the last switch
  EXPECT_EQ(t.number("lava"), 3000u);
}

TEST(Tags, AModsWordsAreReadWrittenAndListedLikeTheGames) {
  const auto tags = withModTags();
  const std::string text =
      "HEXAHEDRON\n0 600 700\n2 2000 800\n4096\n%\n0 512 4096 512 spring\n"
      "100 900 400 900 oneway bumper 7\n500 900 700 900 door 3\n800 900 900 900 tag 42\n"
      "%\n%\n%\n%\n%\n";
  const stage::Level level = stage::parseLevel(text, "m.level", tags);
  ASSERT_EQ(level.faces[0].lines.size(), 4u);
  EXPECT_EQ(level.faces[0].lines[0].tag, stage::kFirstModTag);
  EXPECT_EQ(level.faces[0].lines[1].tag, stage::kFirstModTag + stage::kModTagStep + 7);
  const std::string written = stage::writeLevel(level);
  EXPECT_NE(written.find("0 512 4096 512 spring\n"), std::string::npos) << written;
  EXPECT_NE(written.find("100 900 400 900 oneway bumper 7\n"), std::string::npos) << written;
  EXPECT_NE(written.find("800 900 900 900 tag 42\n"), std::string::npos) << written;
  EXPECT_EQ(stage::parseLevel(written, "m.level", tags), level);
  // Without the mod, its words are unknown, and the message lists what the table knows.
  try {
    stage::parseLevel(text, "m.level");
    ADD_FAILURE() << "read without the mod's words";
  } catch (const stage::StageError& e) {
    EXPECT_STREQ(e.what(),
                 "m.level:6:16: unknown segment word 'spring' (known: oneway, solid, hazard, goal, "
                 "checkpoint, door N, switch N, tag N)");
  }
  try {
    stage::parseLevel("HEXAHEDRON\n0 600 700\n2 2000 800\n4096\n%\n0 512 4096 512 bumper 1000\n%\n%\n%\n%\n%\n",
                      "m.level", tags);
    ADD_FAILURE() << "bumper 1000 read";
  } catch (const stage::StageError& e) {
    EXPECT_NE(std::string(e.what()).find("m.level:6:23:"), std::string::npos) << e.what();
  }
  // A passable kind of a mod's is passed by the level checks as the goal is.
  EXPECT_TRUE(tags->playerPasses(stage::kFirstModTag + stage::kModTagStep + 7));
  EXPECT_FALSE(tags->playerPasses(stage::kFirstModTag));
}

// docs/level-format.md's table of words is the game's table, word for word and number for number.
TEST(Tags, TheDocumentedWordsAreTheGamesTable) {
  const std::string doc = readFile(std::string(PLATON_SOURCE_ROOT) + "/docs/level-format.md");
  for (const stage::TagKind& k : stage::gameTags()->kinds()) {
    SCOPED_TRACE(k.word);
    const std::string word = "`" + k.word + (k.count ? " N`" : "`");
    const size_t row = doc.find("| " + word);
    const size_t rowSolid = doc.find(word + " |");
    ASSERT_TRUE(row != std::string::npos || rowSolid != std::string::npos) << "no row for " << word;
    const size_t at = row != std::string::npos ? row : rowSolid;
    const std::string line = doc.substr(at, doc.find('\n', at) - at);
    const std::string number = k.count ? std::to_string(k.number) + " + N" : std::to_string(k.number);
    EXPECT_NE(line.find("| " + number + " |"), std::string::npos) << line;
  }
}

}  // namespace

// The tag table's lookups (by word, and a tag's kind) answer as a pass over every kind would,
// over tables of thousands of kinds, words alone and numbered, declared in any order.
TEST(Tags, LookupsAgreeWithAPassOverEveryKind) {
  platon::testing::Rng rng{77};
  for (int table = 0; table < 20; ++table) {
    stage::TagTable tags = *stage::gameTags();
    std::vector<uint32_t> bases;
    for (uint32_t i = 0; i < 3000; ++i) bases.push_back(stage::kFirstModTag + i * stage::kModTagStep);
    for (size_t i = bases.size(); i > 1; --i) std::swap(bases[i - 1], bases[rng.next() % i]);  // any order
    for (size_t i = 0; i < bases.size(); ++i) {
      stage::TagKind k;
      k.word = "w" + std::to_string(i);
      k.number = bases[i];
      k.count = rng.between(0, 2) == 0 ? 0 : static_cast<uint32_t>(rng.between(1, 999));
      k.owner = "mod";
      tags.add(k);
    }
    // A kind overlapping any other is refused, whichever side it overlaps from.
    stage::TagKind overlapping;
    overlapping.word = "late";
    overlapping.number = bases[0] + 500;
    overlapping.count = 999;
    bool overlaps = false;
    for (const stage::TagKind& k : tags.kinds())
      overlaps =
          overlaps || (k.number <= overlapping.number + overlapping.count && overlapping.number <= k.number + k.count);
    if (overlaps) {
      EXPECT_THROW(tags.add(overlapping), stage::TagError);
    } else {
      EXPECT_NO_THROW(tags.add(overlapping));
    }
    for (int q = 0; q < 20000; ++q) {
      const uint32_t tag = rng.between(0, 2) == 0 ? static_cast<uint32_t>(rng.between(0, 3000))
                                                  : bases[rng.next() % bases.size()] + rng.between(0, 1000);
      const stage::TagKind* expected = nullptr;
      for (const stage::TagKind& k : tags.kinds())
        if (k.holds(tag)) expected = &k;
      uint32_t n = 99;
      ASSERT_EQ(tags.kindOf(tag, &n), expected) << tag;
      if (expected) {
        EXPECT_EQ(n, tag - expected->number);
      }
    }
    for (const stage::TagKind& k : tags.kinds()) ASSERT_EQ(tags.find(k.word), &k);
    EXPECT_EQ(tags.find("nothing"), nullptr);
  }
}

// A level's size is capped as it is read, not by the memory it would take: one segment past the
// most a face may hold, or a level may hold, is refused at its line (a 256 MB file of 12 million
// segments aborted `platon check` with bad_alloc).
TEST(LevelFile, SegmentsPastTheCapsAreRefusedAtTheirLine) {
  auto level = [](const std::vector<size_t>& perFace) {
    std::string text = "HEXAHEDRON\n0 600 700\n2 2000 800\n4096\n";
    text.reserve(24 * (stage::kMaxLevelSegments + 16));
    for (const size_t n : perFace) {
      text += "%\n";
      for (size_t i = 0; i < n; ++i) text += (i % 2 ? "1 3 9 4\n" : "1 2 3 4 hazard\n");  // plain and tagged lines
    }
    return text;
  };
  const size_t face = stage::kMaxFaceSegments;
  EXPECT_NO_THROW((void)stage::parseLevel(level({face, 1, 1, 1, 1, 1}), "ok.level"));
  try {
    (void)stage::parseLevel(level({face + 1, 1, 1, 1, 1, 1}), "face.level");
    ADD_FAILURE() << "read";
  } catch (const stage::StageError& e) {
    EXPECT_EQ(std::string(e.what()), "face.level:" + std::to_string(5 + face + 1) + ":1: face 0 has " +
                                         std::to_string(face) + " segments already, the most a face may have");
  }
  try {
    (void)stage::parseLevel(level({face, face, 1, 1, 1, 1}), "all.level");
    ADD_FAILURE() << "read";
  } catch (const stage::StageError& e) {
    EXPECT_EQ(std::string(e.what()), "all.level:" + std::to_string(5 + face + 1 + face + 2) + ":1: the level has " +
                                         std::to_string(stage::kMaxLevelSegments) +
                                         " segments already, the most a level may have");
  }
}

// Faces are capped as they are read too: a mesh level's '%' lines past a mesh's most faces.
TEST(LevelFile, FacesPastTheCapAreRefusedAtTheirLine) {
  std::string text = "MESH m.obj\n0 600 700\n0 2000 800\n4096\n";
  for (size_t i = 0; i <= stage::kMaxLevelFaces; ++i) text += "%\n";
  try {
    (void)stage::parseLevel(text, "m.level");
    ADD_FAILURE() << "read";
  } catch (const stage::StageError& e) {
    EXPECT_EQ(std::string(e.what()), "m.level:" + std::to_string(5 + stage::kMaxLevelFaces) +
                                         ":1: this '%' starts face " + std::to_string(stage::kMaxLevelFaces) +
                                         "; a level has at most " + std::to_string(stage::kMaxLevelFaces) +
                                         " faces (a mesh's most)");
  }
}
