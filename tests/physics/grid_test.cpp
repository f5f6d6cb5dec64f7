// The grid never misses a line, and the incremental region always equals a fresh scan.
#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "region.h"  // internal: linked through platon_physics_internals

using namespace platon::physics;

namespace {

// Builds the grid with the box around the segments, as MapPart passes it.
void buildGrid(Grid& grid, std::span<const Segment> segments) {
  Vec2 low{INT32_MAX, INT32_MAX}, high{INT32_MIN, INT32_MIN};
  for (const Segment& s : segments) {
    low = {std::min({low.x, s.a.x, s.b.x}), std::min({low.y, s.a.y, s.b.y})};
    high = {std::max({high.x, s.a.x, s.b.x}), std::max({high.y, s.a.y, s.b.y})};
  }
  grid.build(segments, low, high);
}
std::vector<Segment> randomSegments(std::mt19937_64& rng, int n, int32_t half, int32_t maxLength) {
  std::vector<Segment> out;
  while (static_cast<int>(out.size()) < n) {
    const Vec2 a{static_cast<int32_t>(rng() % (2 * static_cast<uint64_t>(half))) - half,
                 static_cast<int32_t>(rng() % (2 * static_cast<uint64_t>(half))) - half};
    const Vec2 b{a.x + static_cast<int32_t>(rng() % (2 * maxLength + 1)) - maxLength,
                 a.y + static_cast<int32_t>(rng() % (2 * maxLength + 1)) - maxLength};
    if (a != b) out.push_back({a, b});
  }
  return out;
}

std::set<uint32_t> scan(const Grid& g, const CellRect& r) {
  std::set<uint32_t> out;
  if (r.empty()) return out;
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x)
      for (const uint32_t l : g.cell(x, y)) out.insert(l);
  return out;
}

// Exact: does the closed segment meet the closed box?
bool meets(const Segment& s, const Box& b) {
  const std::vector<Vec2> box{{static_cast<int32_t>(b.x0), static_cast<int32_t>(b.y0)},
                              {static_cast<int32_t>(b.x1), static_cast<int32_t>(b.y0)},
                              {static_cast<int32_t>(b.x1), static_cast<int32_t>(b.y1)},
                              {static_cast<int32_t>(b.x0), static_cast<int32_t>(b.y1)}};
  return touchesOrOverlaps(box, s);
}
}  // namespace

TEST(Grid, CellsCoveringABoxHoldEveryLineThatMeetsIt) {
  std::mt19937_64 rng(5);
  for (const int32_t maxLength : {3, 50, 5000}) {
    const auto segments = randomSegments(rng, 3000, 10000, maxLength);
    Grid grid;
    buildGrid(grid, segments);
    EXPECT_GE(grid.columns() * grid.rows(), 1000);
    EXPECT_LE(grid.columns() * grid.rows(), 20000);
    for (int q = 0; q < 300; ++q) {
      const int64_t x = static_cast<int64_t>(rng() % 24000) - 12000, y = static_cast<int64_t>(rng() % 24000) - 12000;
      const Box box{x, y, x + static_cast<int64_t>(rng() % 300) + 1, y + static_cast<int64_t>(rng() % 300) + 1};
      const std::set<uint32_t> found = scan(grid, grid.cellsCovering(box));
      for (uint32_t i = 0; i < segments.size(); ++i)
        if (meets(segments[i], box)) {
          ASSERT_TRUE(found.count(i)) << "line " << i << " missed, max length " << maxLength;
        }
    }
  }
}

TEST(Grid, EntriesGrowLinearlyWithShortLines) {
  std::mt19937_64 rng(6);
  size_t perLine[2];
  int k = 0;
  for (const int n : {1000, 100000}) {
    // Constant density: the area grows with the count.
    const int32_t half = static_cast<int32_t>(100 * std::sqrt(static_cast<double>(n)));
    Grid grid;
    const std::vector<Segment> segments = randomSegments(rng, n, half, 60);
    buildGrid(grid, segments);
    perLine[k++] = grid.entries() * 1000 / n;
  }
  EXPECT_LE(perLine[1], perLine[0] * 3 / 2) << "entries per line: " << perLine[0] << " vs " << perLine[1];
}

