// The irregular grid of one map part: which lines pass through which cell.
//
// The seed cuts the plane at the projection of every endpoint. That makes (2n)^2 cells for n lines,
// quadratic in time and memory. We keep the seed's idea (cuts placed where the endpoints are, so
// dense areas get small cells) but take only every k-th projection: about sqrt(n * aspect) columns
// and sqrt(n / aspect) rows, so about n cells in all. Building sorts the projections (n log n), then
// counts and fills a compressed cell -> lines table in two linear passes; memory is one offset
// per cell plus one entry per (line, cell) crossing. Lines are taken in the order given and each
// line's cells are searched for beside the previous line's, so a level that lists neighbouring
// lines together (they all do) fills the table nearly sequentially; a shuffled list is about three
// times slower, from cache misses alone.
#pragma once
#include <span>
#include <vector>

#include "platon/physics/sweep.h"

namespace platon::physics {

struct CellRect {  // inclusive cell index ranges; empty when x0 > x1
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool empty() const { return x0 > x1 || y0 > y1; }
  bool contains(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
  bool containsRect(const CellRect& r) const {
    return r.empty() || (!empty() && r.x0 >= x0 && r.x1 <= x1 && r.y0 >= y0 && r.y1 <= y1);
  }
  friend bool operator==(const CellRect&, const CellRect&) = default;
};

struct Box {  // closed integer box
  int64_t x0, y0, x1, y1;
};

class Grid {
 public:
  // `low` and `high`: the box around every segment (the map part keeps it as lines come).
  void build(std::span<const Segment> segments, Vec2 low, Vec2 high);

  int columns() const { return static_cast<int>(xAxis_.cuts.size()); }
  int rows() const { return static_cast<int>(yAxis_.cuts.size()); }
  // Cells whose area meets the closed box (clamped to the grid; cells on the border extend outwards).
  CellRect cellsCovering(const Box& box) const;
  // The same, searching outwards from `near` first: a moving entity's rectangle shifts by a cell
  // or two per frame, so this is a few comparisons instead of four binary searches. (Inline: every
  // sub-move of every body asks it.)
  CellRect cellsCovering(const Box& box, const CellRect& near) const {
    if (cellLines_.empty()) return {};
    if (near.empty()) return cellsCovering(box);
    return {xAxis_.cellNear(box.x0, near.x0), yAxis_.cellNear(box.y0, near.y0), xAxis_.cellNear(box.x1, near.x1),
            yAxis_.cellNear(box.y1, near.y1)};
  }
  // For each corner of a box whose cells are `r` (as cellsCovering gives them; not empty), the
  // coordinates that fall in the same cell: from <= coordinate < to, per corner (x0, y0, x1, y1).
  void cellRanges(const CellRect& r, Box& from, Box& to) const;
  std::span<const uint32_t> cell(int column, int row) const {
    const size_t c = static_cast<size_t>(row) * xAxis_.cuts.size() + column;
    return {cellLines_.data() + cellStart_[c], cellLines_.data() + cellStart_[c + 1]};
  }
  size_t memoryBytes() const;
  size_t entries() const { return cellLines_.size(); }

 private:
  // Cuts along one axis, with a uniform bucket table over their range so that finding the cell of
  // a coordinate is a table read and a search among the few cuts in one bucket.
  struct Axis {
    std::vector<int32_t> cuts;    // cell i covers [cuts[i], cuts[i+1]); the ends extend to infinity
    std::vector<uint32_t> first;  // per bucket: index of the first cut at or after the bucket's start
    int64_t origin = 0;
    int shift = 0;
    void index();
    int cellOf(int64_t v) const;
    // The coordinates in cell i: [low, high), the end cells reaching to infinity.
    int64_t low(int i) const { return i <= 0 ? INT64_MIN : cuts[static_cast<size_t>(i)]; }
    int64_t high(int i) const {
      return i + 1 >= static_cast<int>(cuts.size()) ? INT64_MAX : cuts[static_cast<size_t>(i) + 1];
    }
    int cellNear(int64_t v, int hint) const {  // looks beside `hint` first
      const int n = static_cast<int>(cuts.size());
      if (hint < 0 || hint >= n) return cellOf(v);
      for (int step = 0; step < 3; ++step) {
        if (hint > 0 && v < cuts[hint]) {
          --hint;
        } else if (hint + 1 < n && v >= cuts[hint + 1]) {
          ++hint;
        } else {
          return hint;
        }
      }
      return cellOf(v);
    }
    size_t bytes() const { return cuts.capacity() * 4 + first.capacity() * 4; }
  };
  int columnOf(int64_t x) const { return xAxis_.cellOf(x); }
  int rowOf(int64_t y) const { return yAxis_.cellOf(y); }
  template <class Visit>
  void forEachCell(const Segment& s, const CellRect& span, Visit&& visit) const;

  Axis xAxis_, yAxis_;
  std::vector<uint32_t> cellStart_;  // size cells + 1
  std::vector<uint32_t> cellLines_;
};

}  // namespace platon::physics
