// The irregular grid of one map part: which lines pass through which cell.
//
// The seed cuts the plane at the projection of every endpoint. That makes (2n)^2 cells for n lines,
// quadratic in time and memory. We keep the seed's idea (cuts placed where the endpoints are, so
// dense areas get small cells) but take only every k-th projection: about sqrt(n * aspect) columns
// and sqrt(n / aspect) rows, so about n cells in all. Building sorts the projections (n log n), then
// counts and fills a compressed cell -> lines table in two linear passes; memory is one offset
// per cell plus one entry per (line, cell) crossing.
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
  void build(std::span<const Segment> segments);

  int columns() const { return static_cast<int>(xCuts_.size()); }
  int rows() const { return static_cast<int>(yCuts_.size()); }
  // Cells whose area meets the closed box (clamped to the grid; cells on the border extend outwards).
  CellRect cellsCovering(const Box& box) const;
  // The same, searching outwards from `near` first: a moving entity's rectangle shifts by a cell
  // or two per frame, so this is a few comparisons instead of four binary searches.
  CellRect cellsCovering(const Box& box, const CellRect& near) const;
  std::span<const uint32_t> cell(int column, int row) const {
    const size_t c = static_cast<size_t>(row) * xCuts_.size() + column;
    return {cellLines_.data() + cellStart_[c], cellLines_.data() + cellStart_[c + 1]};
  }
  size_t memoryBytes() const;
  size_t entries() const { return cellLines_.size(); }

 private:
  int columnOf(int64_t x) const;
  int rowOf(int64_t y) const;
  static int cutNear(const std::vector<int32_t>& cuts, int64_t v, int hint);
  template <class Visit>
  void forEachCell(const Segment& s, Visit&& visit) const;

  std::vector<int32_t> xCuts_;  // column c covers [xCuts_[c], xCuts_[c+1]); the ends extend to infinity
  std::vector<int32_t> yCuts_;
  std::vector<uint32_t> cellStart_;  // size cells + 1
  std::vector<uint32_t> cellLines_;
};

}  // namespace platon::physics
