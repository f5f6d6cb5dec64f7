// The level editor driven headless with the events a window gives (mouse presses at pixels, keys):
// picking hits the face and point under the pointer on every solid, drawing makes the segment the
// mouse drew, every kind of edit is undone and redone exactly, an edit that breaks the level is
// shown where it is and its save refused, and saving keeps the file's comments.
#include "platon/editor/editor.h"

#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "platon/testing/rng.h"
#include "platon/testing/temp_folder.h"

using namespace platon;

namespace {

constexpr int64_t kGravity = 22938;  // 0.35 in Q16, the scenes' default

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::string levelFile(const std::string& name) {
  return std::string(PLATON_SOURCE_ROOT) + "/levels/" + name + "/" + name + ".level";
}

editor::Editor editorOf(const std::string& path, const std::string& text) {
  editor::LevelDocument document(path, text, stage::gameTags());
  stage::Stage solid = stage::platonicStageOf(document.level());
  return editor::Editor(std::move(document), std::move(solid), kGravity);
}

editor::Editor editorOf(const std::string& path) { return editorOf(path, readFile(path)); }

// The window as a test drives it: the pointer stays where the last event left it.
struct Driver {
  editor::Editor& e;
  float x = 0, y = 0;
  bool alt = false;  // held: no snapping

  core::WindowInput input() const {
    core::WindowInput in;
    in.width = e.lens().width, in.height = e.lens().height;
    in.mouseX = x, in.mouseY = y, in.alt = alt;
    return in;
  }
  void moveTo(const Eigen::Vector2d& p) {
    x = float(p.x()), y = float(p.y());
    e.handle(input());
  }
  void button(const Eigen::Vector2d& p, core::MouseEvent::Kind kind, uint8_t which = 1) {
    moveTo(p);
    core::WindowInput in = input();
    in.mouse.push_back({kind, which, x, y, 0});
    e.handle(in);
  }
  void click(const Eigen::Vector2d& p) {
    button(p, core::MouseEvent::Kind::Down);
    button(p, core::MouseEvent::Kind::Up);
  }
  void drag(const Eigen::Vector2d& from, const Eigen::Vector2d& to, uint8_t which = 1) {
    button(from, core::MouseEvent::Kind::Down, which);
    moveTo((from + to) / 2);
    button(to, core::MouseEvent::Kind::Up, which);
  }
  editor::Editor::Request key(const std::string& name, bool ctrl = false, bool shift = false) {
    core::WindowInput in = input();
    in.keys.push_back({name, ctrl, shift, false});
    return e.handle(in);
  }
};

// The pixel of a point of face `face` as the editor's camera shows it.
Eigen::Vector2d pixelOf(const editor::Editor& e, int face, double x, double y) {
  const auto at = editor::toScreen(e.lens(), *e.stageView(), {face, x, y});
  EXPECT_TRUE(at);
  return at ? *at : Eigen::Vector2d(0, 0);
}

// A face the camera looks at squarely (the start's): the points of a grid across it that show.
int frontFace(const editor::Editor& e) { return e.document().level().start.face; }

}  // namespace

