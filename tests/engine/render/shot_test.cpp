// Render tests: `platon shot` of a level on each solid and mesh stage, at a frame of its recorded
// play-through, against a stored picture (tests/data/render/). Mesa's llvmpipe is deterministic
// on one machine, but drivers and versions round edges differently: a pixel counts as different
// when a channel is off by more than 40, and a picture passes with at most 1.5% such pixels and a
// mean difference of at most 3 per channel. A second test shows that the tolerance still tells
// levels apart. PLATON_UPDATE_RENDER_REFERENCES=1 writes the stored pictures anew.
#include <SDL2/SDL.h>
#include <SDL2/SDL_image.h>
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "platon/testing/pixels.h"
#include "platon/testing/temp_folder.h"

namespace {

struct Picture {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;
};

Picture load(const std::string& path) {
  Picture p;
  SDL_Surface* loaded = IMG_Load(path.c_str());
  if (!loaded) return p;
  SDL_Surface* rgba = SDL_ConvertSurfaceFormat(loaded, SDL_PIXELFORMAT_ABGR8888, 0);
  SDL_FreeSurface(loaded);
  if (!rgba) return p;
  p.width = rgba->w, p.height = rgba->h;
  for (int y = 0; y < rgba->h; ++y) {
    const auto* row = static_cast<const uint8_t*>(rgba->pixels) + static_cast<size_t>(y) * rgba->pitch;
    p.rgba.insert(p.rgba.end(), row, row + static_cast<size_t>(rgba->w) * 4);
  }
  SDL_FreeSurface(rgba);
  return p;
}

struct Difference {
  double differentShare = 1;  // of the pixels
  double meanPerChannel = 255;
};

Difference compare(const Picture& a, const Picture& b) {
  Difference d;
  if (a.width != b.width || a.height != b.height || a.rgba.empty()) return d;
  size_t different = 0;
  double total = 0;
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int delta = std::abs(int{a.rgba[i + c]} - int{b.rgba[i + c]});
      worst = std::max(worst, delta);
      total += delta;
    }
    different += worst > 40;
  }
  const double pixels = static_cast<double>(a.rgba.size()) / 4;
  d.differentShare = static_cast<double>(different) / pixels;
  d.meanPerChannel = total / (pixels * 3);
  return d;
}

struct Case {
  const char* level;
  const char* replay;
  int frame;
};

const Case kCases[] = {
    {"tetra_underside", "tetra_underside_drop", 1010},
    {"cube_switches", "cube_switches_solve", 560},
    {"octa_ring", "octa_ring_run", 1000},
    {"dodeca_trapdoor", "dodeca_trapdoor_solve", 120},
    {"icosa_drop", "icosa_drop_solve", 640},
    {"prism", "prism_walk", 500},
    {"soccer_ball", "soccer_ball_walk", 500},
    {"cube_lift", "cube_lift_ride", 300},       // the lift, a platform a script made, with the player on it
    {"cube_bridge", "cube_bridge_cross", 200},  // the bridge, a platform a script turns, half way round
    {"tetra_around", "tetra_around_run", 366},  // the player over a sharp edge
};

class Shots : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { IMG_Init(IMG_INIT_PNG); }
  std::string shoot(const Case& c, const char* size = "320x180", const std::string& extra = "") {
    std::string out = folder.path(std::string(c.level) + std::to_string(c.frame) + (extra.empty() ? "" : "x") + ".png");
    const std::string command = std::string("SDL_VIDEODRIVER=offscreen ") + PLATON_EXE + " shot " + c.level +
                                " --input tests/replays/" + c.replay + ".replay --frame " + std::to_string(c.frame) +
                                " --size " + size + " " + extra + " --out " + out + " > /dev/null";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return out;
  }
  static std::string reference(const Case& c) { return std::string("tests/data/render/") + c.level + ".png"; }
  platon::testing::TempFolder folder{"shots"};
};

TEST_F(Shots, EveryStageLooksAsStored) {
  const bool update = std::getenv("PLATON_UPDATE_RENDER_REFERENCES") != nullptr;
  for (const Case& c : kCases) {
    SCOPED_TRACE(c.level);
    const std::string shot = shoot(c);
    if (update) std::system(("cp " + shot + " " + reference(c)).c_str());
    const Picture now = load(shot), stored = load(reference(c));
    ASSERT_FALSE(now.rgba.empty()) << "no picture at " << shot << ": " << IMG_GetError();
    ASSERT_FALSE(stored.rgba.empty()) << "no stored picture " << reference(c)
                                      << " (PLATON_UPDATE_RENDER_REFERENCES=1 writes it)";
    const Difference d = compare(now, stored);
    EXPECT_LE(d.differentShare, 0.015) << "pixels off by more than 40: " << d.differentShare * 100 << "%";
    EXPECT_LE(d.meanPerChannel, 3.0) << "mean difference per channel";
  }
}

