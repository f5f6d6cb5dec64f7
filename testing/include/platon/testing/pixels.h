// Reading a rendered picture as a person would: where a colour forms round blobs (a ball), so a
// test can say "one ball shows" rather than compare pixels one by one.
#pragma once
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace platon::testing {

// The round blobs of pixels `in(r, g, b)` picks in a width x height RGBA picture (rows from the
// top): 4-connected regions of at least `least` pixels whose box is nearly square (the longer side
// at most 1.3 times the shorter) and over half filled. Two balls side by side, overlapping or not,
// are not one round blob; a line of the same colour is not one either.
template <class Picks>
int roundBlobs(const std::vector<uint8_t>& rgba, int width, int height, Picks in, int least = 30) {
  auto picked = [&](int x, int y) {
    const uint8_t* c = &rgba[(static_cast<size_t>(y) * width + x) * 4];
    return in(int{c[0]}, int{c[1]}, int{c[2]});
  };
  std::vector<uint8_t> seen(static_cast<size_t>(width) * height, 0);
  int blobs = 0;
  for (int y0 = 0; y0 < height; ++y0)
    for (int x0 = 0; x0 < width; ++x0) {
      if (seen[static_cast<size_t>(y0) * width + x0] || !picked(x0, y0)) continue;
      int area = 0, left = x0, right = x0, top = y0, bottom = y0;
      std::vector<std::pair<int, int>> todo{{x0, y0}};
      seen[static_cast<size_t>(y0) * width + x0] = 1;
      while (!todo.empty()) {
        const auto [x, y] = todo.back();
        todo.pop_back();
        ++area, left = std::min(left, x), right = std::max(right, x), top = std::min(top, y),
                bottom = std::max(bottom, y);
        for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          uint8_t& s = seen[static_cast<size_t>(ny) * width + nx];
          if (!s && picked(nx, ny)) s = 1, todo.push_back({nx, ny});
        }
      }
      const int w = right - left + 1, h = bottom - top + 1;
      if (area >= least && std::max(w, h) * 10 <= 13 * std::min(w, h) && area * 2 >= w * h) ++blobs;
    }
  return blobs;
}

// The game's player colour (0xf2c14e), lit: darker or brighter, the same hue.
inline bool playerGold(int r, int g, int b) { return r > 90 && r >= g && g > b + 30 && r > b + 60 && g * 10 > r * 6; }

}  // namespace platon::testing