// Points of every face of every solid, seen from a camera round the solid: the pick through the
// point's pixel finds that face and that point, to a small fraction of a unit per pixel.
TEST(EditorPick, TheRayThroughAPointsPixelFindsThePoint) {
  platon::testing::Rng rng{23};
  int picked = 0;
  for (const stage::Solid solid : stage::kSolids) {
    const stage::Stage s = stage::platonicStage(solid, 4096);
    physics::World world;
    stage::Stage copy = s;
    stage::addStageToWorld(copy, world, 0);
    const auto view = core::stageView(copy, world);
    for (int round = 0; round < 200; ++round) {
      editor::Lens lens;
      const Eigen::Vector3d axis = Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
      if (axis.norm() < 1e-3) continue;
      lens.pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(rng.uniform(0, 6.28), axis.normalized()));
      lens.pose.centre = s.centre;
      lens.pose.distance = view->radius * rng.uniform(1.5, 4);
      const int face = rng.between(0, static_cast<int>(s.faceCount()) - 1);
      const auto& c = s.faces[static_cast<size_t>(face)].corners;
      // a point inside the face: a random mix of its corners, kept off the very border
      double wx = 0, wy = 0, total = 0;
      for (const physics::Vec2 p : c) {
        const double w = rng.uniform(0.2, 1);
        wx += w * p.x, wy += w * p.y, total += w;
      }
      const editor::FacePoint point{face, wx / total, wy / total};
      const Eigen::Vector3d n = s.faces[static_cast<size_t>(face)].normal;
      const Eigen::Vector3d toEye = lens.pose.eye() - s.faces[static_cast<size_t>(face)].toWorld(point.x, point.y);
      if (n.dot(toEye.normalized()) < 0.2) continue;  // turned away or edge on
      const auto pixel = editor::toScreen(lens, *view, point);
      ASSERT_TRUE(pixel);
      const auto hit = editor::pickFace(*view, editor::rayThrough(lens, pixel->x(), pixel->y()));
      ASSERT_TRUE(hit) << stage::solidName(solid) << " face " << face;
      // A nearer face may hide it (a solid is convex: none does from outside).
      EXPECT_EQ(hit->face, face);
      EXPECT_NEAR(hit->x, point.x, 0.5);
      EXPECT_NEAR(hit->y, point.y, 0.5);
      ++picked;
    }
  }
  EXPECT_GE(picked, 300);
}

namespace {

// A point a fraction `t` of the way from face f's centre to its corner k (inside the face).
editor::FacePoint toward(const editor::Editor& e, int f, size_t k, double t) {
  const auto& c = e.solid().faces[static_cast<size_t>(f)].corners;
  double cx = 0, cy = 0;
  for (const physics::Vec2 p : c) cx += p.x, cy += p.y;
  cx /= static_cast<double>(c.size()), cy /= static_cast<double>(c.size());
  return {f, cx + t * (c[k % c.size()].x - cx), cy + t * (c[k % c.size()].y - cy)};
}

Eigen::Vector2d pixelOf(const editor::Editor& e, editor::FacePoint p) { return pixelOf(e, p.face, p.x, p.y); }

const stage::LevelLine& lastLine(const editor::Editor& e, int face) {
  return e.document().level().faces[static_cast<size_t>(face)].lines.back();
}

}  // namespace

// On a level of each solid: a drag on the face in view draws that segment (snapping off: to the
// unit; on: to the grid), a click and a click draw one too, and the new segment is selected.
TEST(Editor, TheMouseDrawsTheSegmentItDrawsOnEverySolid) {
  for (const std::string name : {"tetra_around", "cube_intro", "octa_ring", "dodeca_trapdoor", "icosa_drop"}) {
    SCOPED_TRACE(name);
    editor::Editor e = editorOf(levelFile(name));
    Driver d{e};
    const int f = frontFace(e);
    const size_t before = e.document().level().faces[static_cast<size_t>(f)].lines.size();
    const editor::FacePoint p = toward(e, f, 0, 0.4), q = toward(e, f, 1, 0.4);
    d.alt = true;
    d.drag(pixelOf(e, p), pixelOf(e, q));
    ASSERT_EQ(e.document().level().faces[static_cast<size_t>(f)].lines.size(), before + 1);
    const stage::LevelLine l = lastLine(e, f);
    EXPECT_NEAR(l.a.x, p.x, 3);
    EXPECT_NEAR(l.a.y, p.y, 3);
    EXPECT_NEAR(l.b.x, q.x, 3);
    EXPECT_NEAR(l.b.y, q.y, 3);
    EXPECT_EQ(e.selection(), (std::vector<editor::SegmentRef>{{f, static_cast<int>(before)}}));
    // Snapping to the grid, by two clicks; Esc ends the chain the second click went on with.
    d.alt = false;
    const editor::FacePoint r = toward(e, f, 2, 0.5);
    d.click(pixelOf(e, q));
    d.click(pixelOf(e, r));
    d.key("Escape");
    ASSERT_EQ(e.document().level().faces[static_cast<size_t>(f)].lines.size(), before + 2);
    const stage::LevelLine g = lastLine(e, f);
    EXPECT_EQ(g.a, l.b) << "the second segment starts at the first one's end (snapped to it)";
    EXPECT_EQ(g.b.x % 64, 0);
    EXPECT_EQ(g.b.y % 64, 0);
    EXPECT_NEAR(g.b.x, r.x, 46);
    EXPECT_NEAR(g.b.y, r.y, 46);
    EXPECT_TRUE(e.loads());
  }
}

