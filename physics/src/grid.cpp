#include "platon/physics/grid.h"

#include <algorithm>
#include <cmath>

namespace platon::physics {
namespace {

// Every k-th distinct value of the sorted projections, so about `count` cuts.
std::vector<int32_t> pickCuts(std::vector<int32_t> values, size_t count) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::vector<int32_t> cuts;
  if (values.empty()) return {0};
  count = std::clamp<size_t>(count, 1, values.size());
  const size_t step = values.size() / count;
  for (size_t i = 0; i < values.size(); i += step) cuts.push_back(values[i]);
  return cuts;
}

}  // namespace

int Grid::columnOf(int64_t x) const {
  const auto it = std::upper_bound(xCuts_.begin(), xCuts_.end(), x);
  return std::max(0, static_cast<int>(it - xCuts_.begin()) - 1);
}

int Grid::rowOf(int64_t y) const {
  const auto it = std::upper_bound(yCuts_.begin(), yCuts_.end(), y);
  return std::max(0, static_cast<int>(it - yCuts_.begin()) - 1);
}

CellRect Grid::cellsCovering(const Box& box) const {
  if (cellLines_.empty()) return {};
  return {columnOf(box.x0), rowOf(box.y0), columnOf(box.x1), rowOf(box.y1)};
}

int Grid::cutNear(const std::vector<int32_t>& cuts, int64_t v, int hint) {
  const int n = static_cast<int>(cuts.size());
  for (int step = 0; step < 4; ++step) {
    if (hint > 0 && v < cuts[hint]) {
      --hint;
    } else if (hint + 1 < n && v >= cuts[hint + 1]) {
      ++hint;
    } else {
      return hint;
    }
  }
  const auto it = std::upper_bound(cuts.begin(), cuts.end(), v);
  return std::max(0, static_cast<int>(it - cuts.begin()) - 1);
}

CellRect Grid::cellsCovering(const Box& box, const CellRect& near) const {
  if (cellLines_.empty()) return {};
  if (near.empty()) return cellsCovering(box);
  return {cutNear(xCuts_, box.x0, near.x0), cutNear(yCuts_, box.y0, near.y0), cutNear(xCuts_, box.x1, near.x1),
          cutNear(yCuts_, box.y1, near.y1)};
}

// Visits every cell a segment passes through (a superset near cell corners is harmless):
// column by column, the y-range of the segment inside the column's slab, rounded outwards.
template <class Visit>
void Grid::forEachCell(const Segment& s, Visit&& visit) const {
  Vec2 a = s.a, b = s.b;
  if (b.x < a.x) std::swap(a, b);
  const int c0 = columnOf(a.x), c1 = columnOf(b.x);
  const int64_t dx = int64_t{b.x} - a.x, dy = int64_t{b.y} - a.y;
  for (int c = c0; c <= c1; ++c) {
    int64_t lo, hi;
    if (dx == 0) {
      lo = std::min(a.y, b.y);
      hi = std::max(a.y, b.y);
    } else {
      const int64_t xl = c == c0 ? a.x : xCuts_[c];
      const int64_t xr = c == c1 ? b.x : xCuts_[c + 1];
      const int64_t yl = a.y + static_cast<int64_t>(floorDiv(i128{xl - a.x} * dy, dx));
      const int64_t yr = a.y + static_cast<int64_t>(floorDiv(i128{xr - a.x} * dy, dx));
      lo = std::min(yl, yr);
      hi = std::max(yl, yr) + 1;  // the floors above round down; one unit covers the ceiling
      lo = std::max<int64_t>(lo, std::min(a.y, b.y));
      hi = std::min<int64_t>(hi, std::max(a.y, b.y));
    }
    const int r0 = rowOf(lo), r1 = rowOf(hi);
    for (int r = r0; r <= r1; ++r) visit(static_cast<size_t>(r) * xCuts_.size() + c);
  }
}

void Grid::build(std::span<const Segment> segments) {
  const size_t n = segments.size();
  std::vector<int32_t> xs, ys;
  xs.reserve(2 * n);
  ys.reserve(2 * n);
  int64_t minX = INT64_MAX, maxX = INT64_MIN, minY = INT64_MAX, maxY = INT64_MIN;
  for (const Segment& s : segments) {
    for (const Vec2 p : {s.a, s.b}) {
      xs.push_back(p.x);
      ys.push_back(p.y);
      minX = std::min<int64_t>(minX, p.x), maxX = std::max<int64_t>(maxX, p.x);
      minY = std::min<int64_t>(minY, p.y), maxY = std::max<int64_t>(maxY, p.y);
    }
  }
  // About n cells, shaped after the map's extent so long levels get more columns than rows.
  const double width = n ? static_cast<double>(maxX - minX + 1) : 1.0;
  const double height = n ? static_cast<double>(maxY - minY + 1) : 1.0;
  const double cells = std::max<double>(1.0, static_cast<double>(n));
  const double aspect = std::clamp(width / height, 1.0 / cells, cells);
  xCuts_ = pickCuts(std::move(xs), static_cast<size_t>(std::ceil(std::sqrt(cells * aspect))));
  yCuts_ = pickCuts(std::move(ys), static_cast<size_t>(std::ceil(std::sqrt(cells / aspect))));

  const size_t cellCount = xCuts_.size() * yCuts_.size();
  cellStart_.assign(cellCount + 1, 0);
  for (const Segment& s : segments) forEachCell(s, [&](size_t c) { ++cellStart_[c + 1]; });
  for (size_t c = 0; c < cellCount; ++c) cellStart_[c + 1] += cellStart_[c];
  cellLines_.resize(cellStart_[cellCount]);
  std::vector<uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (uint32_t i = 0; i < n; ++i) forEachCell(segments[i], [&](size_t c) { cellLines_[fill[c]++] = i; });
}

size_t Grid::memoryBytes() const {
  return (xCuts_.capacity() + yCuts_.capacity()) * sizeof(int32_t) +
         (cellStart_.capacity() + cellLines_.capacity()) * sizeof(uint32_t);
}

}  // namespace platon::physics