// The tolerance is not so wide that any picture passes: each stage against every other's stored
// picture fails it, and so does the same stage a second later.
TEST_F(Shots, TheToleranceTellsStagesAndMomentsApart) {
  std::vector<Picture> stored;
  for (const Case& c : kCases) {
    stored.push_back(load(reference(c)));
    ASSERT_FALSE(stored.back().rgba.empty()) << "no stored picture " << reference(c);
    ASSERT_EQ(stored.back().width, stored.front().width);
    ASSERT_EQ(stored.back().height, stored.front().height);
  }
  for (size_t i = 0; i < stored.size(); ++i)
    for (size_t j = 0; j < stored.size(); ++j) {
      if (i == j) continue;
      const Difference d = compare(stored[i], stored[j]);
      EXPECT_TRUE(d.differentShare > 0.015 || d.meanPerChannel > 3.0)
          << kCases[i].level << " passes as " << kCases[j].level;
    }
  Case later = kCases[0];
  later.frame += 60;
  const Picture moved = load(shoot(later));
  ASSERT_EQ(moved.width, stored[0].width);
  ASSERT_EQ(moved.height, stored[0].height);
  const Difference d = compare(moved, stored[0]);
  EXPECT_TRUE(d.differentShare > 0.015 || d.meanPerChannel > 3.0) << "a second later passes as the stored moment";
}

// The player is one body and is drawn once: on every stage, at frames around its first crossing of
// an edge (where it has an instance on each face: two balls side by side showed on the
// tetrahedron), exactly one ball shows, never none (no wall or face hides it) and never two.
TEST_F(Shots, ThePlayerIsDrawnOnceAcrossEdges) {
  const Case crossings[] = {
      {"tetra_around", "tetra_around_run", 366},
      {"soccer_ball", "soccer_ball_walk", 248},
      {"icosa_drop", "icosa_drop_solve", 161},
      {"octa_ring", "octa_ring_run", 366},
      {"dodeca_belt", "dodeca_belt_run", 407},
      {"cube_intro", "cube_intro_walk", 414},
      {"prism", "prism_walk", 120},
  };
  for (const Case& crossing : crossings)
    for (const int offset : {-16, -8, 0, 8, 16}) {
      Case c = crossing;
      c.frame += offset;
      const Picture p = load(shoot(c, "640x360"));
      ASSERT_FALSE(p.rgba.empty());
      EXPECT_EQ(platon::testing::roundBlobs(p.rgba, p.width, p.height, platon::testing::playerGold), 1)
          << c.level << " at frame " << c.frame;
    }
}

// Each event reads without the HUD: the frames after it show its particles (and its flash) where the
// frame before did not. Counted by colour, in the frame before and a few frames after.
TEST_F(Shots, EventsReadWithoutTheHud) {
  struct Event {
    Case at;  // the frame the event's sound plays on
    const char* what;
    bool (*colour)(int r, int g, int b);
  };
  const Event events[] = {
      {{"cube_switches", "cube_switches_hazard", 212},
       "death's sparks",
       [](int r, int g, int b) { return r > 150 && g * 10 < r * 6 && g * 10 > r * 2 && b * 10 < r * 4; }},
      {{"cube_switches", "cube_switches_hazard", 79},
       "checkpoint's sparks",
       [](int r, int g, int b) { return g > 120 && g > r + 50 && g > b + 40; }},
      {{"cube_switches", "cube_switches_solve", 279},
       "switch's sparks",
       [](int r, int g, int b) { return r > 150 && g > 120 && b * 10 < g * 5; }},
      {{"cube_switches", "cube_switches_solve", 673},
       "goal's confetti",
       [](int r, int g, int b) { return r > 150 && g > 100 && b * 10 < g * 6; }},
  };
  auto count = [](const Picture& p, bool (*colour)(int, int, int)) {
    int n = 0;
    for (size_t i = 0; i < p.rgba.size(); i += 4) n += colour(p.rgba[i], p.rgba[i + 1], p.rgba[i + 2]);
    return n;
  };
  for (const Event& e : events) {
    Case before = e.at, after = e.at;
    before.frame -= 1, after.frame += 4;
    const Picture a = load(shoot(before, "640x360")), b = load(shoot(after, "640x360"));
    ASSERT_FALSE(a.rgba.empty());
    ASSERT_FALSE(b.rgba.empty());
    EXPECT_GT(count(b, e.colour), count(a, e.colour) + 60) << e.what << " at frame " << after.frame;
  }
}

}  // namespace

namespace {

// The debug view (`platon shot --debug`, F2 in a window) draws what the physics sees, over walls
// and bodies: counted by the overlay's colours, which the game's own picture never shows.
TEST_F(Shots, TheDebugViewShowsLinesPlatformsContactsAndCopies) {
  auto near = [](int r, int g, int b, int R, int G, int B) {
    return std::abs(r - R) < 40 && std::abs(g - G) < 40 && std::abs(b - B) < 40;
  };
  struct Look {
    const char* what;
    Case at;
    int r, g, b;
  };
  const Look looks[] = {
      {"solid lines", {"cube_switches", "cube_switches_solve", 120}, 160, 255, 120},
      {"a contact and its normal", {"cube_switches", "cube_switches_solve", 120}, 255, 60, 60},
      {"the moving platform", {"cube_lift", "cube_lift_ride", 200}, 230, 60, 230},
      {"a copy across an edge", {"tetra_around", "tetra_around_run", 365}, 255, 140, 0},
  };
  for (const Look& l : looks) {
    const Picture plain = load(shoot(l.at, "640x360")), debug = load(shoot(l.at, "640x360", "--debug"));
    ASSERT_FALSE(plain.rgba.empty());
    ASSERT_FALSE(debug.rgba.empty());
    auto count = [&](const Picture& p) {
      int n = 0;
      for (size_t i = 0; i < p.rgba.size(); i += 4) n += near(p.rgba[i], p.rgba[i + 1], p.rgba[i + 2], l.r, l.g, l.b);
      return n;
    };
    EXPECT_GT(count(debug), count(plain) + 30) << l.what << ": " << count(debug) << " against " << count(plain);
  }
}

}  // namespace