// Each kind of edit made with the mouse and keys, then undone one by one back to the file as it was
// (byte for byte) and redone to the end.
TEST(Editor, EveryKindOfEditIsUndoneAndRedone) {
  const std::string path = levelFile("cube_switches");
  const std::string original = readFile(path);
  editor::Editor e = editorOf(path, original);
  Driver d{e};
  const int f = frontFace(e);
  std::vector<std::string> texts{e.document().text()};
  auto changed = [&](const std::string& what) {
    ASSERT_NE(e.document().text(), texts.back()) << what << " changed nothing: " << e.message();
    texts.push_back(e.document().text());
  };
  const editor::FacePoint p = toward(e, f, 0, 0.3), q = toward(e, f, 1, 0.3), r = toward(e, f, 3, 0.3);
  d.alt = true;
  d.drag(pixelOf(e, p), pixelOf(e, q));
  changed("draw");
  const int index = static_cast<int>(e.document().level().faces[static_cast<size_t>(f)].lines.size()) - 1;
  d.key("S");
  const stage::LevelLine drawn = lastLine(e, f);
  d.drag(pixelOf(e, f, drawn.b.x, drawn.b.y), pixelOf(e, r));  // an end point
  changed("move an end");
  {
    const stage::LevelLine& l = lastLine(e, f);
    const editor::FacePoint mid{f, (l.a.x + l.b.x) / 2.0, (l.a.y + l.b.y) / 2.0};
    d.drag(pixelOf(e, mid), pixelOf(e, {f, mid.x + 100, mid.y - 60}));  // the whole segment
    changed("move a segment");
  }
  d.click(
      pixelOf(e, f, (lastLine(e, f).a.x + lastLine(e, f).b.x) / 2.0, (lastLine(e, f).a.y + lastLine(e, f).b.y) / 2.0));
  ASSERT_EQ(e.selection(), (std::vector<editor::SegmentRef>{{f, index}}));
  d.key("T");
  changed("tag");
  d.key("]");
  d.key("T", false, true);
  changed("tag number");
  d.key("O");
  changed("one-way");
  d.key("C", true);
  d.moveTo(pixelOf(e, toward(e, f, 2, 0.2)));
  d.key("V", true);
  changed("paste");
  d.key("Delete");
  changed("delete");
  d.moveTo(pixelOf(e, toward(e, f, 1, 0.1)));
  d.key("P");
  changed("start");
  d.moveTo(pixelOf(e, toward(e, f, 3, 0.15)));
  d.key("G");
  changed("goal");
  d.key("V");
  changed("gravity");
  EXPECT_EQ(texts.size(), 12u);  // the file and eleven edits
  for (size_t i = texts.size() - 1; i > 0; --i) {
    d.key("Z", true);
    EXPECT_EQ(e.document().text(), texts[i - 1]) << "undo " << i;
  }
  EXPECT_EQ(e.document().text(), original);
  EXPECT_FALSE(e.document().modified());
  for (size_t i = 1; i < texts.size(); ++i) {
    d.key(i % 2 ? "Y" : "Z", true, i % 2 == 0);
    EXPECT_EQ(e.document().text(), texts[i]) << "redo " << i;
  }
}

