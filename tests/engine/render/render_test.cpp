// The renderer plugin, loaded as the engine loads it, drawing offscreen (SDL_VIDEODRIVER=offscreen:
// a GL core context on Mesa llvmpipe, no display needed). Pixels are read back and checked where
// the picture must have the face, a hazard line, the player's circle, the heads-up text and the
// error overlay.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "platon/core/display.h"
#include "platon/core/scene.h"
#include "platon/testing/mapped.h"
#include "platon/testing/pixels.h"
#include "platon/testing/temp_folder.h"

namespace platon {
namespace {

struct Rgba {
  int r, g, b, a;
};

class Renderer : public ::testing::Test {
 protected:
  void SetUp() override {
    setenv("SDL_VIDEODRIVER", "offscreen", 1);
    registry.addPlugin("rendering", "platon_render", {PLATON_PLUGIN_DIR});
    const std::string manifest =
        folder.write("scene.lua", "return { name = 'render test', systems = { 'rendering' } }");
    scene = core::loadScene(manifest, registry);
    ASSERT_NE(scene->findSystem("rendering"), nullptr);
    display = scene->findSystem("rendering")->display();
    ASSERT_NE(display, nullptr);
  }

  // A square face 0..1000 in the z = 0 plane (as the top of a cube whose centre is 500 below it)
  // with a hazard line along y = 100, seen from straight above: the camera 1600 over the face's
  // centre, looking down with +y up, so a face unit is 720 / (2 tan(22.5 deg) 1600) pixels.
  core::View squareFace() const {
    core::View view;
    view.title = "render test";
    auto stage = std::make_shared<core::StageView>();
    core::ViewFace face;
    face.part = 0;
    face.corners = {{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};
    face.xAxis = {1, 0, 0}, face.yAxis = {0, 1, 0}, face.normal = {0, 0, 1};
    face.lines.push_back({{100, 100}, {900, 100}, 1, 0, stage::gameTags()->style(1)});  // a hazard
    stage->faces.push_back(face);
    // Face 3: the cube's bottom, 1000 below, facing down: away from the camera.
    core::ViewFace bottom;
    bottom.part = 3;
    bottom.corners = face.corners;
    bottom.origin = {0, 1000, -1000}, bottom.xAxis = {1, 0, 0}, bottom.yAxis = {0, -1, 0}, bottom.normal = {0, 0, -1};
    stage->faces.push_back(bottom);
    stage->centre = {500, 500, -500};
    stage->radius = 866;
    stage->edge = 1000;
    view.stage = stage;
    view.camera.centre = {500, 500, -500};
    view.camera.distance = 2100;
    return view;
  }
  static constexpr float kPixelsPerUnit = 720.0f / (2 * 0.41421356f * 1600);

  Rgba at(const std::vector<uint8_t>& pixels, int width, int x, int y) const {
    const size_t i = (static_cast<size_t>(y) * width + x) * 4;
    return {pixels[i], pixels[i + 1], pixels[i + 2], pixels[i + 3]};
  }

  testing::TempFolder folder{"render"};
  core::SystemRegistry registry;
  std::unique_ptr<core::Scene> scene;
  core::Display* display = nullptr;
};

bool near(Rgba p, int r, int g, int b, int tolerance = 12) {
  return std::abs(p.r - r) <= tolerance && std::abs(p.g - g) <= tolerance && std::abs(p.b - b) <= tolerance;
}

std::string show(Rgba p) {
  return "(" + std::to_string(p.r) + ", " + std::to_string(p.g) + ", " + std::to_string(p.b) + ")";
}

TEST_F(Renderer, DrawsTheFaceItsLinesAndTheScriptsShapes) {
  core::DrawList draw(true);
  draw.circle(core::Place::onFace(0), {500, 500}, 50, {10, 200, 10, 255});
  draw.circle(core::Place::onFace(3), {500, 500}, 400, {200, 10, 200, 255});  // on the far side: hidden by the solid
  draw.text(core::Place::onFace(3), {100, 900}, "far side", 300, {200, 10, 200, 255});
  display->present(squareFace(), draw);
  int w = 0, h = 0;
  const std::vector<uint8_t> pixels = display->capture(w, h);
  ASSERT_EQ(w, 1280);
  ASSERT_EQ(h, 720);
  auto px = [&](float x, float y) {
    return at(pixels, w, static_cast<int>(640 + (x - 500) * kPixelsPerUnit),
              static_cast<int>(360 - (y - 500) * kPixelsPerUnit));
  };
  // The player's ball: green, lit (brighter or darker than the flat colour, never another hue).
  const Rgba ball = px(500, 500);
  EXPECT_TRUE(ball.g > 120 && ball.r < 80 && ball.b < 80) << "the player's ball: " << show(ball);
  // The hazard wall glows: its own colour exactly, whatever the light.
  EXPECT_TRUE(near(px(500, 100), 213, 94, 0)) << "the hazard line: " << show(px(500, 100));
  const Rgba face = px(200, 800);
  EXPECT_TRUE(face.b > face.r && face.b > 90 && face.b < 200) << "the face: " << show(face);
  EXPECT_TRUE(near(at(pixels, w, 100, 400), 20, 17, 36)) << "outside the face: " << show(at(pixels, w, 100, 400));
  for (int y = 0; y < h; y += 7)
    for (int x = 0; x < w; x += 7) {
      const Rgba p = at(pixels, w, x, y);
      ASSERT_FALSE(p.r > 120 && p.b > 120 && p.g < 60) << "the far side's shape or text shows at " << x << ", " << y;
    }
}

// What the world draws (drawWorld's shapes): a body is drawn once however many faces it spans, a
// platform's line shows as a plank, and a polygon body is cut at its face's edge. Two faces of a
// cube meet at x = 1000 (face 0 on top, face 1 the side, facing +x), seen from between their normals.
TEST_F(Renderer, DrawsEachBodyOnceAndThePlatformsOfTheWorld) {
  core::View view = squareFace();
  auto stage = std::make_shared<core::StageView>(*view.stage);
  core::ViewFace side;
  side.part = 1;
  side.corners = {{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};
  side.origin = {1000, 0, 0}, side.xAxis = {0, 0, -1}, side.yAxis = {0, 1, 0}, side.normal = {1, 0, 0};
  stage->faces.push_back(side);
  view.stage = stage;
  view.camera.centre = {1000, 500, 0};
  view.camera.distance = 1400;
  view.camera.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitY()));
  // The ball 20 units inside face 0's edge: an instance on each face, one body (drawn per instance,
  // a ball on each face's plane, two showed side by side).
  core::DrawList draw(true);
  const core::Color gold{242, 193, 78, 255};
  draw.circle(core::Place::onFace(0), {980, 500}, 100, gold, 7);
  draw.circle(core::Place::onFace(1), {-20, 500}, 100, gold, 7);
  display->present(view, draw);
  int w = 0, h = 0;
  std::vector<uint8_t> pixels = display->capture(w, h);
  EXPECT_EQ(testing::roundBlobs(pixels, w, h, testing::playerGold), 1) << "one ball";
  // The same two circles as two bodies (a script's own drawing): two balls, side by side.
  core::DrawList two(true);
  two.circle(core::Place::onFace(0), {980, 500}, 100, gold);
  two.circle(core::Place::onFace(1), {-20, 500}, 100, gold);
  display->present(view, two);
  pixels = display->capture(w, h);
  EXPECT_NE(testing::roundBlobs(pixels, w, h, testing::playerGold), 1) << "two balls are not one";
  // A platform's line, and a crate across the edge: its part beyond face 0 is drawn on face 1 only.
  core::DrawList world(true);
  world.wall(core::Place::onFace(0), {200, 300}, {600, 300}, 0, 0);
  const std::vector<core::Point2> crate{{900, 600}, {1100, 600}, {1100, 800}, {900, 800}};
  world.polygon(core::Place::onFace(0), crate, {176, 138, 90, 255}, 9);
  display->present(view, world);
  pixels = display->capture(w, h);
  auto teal = [](int r, int g, int b) { return g > 120 && b > 110 && r < g - 60; };
  auto wood = [](int r, int g, int b) { return r > 80 && r > b + 30 && g > b + 10 && r - g < 60 && r - g > 15; };
  int tealPixels = 0, woodPixels = 0;
  for (size_t i = 0; i < pixels.size(); i += 4) {
    tealPixels += teal(pixels[i], pixels[i + 1], pixels[i + 2]);
    woodPixels += wood(pixels[i], pixels[i + 1], pixels[i + 2]);
  }
  EXPECT_GT(tealPixels, 200) << "the platform";
  EXPECT_GT(woodPixels, 200) << "the crate";
}

TEST_F(Renderer, ShowsTheHeadsUpLinesAndTheErrorOverlay) {
  core::View view = squareFace();
  core::DrawList draw(true);
  display->present(view, draw);
  int w = 0, h = 0;
  const std::vector<uint8_t> plain = display->capture(w, h);
  view.hud = {"Cube: first steps    0:03    deaths 0"};
  view.error =
      "levels/x/level.lua:20: attempt to index a nil value\nstack traceback:\n\tlevels/x/level.lua:20: in function";
  display->present(view, draw);
  const std::vector<uint8_t> shown = display->capture(w, h);
  int bright = 0;  // text pixels in the heads-up corner
  for (int y = 8; y < 30; ++y)
    for (int x = 8; x < 300; ++x) bright += at(shown, w, x, y).r > 200 && at(plain, w, x, y).r < 60;
  EXPECT_GT(bright, 100);
  // The overlay: a red box along the bottom, over the face too, with white text on it.
  const Rgba box = at(shown, w, 1200, h - 20);
  EXPECT_GT(box.r, 90);
  EXPECT_LT(box.g, 40);
  EXPECT_TRUE(near(at(plain, w, 1200, h - 20), 22, 24, 30)) << show(at(plain, w, 1200, h - 20));
  int white = 0;
  for (int y = h - 100; y < h; ++y)
    for (int x = 16; x < 400; ++x) white += near(at(shown, w, x, y), 255, 255, 255, 40);
  EXPECT_GT(white, 100);
}

// Multisampling is set on the open window and takes effect on the next frame: the edges of a ball
// and of a tilted face turn to blends (a few pixels differ, nothing else), and back again.
TEST_F(Renderer, MultisamplingSmoothsEdgesFromTheNextFrameAndGoesBack) {
  core::View view = squareFace();
  view.camera.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  core::DrawList draw(true);
  draw.circle(core::Place::onFace(0), {500, 500}, 120, {240, 200, 40, 255});
  auto frame = [&](int samples) {
    display->setMultisamples(samples);
    display->present(view, draw);
    int w = 0, h = 0;
    std::vector<uint8_t> pixels = display->capture(w, h);
    EXPECT_EQ(w, 1280);
    EXPECT_EQ(h, 720);
    return pixels;
  };
  const std::vector<uint8_t> plain = frame(0), smooth = frame(4), again = frame(0), chosen = frame(-1);
  size_t differ = 0;
  for (size_t i = 0; i < plain.size(); i += 4)
    differ += plain[i] != smooth[i] || plain[i + 1] != smooth[i + 1] || plain[i + 2] != smooth[i + 2];
  EXPECT_GT(differ, 500u) << "4 samples changed no edge";
  EXPECT_LT(differ, plain.size() / 4 / 50) << "4 samples changed more than the edges";
  EXPECT_EQ(again, plain) << "multisampling turned off is the picture without it";
  EXPECT_EQ(chosen, plain) << "auto on a software rasterizer samples once";
}

TEST_F(Renderer, SavesAScreenshotAsPng) {
  display->present(squareFace(), core::DrawList(true));
  const std::string path = folder.path("shot.png");
  display->saveScreenshot(path);
  std::ifstream file(path, std::ios::binary);
  std::string head(8, '\0');
  file.read(head.data(), 8);
  EXPECT_EQ(head, "\x89PNG\r\n\x1a\n");
  EXPECT_THROW(display->saveScreenshot("/nonexistent/folder/shot.png"), std::runtime_error);
}

// The plugin is loaded only when a scene names it, and only then are SDL2 and GL in the process.
TEST(Plugins, LoadedOnlyWhenASceneNamesThem) {
  using platon::testing::mapped;
  // "threadsafe": the child is this program started afresh, running this test alone, so nothing an
  // earlier test loaded is mapped in it.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        setenv("SDL_VIDEODRIVER", "offscreen", 1);
        testing::TempFolder folder("plugins");
        core::SystemRegistry registry;
        registry.addPlugin("rendering", "platon_render", {PLATON_PLUGIN_DIR});
        auto bare = core::loadScene(folder.write("a.lua", "return { name = 'a' }"), registry);
        const bool before = mapped("libplaton_render") || mapped("libSDL2") || mapped("libGL");
        auto shown =
            core::loadScene(folder.write("b.lua", "return { name = 'b', systems = { 'rendering' } }"), registry);
        shown->findSystem("rendering")->display()->present({}, core::DrawList(true));
        const bool after = mapped("libplaton_render") && mapped("libSDL2") && mapped("libGL");
        if (before || !after) std::fprintf(stderr, "mapped before the scene named it: %d, after: %d\n", before, after);
        std::exit(!before && after ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST(Plugins, AMissingModuleNamesWhereItLooked) {
  testing::TempFolder folder("plugins");
  core::SystemRegistry registry;
  registry.addPlugin("rendering", "platon_no_such_module", {folder.path("")});
  try {
    core::loadScene(folder.write("a.lua", "return { name = 'a', systems = { 'rendering' } }"), registry);
    FAIL() << "no error";
  } catch (const std::exception& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("system 'rendering': cannot load its plugin libplaton_no_such_module.so"), std::string::npos)
        << message;
    EXPECT_NE(message.find(folder.path("libplaton_no_such_module.so")), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace platon
