// Writing a level over the text it came from (the editor's save): what did not change comes back
// byte for byte, comments and order included; what changed reads back as the edit.
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "platon/stage/level.h"
#include "platon/testing/rng.h"

using namespace platon;
using physics::Vec2;

namespace {

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Every Platonic level the game ships, with its text.
std::vector<std::pair<std::string, std::string>> shippedLevels() {
  std::vector<std::pair<std::string, std::string>> levels;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(PLATON_SOURCE_ROOT) + "/levels")) {
    if (entry.path().extension() != ".level") continue;
    const std::string text = readFile(entry.path());
    if (stage::parseLevel(text, entry.path()).solid) levels.emplace_back(entry.path().string(), text);
  }
  return levels;
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = std::min(text.find('\n', start), text.size());
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

bool contains(const std::vector<std::string>& lines, const std::string& line) {
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

// A random whole-unit point well inside face f (the level's segments need not be on the stage
// here: only the text is tested).
Vec2 somePoint(platon::testing::Rng& rng, int32_t size) { return {rng.between(1, size - 1), rng.between(1, size / 2)}; }

std::string difference(const stage::Level& a, const stage::Level& b) {
  if (!(a.start == b.start)) return "the start";
  if (!(a.goal == b.goal)) return "the goal";
  for (size_t f = 0; f < a.faces.size(); ++f) {
    if (a.faces[f].gravityQ16 != b.faces[f].gravityQ16) return "face " + std::to_string(f) + " gravity";
    if (a.faces[f].lines.size() != b.faces[f].lines.size()) return "face " + std::to_string(f) + " count";
    for (size_t i = 0; i < a.faces[f].lines.size(); ++i)
      if (!(a.faces[f].lines[i] == b.faces[f].lines[i]))
        return "face " + std::to_string(f) + " line " + std::to_string(i);
  }
  return "?";
}

}  // namespace

TEST(LevelWrite, AnUneditedLevelComesBackByteForByte) {
  const auto levels = shippedLevels();
  ASSERT_GE(levels.size(), 8u);
  for (const auto& [path, text] : levels) {
    SCOPED_TRACE(path);
    EXPECT_EQ(stage::writeLevel(stage::parseLevel(text, path), text), text);
  }
  // Line ends of either kind, and a last line without one.
  for (const std::string& text :
       {std::string("HEXAHEDRON\r\n0 600 700\r\n3 2000 2000\r\n4096\r\n%  # one\r\n256 512 "
                    "2600 512 # floor\r\n%\r\n%\r\n%\r\n%\r\n%"),
        std::string("# lead\nHEXAHEDRON\n0 600 700\n3 2000 2000\n4096\n%\n%\n%\n%\n%\n%\n1 2 3 4")})
    EXPECT_EQ(stage::writeLevel(stage::parseLevel(text, "t"), text), text);
}

// A goal written "x y" is on the start's face: moving the start to another face writes the goal's
// face out, so that it stays where it was. A face's gravity is written as briefly as reads back.
TEST(LevelWrite, AGoalWithoutItsFaceStaysWhenTheStartMovesAndGravityIsShort) {
  const std::string text =
      "HEXAHEDRON\n0 600 700  # start\n3600 1500  # goal, on the start's face\n4096\n%\n%\n%\n%\n%\n%\n";
  stage::Level level = stage::parseLevel(text, "t");
  level.start.face = 1;
  const std::string written = stage::writeLevel(level, text);
  EXPECT_EQ(stage::parseLevel(written, "t"), level) << written;
  EXPECT_NE(written.find("0 3600 1500  # goal, on the start's face"), std::string::npos) << written;
  level.faces[2].gravityQ16 = physics::Vec2w{22938, -7};
  const std::string again = stage::writeLevel(level, written);
  EXPECT_NE(again.find("% gravity 0.35 -0.0001"), std::string::npos) << again;
  EXPECT_EQ(stage::parseLevel(again, "t"), level);
}

