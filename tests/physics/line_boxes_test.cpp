// The overlap check's index of line boxes finds exactly the boxes a brute-force pass finds, over
// families of maps (random, stacked floors, rows of walls, long diagonals, one point, equal boxes)
// and query boxes of every size; and what it walks grows with what the query meets, not with the
// map: a body among 10^6 stacked floors looks at a few dozen of them.
#include "line_boxes.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "platon/testing/rng.h"

using namespace platon::physics;

namespace {

using Box = LineBoxes::Box;

std::vector<uint32_t> bruteForce(const std::vector<LineBoxes::Item>& items, const Box& q) {
  std::vector<uint32_t> out;
  for (const auto& i : items)
    if (i.box.x0 <= q.x1 && q.x0 <= i.box.x1 && i.box.y0 <= q.y1 && q.y0 <= i.box.y1) out.push_back(i.key);
  return out;
}

Box boxOf(int64_t ax, int64_t ay, int64_t bx, int64_t by) {
  return {std::min(ax, bx), std::min(ay, by), std::max(ax, bx), std::max(ay, by)};
}

}  // namespace

TEST(LineBoxes, FindExactlyTheBoxesABruteForcePassFinds) {
  platon::testing::Rng rng{2026};
  for (int family = 0; family < 6; ++family)
    for (int map = 0; map < 40; ++map) {
      const int n = rng.between(0, 600);
      std::vector<LineBoxes::Item> items;
      for (int k = 0; k < n; ++k) {
        const int64_t x = rng.between(-5000, 5000), y = rng.between(-5000, 5000);
        const int64_t len = rng.between(0, 3000);
        Box b{};
        switch (family) {
          case 0:
            b = boxOf(x, y, rng.between(-5000, 5000), rng.between(-5000, 5000));
            break;
          case 1:
            b = boxOf(-5000, y, 5000, y);
            break;  // stacked floors
          case 2:
            b = boxOf(x, -5000, x, 5000);
            break;  // a row of walls
          case 3:
            b = boxOf(x, y, x + len, y + len);
            break;
          case 4:
            b = boxOf(x, y, x, y);
            break;  // points
          case 5:
            b = boxOf(0, 0, 10, 10);
            break;  // all the same
        }
        items.push_back({b, static_cast<uint32_t>(k)});
      }
      const LineBoxes index(items);
      for (int q = 0; q < 60; ++q) {
        const int64_t x = rng.between(-6000, 6000), y = rng.between(-6000, 6000), size = rng.between(0, 4000);
        const Box query =
            q % 7 == 0 ? boxOf(-9000, -9000, 9000, 9000) : boxOf(x, y, x + size, y + rng.between(0, 4000));
        std::vector<uint32_t> found;
        index.query(query, [&](uint32_t key) { found.push_back(key); });
        std::sort(found.begin(), found.end());
        ASSERT_EQ(found, bruteForce(items, query)) << "family " << family << " map " << map << " query " << q;
      }
    }
}

TEST(LineBoxes, AQueryWalksWhatItMeetsNotTheMap) {
  for (const bool floors : {true, false}) {
    std::vector<LineBoxes::Item> items;
    for (uint32_t k = 0; k < 1'000'000; ++k) {
      const int64_t at = int64_t{k} * 4;
      items.push_back({floors ? Box{0, at, 4'000'000, at} : Box{at, 0, at, 4'000'000}, k});
    }
    const LineBoxes index(std::move(items));
    size_t met = 0;
    const size_t work = index.query({2'000'000, 2'000'000, 2'000'100, 2'000'100}, [&](uint32_t) { ++met; });
    EXPECT_EQ(met, 26u);
    EXPECT_LT(work, 200u) << (floors ? "floors" : "walls");
  }
}