// The start put into a wall: the check's error is drawn at the start, the level does not load, and
// Ctrl+S refuses (the file stays); Ctrl+Shift+S saves it anyway. A good save keeps every comment.
TEST(Editor, ABrokenEditIsShownAndItsSaveRefusedAndASaveKeepsComments) {
  const platon::testing::TempFolder folder("editor_save");
  const std::string original = readFile(levelFile("cube_switches"));
  const std::string path = folder.write("cube_switches.level", original);
  editor::Editor e = editorOf(path);
  Driver d{e};
  d.alt = true;
  // Face 0's floor runs along y = 1200 from x 200 to 1900: onto it.
  d.moveTo(pixelOf(e, 0, 1000, 1230));
  ASSERT_TRUE(e.cursor());
  d.key("P");
  EXPECT_FALSE(e.loads());
  bool shown = false;
  for (const editor::Marker& m : e.markers()) shown = shown || (m.on == editor::Marker::On::Start && m.error);
  EXPECT_TRUE(shown);
  core::DrawList list(true);
  e.draw(list);
  EXPECT_GT(list.shapes().size(), 10u);
  d.key("S", true);
  EXPECT_EQ(readFile(path), original);
  EXPECT_NE(e.message().find("not saved"), std::string::npos) << e.message();
  d.key("S", true, true);
  EXPECT_EQ(readFile(path), e.document().text());
  EXPECT_NE(readFile(path), original);
  d.key("Z", true);  // the start back where it was
  EXPECT_TRUE(e.loads());
  size_t empty = 0;  // "faces 2, 3, 4, 5 have no lines": one finding, each face outlined
  for (const editor::Marker& m : e.markers()) empty += m.on == editor::Marker::On::Face ? 1 : 0;
  EXPECT_EQ(empty, 4u);
  d.key("Home");
  d.drag(pixelOf(e, 0, 2400, 2000), pixelOf(e, 0, 3400, 2200));
  d.key("S", true);
  const std::string saved = readFile(path);
  EXPECT_EQ(saved, e.document().text());
  for (size_t start = 0; start < original.size();) {
    const size_t end = std::min(original.find('\n', start), original.size());
    const std::string line = original.substr(start, end - start);
    if (line.find('#') != std::string::npos) {
      EXPECT_NE(saved.find(line), std::string::npos) << line;
    }
    start = end + 1;
  }
  EXPECT_EQ(stage::parseLevel(saved, path), e.document().level());
}

// The palette is the scene's tag table: a mod's word is there, in its place, and a segment drawn
// with it is written with the mod's word; segments a hand-edited file put off their face are each
// marked as errors (the check itself stops at the first), and the level does not load.
TEST(Editor, APaletteHoldsTheModsWordsAndEverySegmentOffItsFaceIsMarked) {
  auto tags = std::make_shared<stage::TagTable>(*stage::gameTags());
  tags->add({"spring", stage::kFirstModTag, 0, stage::Passage::Wall, {40, 200, 90, false, false}, "a mod"});
  const std::string text =
      "HEXAHEDRON\n0 600 700\n0 3000 700\n4096\n%\n100 500 4000 500  # floor\n"
      "5000 100 5100 100  # off the face\n100 3000 200 -50  # off too\n%\n%\n%\n%\n%\n";
  editor::LevelDocument document("t.level", text, tags);
  stage::Stage solid = stage::platonicStageOf(document.level());
  editor::Editor e(std::move(document), std::move(solid), kGravity);
  size_t off = 0;
  for (const editor::Marker& m : e.markers()) off += m.on == editor::Marker::On::Segment && m.error ? 1 : 0;
  EXPECT_EQ(off, 2u);
  EXPECT_FALSE(e.loads());
  ASSERT_EQ(e.palette().back().word, "spring");
  Driver d{e};
  while (e.palette()[e.paletteIndex()].word != "spring") d.key("T");
  d.alt = true;
  d.drag(pixelOf(e, 0, 1000, 1500), pixelOf(e, 0, 2000, 1500));
  EXPECT_EQ(lastLine(e, 0).tag, stage::kFirstModTag);
  EXPECT_NE(e.document().text().find("spring\n"), std::string::npos) << e.document().text();
  d.key("S");
  d.click(pixelOf(e, 0, 1500, 1500));
  d.key("Delete");  // the drawn one goes; the two off the face are still marked
  EXPECT_EQ(e.document().level().faces[0].lines.size(), 3u);
  off = 0;
  for (const editor::Marker& m : e.markers()) off += m.on == editor::Marker::On::Segment && m.error ? 1 : 0;
  EXPECT_EQ(off, 2u);
  EXPECT_NE(e.document().text().find("# off too"), std::string::npos);
}