TEST(Region, IncrementalUpdatesMatchAFreshScan) {
  std::mt19937_64 rng(7);
  const auto segments = randomSegments(rng, 5000, 20000, 400);
  Grid grid;
  buildGrid(grid, segments);
  Region region;
  int64_t x = 0, y = 0;
  for (int step = 0; step < 3000; ++step) {
    x += static_cast<int64_t>(rng() % 801) - 400;
    y += static_cast<int64_t>(rng() % 801) - 400;
    const int64_t w = static_cast<int64_t>(rng() % 2000);
    const CellRect want = (step % 97 == 0) ? CellRect{} : grid.cellsCovering({x, y, x + w, y + w});
    region.update(grid, want);
    const std::set<uint32_t> expected = scan(grid, want);
    const std::set<uint32_t> got(region.lines().begin(), region.lines().end());
    ASSERT_EQ(got.size(), region.lines().size()) << "a line listed twice";
    ASSERT_EQ(got, expected) << "step " << step;
  }
}

// Region::keeps answers "would this box cover the same cells" from four ranges the region keeps
// (coverBox then skips the search). Over random maps (one line to thousands, clustered and spread),
// random walks of boxes of every size, small steps and jumps, and boxes reaching past the map on
// every side: it says yes exactly when the cells are the same, and a region from another grid is
// never kept.
TEST(Region, KeepsExactlyTheBoxesThatCoverItsCells) {
  std::mt19937_64 rng(11);
  int kept = 0, moved = 0;
  for (int map = 0; map < 40; ++map) {
    const int lines = map % 4 == 0 ? 1 + map / 4 : 200 + static_cast<int>(rng() % 3000);
    const int32_t half = map % 3 == 0 ? 2000 : 40000;
    const auto segments = randomSegments(rng, lines, half, map % 2 ? 300 : 5000);
    Grid grid, other;
    buildGrid(grid, segments);
    buildGrid(other, segments);
    Region region;
    int64_t x = 0, y = 0;
    for (int step = 0; step < 2000; ++step) {
      const int64_t jump = step % 50 == 0 ? 4 * half : 600;
      x += static_cast<int64_t>(rng() % static_cast<uint64_t>(2 * jump + 1)) - jump;
      y += static_cast<int64_t>(rng() % static_cast<uint64_t>(2 * jump + 1)) - jump;
      const int64_t w = static_cast<int64_t>(rng() % 3000), h = static_cast<int64_t>(rng() % 3000);
      const Box box{x, y, x + w, y + h};
      const CellRect cells = grid.cellsCovering(box, region.rect());
      ASSERT_EQ(cells, grid.cellsCovering(box)) << "the hinted search found other cells";
      const bool same = step > 0 && cells == region.rect();
      ASSERT_EQ(region.keeps(grid, box), same) << "map " << map << " step " << step;
      ASSERT_FALSE(region.keeps(other, box)) << "kept for another grid";
      kept += same, moved += !same;
      region.update(grid, cells);
      ASSERT_TRUE(region.keeps(grid, box));
    }
    region.update(grid, CellRect{});  // no cells: no box keeps them (every box covers some)
    ASSERT_FALSE(region.keeps(grid, {x, y, x, y})) << "kept an empty rectangle";
    region.update(grid, grid.cellsCovering({x, y, x, y}));
    region.clear();
    ASSERT_FALSE(region.keeps(grid, {0, 0, 0, 0})) << "kept after clear";
  }
  // Both answers were asked often.
  EXPECT_GT(kept, 10000);
  EXPECT_GT(moved, 10000);
}