// Random edits of every kind on every shipped level: the written text reads back as the edit, every
// comment line and every untouched segment's line is still there as it was, and a changed line
// keeps its comment.
TEST(LevelWrite, EditsReadBackAndKeepEveryUntouchedLine) {
  platon::testing::Rng rng{25};
  int edits = 0;
  for (const auto& [path, text] : shippedLevels()) {
    SCOPED_TRACE(path);
    const stage::Level original = stage::parseLevel(text, path);
    const std::vector<std::string> before = linesOf(text);
    for (int round = 0; round < 40; ++round) {
      stage::Level level = original;
      std::vector<int> touched, deleted;  // the lines whose values changed or went, and those that went
      const int kinds = rng.between(1, 4);
      for (int k = 0; k < kinds; ++k) {
        auto& face = level.faces[static_cast<size_t>(rng.between(0, static_cast<int>(level.faces.size()) - 1))];
        switch (rng.between(0, 6)) {
          case 0:  // a new segment
            face.lines.push_back({somePoint(rng, level.size), somePoint(rng, level.size), rng.between(0, 1) == 1,
                                  static_cast<uint32_t>(rng.between(0, 3))});
            break;
          case 1:  // one deleted
            if (!face.lines.empty()) {
              const auto i = static_cast<size_t>(rng.between(0, static_cast<int>(face.lines.size()) - 1));
              touched.push_back(face.lines[i].sourceLine);
              deleted.push_back(face.lines[i].sourceLine);
              face.lines.erase(face.lines.begin() + static_cast<std::ptrdiff_t>(i));
            }
            break;
          case 2:  // one moved or retagged
            if (!face.lines.empty()) {
              auto& l = face.lines[static_cast<size_t>(rng.between(0, static_cast<int>(face.lines.size()) - 1))];
              touched.push_back(l.sourceLine);
              l.a = somePoint(rng, level.size);
              l.tag = static_cast<uint32_t>(rng.between(0, 3));
            }
            break;
          case 3:
            touched.push_back(level.start.sourceLine);
            level.start.position = somePoint(rng, level.size);
            break;
          case 4:
            touched.push_back(level.goal.sourceLine);
            level.goal.face = rng.between(0, static_cast<int>(level.faces.size()) - 1);
            break;
          case 5:
            touched.push_back(face.sourceLine);
            face.gravityQ16 =
                rng.between(0, 1) ? std::nullopt : std::optional(physics::Vec2w{rng.between(-30000, 30000), 7});
            break;
          default:  // a copy of a segment (its sourceLine copied too: the writer must see it is new)
            if (!face.lines.empty()) face.lines.push_back(face.lines.front());
            break;
        }
      }
      const std::string written = stage::writeLevel(level, text);
      stage::Level read;
      ASSERT_NO_THROW(read = stage::parseLevel(written, path)) << written;
      ASSERT_EQ(read, level) << difference(read, level) << "\n"
                             << written << "\nexpected face 1: " <<
          [&] {
            std::string o;
            for (const auto& l : level.faces[1].lines)
              o += std::to_string(l.a.x) + " " + std::to_string(l.a.y) + " " + std::to_string(l.b.x) + " " +
                   std::to_string(l.b.y) + " src " + std::to_string(l.sourceLine) + "; ";
            return o;
          }();
      const std::vector<std::string> after = linesOf(written);
      for (size_t i = 0; i < before.size(); ++i) {
        const std::string& line = before[i];
        const bool changed = std::find(touched.begin(), touched.end(), static_cast<int>(i) + 1) != touched.end();
        const size_t hash = line.find('#');
        if (!changed) {
          EXPECT_TRUE(contains(after, line)) << "line " << i + 1 << " went: " << line << "\n" << written;
        } else if (hash != std::string::npos && line.find_first_not_of(" \t") < hash &&
                   std::find(deleted.begin(), deleted.end(), static_cast<int>(i) + 1) == deleted.end()) {
          bool kept = false;  // a changed line keeps its comment
          for (const std::string& a : after) kept = kept || a.ends_with(line.substr(hash));
          EXPECT_TRUE(kept) << "line " << i + 1 << " lost its comment: " << line << "\n" << written;
        }
      }
      ++edits;
    }
  }
  EXPECT_GE(edits, 300);
}