// The undo history keeps the latest steps within its byte budget: a long session on a big level
// does not grow without end, and what is kept still undoes exactly.
TEST(LevelDocument, TheUndoHistoryKeepsTheLatestStepsWithinItsBudget) {
  std::string text = "HEXAHEDRON\n0 600 700\n0 3000 700\n4096\n%\n";
  for (int i = 0; i < 20000; ++i) text += "100 " + std::to_string(800 + i % 3000) + " 200 900\n";
  text += "%\n%\n%\n%\n%\n";
  editor::LevelDocument document("big.level", text, stage::gameTags());
  const size_t perStep = text.size();
  std::vector<std::string> texts{document.text()};
  for (int i = 0; i < 200; ++i) {
    ASSERT_TRUE(document.edit("move", [&](stage::Level& l) { l.start.position.x = 601 + i; }));
    texts.push_back(document.text());
  }
  EXPECT_LE(document.undoSteps() * perStep, editor::LevelDocument::kMaxUndoBytes + perStep);
  EXPECT_LT(document.undoSteps(), 200u);
  const size_t kept = document.undoSteps();
  for (size_t i = 0; i < kept; ++i) ASSERT_TRUE(document.undo());
  EXPECT_FALSE(document.undo());
  EXPECT_EQ(document.text(), texts[texts.size() - 1 - kept]);
}

// A downloaded level folder can hold links named as a save's files might be (the level's name
// with .new, .partial, .tmp, ~) that lead outside it. Ctrl+S saves the level and changes nothing
// outside; a level file that is itself a link is not saved, and the editor says why.
TEST(Editor, CtrlSNeverWritesThroughALinkPlantedInTheLevelsFolder) {
  namespace fs = std::filesystem;
  for (const char* suffix : {".new", ".partial", ".tmp", "~", ""}) {
    SCOPED_TRACE(std::string("a link named cube_switches.level") + suffix);
    const platon::testing::TempFolder folder("editor_links");
    const std::string victim = folder.write("outside/victim.txt", "the player's own file\n");
    const std::string original = readFile(levelFile("cube_switches"));
    const std::string path = folder.write("level/cube_switches.level", original);
    editor::Editor e = editorOf(path);
    const fs::path planted = folder.path(std::string("level/cube_switches.level") + suffix);
    if (*suffix == '\0') {  // the level file itself: read already, then made a link to the outside file
      fs::remove(planted);
      fs::create_symlink(victim, planted);
    } else {
      fs::create_symlink(victim, planted);
    }
    Driver d{e};
    d.alt = true;
    d.drag(pixelOf(e, 0, 2400, 2000), pixelOf(e, 0, 3400, 2200));
    d.key("S", true);
    EXPECT_EQ(readFile(victim), "the player's own file\n");
    EXPECT_TRUE(fs::is_symlink(planted));
    if (*suffix == '\0') {
      EXPECT_NE(e.message().find("it is a link"), std::string::npos) << e.message();
    } else {
      EXPECT_EQ(readFile(path), e.document().text());
      EXPECT_FALSE(fs::is_symlink(path));
    }
  }
}
