#include "grid.h"

#include <algorithm>
#include <utility>

#include "fixed_point.h"

namespace platon::physics {
namespace {

// LSD radix sort, a byte per pass: linear, where std::sort's n log n dominated initialize().
void radixSort(std::vector<int32_t>& values) {
  std::vector<uint32_t> a(values.size()), b(values.size());
  for (size_t i = 0; i < values.size(); ++i) a[i] = static_cast<uint32_t>(values[i]) ^ 0x80000000u;
  for (int shift = 0; shift < 32; shift += 8) {
    size_t start[257] = {};
    for (const uint32_t x : a) ++start[((x >> shift) & 255) + 1];
    if (start[((a.empty() ? 0 : a[0]) >> shift & 255) + 1] == a.size()) continue;  // one bucket: nothing to do
    for (int k = 0; k < 256; ++k) start[k + 1] += start[k];
    for (const uint32_t x : a) b[start[(x >> shift) & 255]++] = x;
    a.swap(b);
  }
  for (size_t i = 0; i < values.size(); ++i) values[i] = static_cast<int32_t>(a[i] ^ 0x80000000u);
}

// Every k-th distinct value of the sorted projections, so about `count` cuts.
std::vector<int32_t> pickCuts(std::vector<int32_t> values, size_t count) {
  radixSort(values);
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::vector<int32_t> cuts;
  if (values.empty()) return {0};
  count = std::clamp<size_t>(count, 1, values.size());
  const size_t step = values.size() / count;
  for (size_t i = 0; i < values.size(); i += step) cuts.push_back(values[i]);
  return cuts;
}

}  // namespace

void Grid::Axis::index() {
  // About four buckets per cut, each a power-of-two wide.
  origin = cuts.front();
  const int64_t span = int64_t{cuts.back()} - origin + 1;
  shift = 0;
  while ((span >> shift) > static_cast<int64_t>(4 * cuts.size())) ++shift;
  const size_t buckets = static_cast<size_t>((span >> shift) + 2);
  first.assign(buckets + 1, 0);
  size_t cut = 0;
  for (size_t b = 0; b <= buckets; ++b) {
    const int64_t start = origin + (static_cast<int64_t>(b) << shift);
    while (cut < cuts.size() && cuts[cut] < start) ++cut;
    first[b] = static_cast<uint32_t>(cut);
  }
}

int Grid::Axis::cellOf(int64_t v) const {
  if (v < origin) return 0;
  const size_t b = std::min(static_cast<size_t>((v - origin) >> shift), first.size() - 2);
  // Cuts before bucket b are all <= v; search the bucket's own cuts for the last one <= v.
  const auto begin = cuts.begin() + first[b], end = cuts.begin() + first[b + 1];
  return std::max(0, static_cast<int>(std::upper_bound(begin, end, v) - cuts.begin()) - 1);
}

CellRect Grid::cellsCovering(const Box& box) const {
  if (cellLines_.empty()) return {};
  return {columnOf(box.x0), rowOf(box.y0), columnOf(box.x1), rowOf(box.y1)};
}

void Grid::cellRanges(const CellRect& r, Box& from, Box& to) const {
  from = {xAxis_.low(r.x0), yAxis_.low(r.y0), xAxis_.low(r.x1), yAxis_.low(r.y1)};
  to = {xAxis_.high(r.x0), yAxis_.high(r.y0), xAxis_.high(r.x1), yAxis_.high(r.y1)};
}

// Visits every cell a segment passes through (a superset near cell corners is harmless). `span` is
// the segment's column and row range, found once by the caller. Within one column (most lines are
// short) that range is the answer; otherwise the segment is walked column by column, taking the
// y-range of the segment inside each column's slab, rounded outwards.
template <class Visit>
void Grid::forEachCell(const Segment& s, const CellRect& span, Visit&& visit) const {
  const size_t stride = xAxis_.cuts.size();
  if (span.x0 == span.x1 || span.y0 == span.y1) {  // one column or one row: the box is the answer
    for (int r = span.y0; r <= span.y1; ++r)
      for (int c = span.x0; c <= span.x1; ++c) visit(static_cast<size_t>(r) * stride + c);
    return;
  }
  Vec2 a = s.a, b = s.b;
  if (b.x < a.x) std::swap(a, b);
  const int64_t dx = int64_t{b.x} - a.x, dy = int64_t{b.y} - a.y;  // dx > 0 here
  for (int c = span.x0; c <= span.x1; ++c) {
    const int64_t xl = c == span.x0 ? a.x : xAxis_.cuts[c];
    const int64_t xr = c == span.x1 ? b.x : xAxis_.cuts[c + 1];
    const int64_t yl = a.y + static_cast<int64_t>(floorDiv(i128{xl - a.x} * dy, dx));
    const int64_t yr = a.y + static_cast<int64_t>(floorDiv(i128{xr - a.x} * dy, dx));
    // The floors round down; one more unit covers the ceiling. Clamp to the segment's own range.
    const int64_t lo = std::max<int64_t>(std::min(yl, yr), std::min(a.y, b.y));
    const int64_t hi = std::min<int64_t>(std::max(yl, yr) + 1, std::max(a.y, b.y));
    const int r0 = yAxis_.cellNear(lo, span.y0), r1 = yAxis_.cellNear(hi, span.y1);
    for (int r = r0; r <= r1; ++r) visit(static_cast<size_t>(r) * stride + c);
  }
}

void Grid::build(std::span<const Segment> segments, Vec2 low, Vec2 high) {
  const size_t n = segments.size();
  const int64_t minX = low.x, maxX = high.x, minY = low.y, maxY = high.y;
  // About n cells, shaped after the map's extent so long levels get more columns than rows.
  // Columns are ceil(sqrt(n * width / height)) and rows ceil(sqrt(n * height / width)), each
  // between 1 and n, in exact integers.
  const uint64_t width = n ? static_cast<uint64_t>(maxX - minX + 1) : 1;
  const uint64_t height = n ? static_cast<uint64_t>(maxY - minY + 1) : 1;
  const uint64_t cells = std::max<uint64_t>(1, n);
  auto sideFor = [&](uint64_t along, uint64_t across) {
    const u128 want = static_cast<u128>(cells) * along;  // side^2 * across >= want
    uint64_t side = std::clamp<uint64_t>(isqrt(want / across), 1, cells);
    while (side < cells && static_cast<u128>(side) * side * across < want) ++side;
    return static_cast<size_t>(side);
  };
  // Cuts at endpoint projections. Only quantiles are needed, so a systematic sample of about 16
  // projections per cut serves as well as all of them and keeps the sort small.
  auto cutsFor = [&](bool x, size_t count) {
    const size_t values = 2 * n;
    const size_t stride = std::max<size_t>(1, values / (16 * std::max<size_t>(count, 1)));
    std::vector<int32_t> sample;
    sample.reserve(values / stride + 1);
    for (size_t v = 0; v < values; v += stride) {
      const Segment& s = segments[v / 2];
      const Vec2 p = (v & 1) ? s.b : s.a;
      sample.push_back(x ? p.x : p.y);
    }
    return pickCuts(std::move(sample), count);
  };
  xAxis_.cuts = cutsFor(true, sideFor(width, height));
  yAxis_.cuts = cutsFor(false, sideFor(height, width));
  xAxis_.index();
  yAxis_.index();

  // One pass over the lines finds their cells (each line's from the previous line's: levels list
  // neighbouring lines together, so the cell table is visited in nearly sequential order) and
  // counts each cell's entries; a second pass, over what the first wrote down, fills the
  // compressed table without any geometry.
  const size_t cellCount = xAxis_.cuts.size() * yAxis_.cuts.size();
  // The cells of line 0, then of line 1, ...; the top bit marks a line's last cell (cells number
  // about as many as lines, fewer than 2^31: a map part holds fewer lines than that).
  constexpr uint32_t kLast = 0x80000000u;
  std::vector<uint32_t> entryCells;
  entryCells.reserve(n + n / 2);
  cellStart_.assign(cellCount + 1, 0);
  CellRect span{0, 0, 0, 0};
  for (uint32_t i = 0; i < n; ++i) {
    const Segment& s = segments[i];
    span = {xAxis_.cellNear(std::min(s.a.x, s.b.x), span.x0), yAxis_.cellNear(std::min(s.a.y, s.b.y), span.y0),
            xAxis_.cellNear(std::max(s.a.x, s.b.x), span.x1), yAxis_.cellNear(std::max(s.a.y, s.b.y), span.y1)};
    forEachCell(s, span, [&](size_t cell) {
      entryCells.push_back(static_cast<uint32_t>(cell));
      ++cellStart_[cell + 1];
    });
    entryCells.back() |= kLast;  // every line has at least one cell
  }
  // cellStart_[c + 1] becomes cell c's start and serves as its write cursor, so that after the
  // fill it holds cell c's end, which is cell c + 1's start: no second table needed.
  uint32_t running = 0;
  for (size_t c = 0; c < cellCount; ++c) running += std::exchange(cellStart_[c + 1], running);
  cellLines_.resize(running);
  uint32_t line = 0;
  for (const uint32_t entry : entryCells) {
    cellLines_[cellStart_[(entry & ~kLast) + 1]++] = line;
    line += entry >> 31;
  }
}

size_t Grid::memoryBytes() const {
  return xAxis_.bytes() + yAxis_.bytes() + (cellStart_.capacity() + cellLines_.capacity()) * sizeof(uint32_t);
}

}  // namespace platon::physics
