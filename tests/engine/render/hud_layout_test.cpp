// The screen's text never overlaps itself and stays in the window, at any size from 320x180 up
// (and at twice the pixels a point): every heads-up line, the frame rate and each line of the centre
// block (the level select, the pause menu, the settings) against every other, over a family of
// windows, line counts and line lengths. The text is measured as DejaVu Sans about measures it.
#include "hud_layout.h"

#include <gtest/gtest.h>

using platon::render::layOut;
using platon::render::TextBox;

namespace {

float measure(const std::string& text, float size) { return 0.58f * size * static_cast<float>(text.size()); }

std::vector<std::string> lines(int count, size_t length) {
  std::vector<std::string> out;
  for (int i = 0; i < count; ++i) out.push_back(std::string(length + static_cast<size_t>(i % 3) * 7, 'x'));
  return out;
}

TEST(HudLayout, NothingOverlapsOrLeavesTheWindowAtAnySize) {
  int windows = 0;
  for (const float width : {320.0f, 400.0f, 640.0f, 1280.0f, 1920.0f, 3840.0f, 500.0f})
    for (const float height : {180.0f, 240.0f, 360.0f, 720.0f, 1080.0f, 2160.0f, 1000.0f})
      for (const float dpi : {1.0f, 2.0f})
        for (const int hudLines : {0, 1, 3})
          for (const size_t hudLength : {10u, 90u})
            for (const int centreLines : {0, 4, 18, 20})
              for (const size_t centreLength : {12u, 70u})
                for (const bool fps : {false, true}) {
                  ++windows;
                  const auto l = layOut(width, height, dpi, lines(hudLines, hudLength),
                                        lines(centreLines, centreLength), fps ? "60 fps  16.67 ms" : "", measure);
                  const std::string where = std::to_string(int(width)) + "x" + std::to_string(int(height)) + " dpi " +
                                            std::to_string(int(dpi)) + ", " + std::to_string(hudLines) +
                                            " HUD lines of " + std::to_string(hudLength) + ", " +
                                            std::to_string(centreLines) + " centre lines of " +
                                            std::to_string(centreLength) + (fps ? ", fps" : "");
                  std::vector<const TextBox*> boxes;
                  for (const TextBox& b : l.hud) boxes.push_back(&b);
                  for (const TextBox& b : l.centre) boxes.push_back(&b);
                  if (l.fps.width > 0) boxes.push_back(&l.fps);
                  for (const TextBox* b : boxes) {
                    ASSERT_GE(b->x, 0) << where << ": '" << b->text << "'";
                    ASSERT_GE(b->y, 0) << where << ": '" << b->text << "'";
                    ASSERT_LE(b->x + b->width, width + 0.5f) << where << ": '" << b->text << "'";
                    ASSERT_LE(b->y + b->height, height + 0.5f) << where << ": '" << b->text << "'";
                  }
                  for (size_t i = 0; i < boxes.size(); ++i)
                    for (size_t j = i + 1; j < boxes.size(); ++j)
                      ASSERT_FALSE(boxes[i]->overlaps(*boxes[j]))
                          << where << ": '" << boxes[i]->text << "' and '" << boxes[j]->text << "'";
                  // The centre block's band covers no heads-up line.
                  if (!l.centre.empty()) {
                    for (const TextBox& h : l.hud) {
                      ASSERT_FALSE(h.overlaps(l.centreBand)) << where << ": '" << h.text << "'";
                    }
                  }
                }
  EXPECT_GT(windows, 5000);
}

// A line too long for its place is cut, with "...", not left to run off the window.
TEST(HudLayout, ALongLineIsCutToFit) {
  const auto l = layOut(320, 180, 1, {std::string(200, 'y')}, {}, "60 fps  16.67 ms", measure);
  ASSERT_EQ(l.hud.size(), 1u);
  EXPECT_EQ(l.hud[0].text.substr(l.hud[0].text.size() - 3), "...");
  EXPECT_FALSE(l.hud[0].overlaps(l.fps));
}

}  // namespace
