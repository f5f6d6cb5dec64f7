// Where the screen's text goes: the heads-up lines (top left), the frame-rate box (top right) and
// the centre block (titles, menus), so that none overlaps another or leaves the window at any
// size. Plain arithmetic over a text-measuring function, so a test can lay out any window.
#pragma once
#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace platon::render {

struct TextBox {
  // Pixels, from the top left: a line's backing box (the renderer draws it from 4 points left and 2
  // above its text, which starts at x, y).
  float x = 0, y = 0, width = 0, height = 0;
  std::string text;  // as it fits (cut with "..." when it did not)
  float size = 0;    // the text's height
  bool overlaps(const TextBox& o) const {
    return x < o.x + o.width && o.x < x + width && y < o.y + o.height && o.y < y + height;
  }
};

struct ScreenLayout {
  std::vector<TextBox> hud, centre;
  TextBox fps;         // width 0: none
  TextBox centreBand;  // the dark band behind the centre block
};

// `measure(text, size)`: the text's width in pixels at that height. `dpi`: pixels per point.
inline ScreenLayout layOut(float width, float height, float dpi, const std::vector<std::string>& hud,
                           const std::vector<std::string>& centre, const std::string& fps,
                           const std::function<float(const std::string&, float)>& measure) {
  ScreenLayout out;
  const float pad = std::min(8 * dpi, width / 80);
  // The heads-up lines: 18 points tall, less on a small window (a 30th of its height at most, and a
  // 45th of its width).
  const float hudSize = std::max(6.0f, std::min({18 * dpi, height / 30, width / 45})), hudStep = hudSize * 1.45f;
  float fpsWidth = 0;
  if (!fps.empty()) {
    fpsWidth = measure(fps, hudSize) + 8 * dpi;
    out.fps = {width - fpsWidth - pad, pad, fpsWidth, hudSize * 1.35f, fps, hudSize};
  }
  // A line as long as fits in `room` pixels at `size`: cut, with "...", when it is longer.
  auto fitted = [&](std::string text, float size, float room) {
    if (measure(text, size) <= room) return text;
    while (text.size() > 1 && measure(text + "...", size) > room) text.pop_back();
    return text + "...";
  };
  float y = pad;
  for (size_t i = 0; i < hud.size(); ++i) {
    // The first line shares the top with the frame-rate box; the others have the whole width.
    const float room = width - 2 * pad - 8 * dpi - (i == 0 && fpsWidth > 0 ? fpsWidth + pad : 0);
    const std::string text = fitted(hud[i], hudSize, std::max(room, 0.0f));
    out.hud.push_back({pad, y, measure(text, hudSize) + 8 * dpi, hudSize * 1.35f, text, hudSize});
    y += hudStep;
  }
  if (centre.empty()) return out;
  // The centre block: below the heads-up lines, as big as fits both ways (30 points at most).
  float top = hud.empty() ? 0 : y;
  if (!fps.empty()) top = std::max(top, out.fps.y + out.fps.height + pad);
  const float lines = static_cast<float>(centre.size()) + 1.5f, available = height - top - pad;
  float size = std::min(30 * dpi, available / (lines * 1.4f));
  for (size_t i = 0; i < centre.size(); ++i) {
    const float scale = i == 0 ? 1.3f : 1.0f;
    const float w = measure(centre[i], size * scale);
    if (w > width * 0.94f) size *= width * 0.94f / w;
  }
  size = std::max(size, 4.0f);
  const float step = size * 1.4f, blockHeight = step * static_cast<float>(centre.size()) + size;
  const float blockTop = std::max(top + size, top + (available - blockHeight) / 2 + size * 0.5f);
  out.centreBand = {0, blockTop - size, width, blockHeight + size, "", 0};
  for (size_t i = 0; i < centre.size(); ++i) {
    const float lineSize = i == 0 ? size * 1.3f : size;
    const std::string text = fitted(centre[i], lineSize, width * 0.98f);
    const float w = measure(text, lineSize);
    out.centre.push_back({(width - w) / 2, blockTop + static_cast<float>(i) * step, w, lineSize, text, lineSize});
  }
  return out;
}

}  // namespace platon::render
