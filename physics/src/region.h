// The lines near one entity instance: the union of a rectangle of grid cells, kept up to date
// incrementally. When the rectangle moves, only the cells that enter or leave it are read; a per-line count of covering
// cells says when a line enters or leaves the region.
#pragma once
#include <span>
#include <vector>

#include "grid.h"

namespace platon::physics {

class Region {
 public:
  // Moves the rectangle to `want`, visiting only the cells that change.
  void update(const Grid& grid, const CellRect& want);
  void clear();
  // Whether every corner of `box` lies in the cell of `grid` the rectangle's corner has: then the
  // box covers the same cells, and updating to it would change nothing. (Four pairs of
  // comparisons where finding the cells takes four searches: every sub-move asks.)
  bool keeps(const Grid& grid, const Box& box) const {
    return grid_ == &grid && box.x0 >= from_.x0 && box.x0 < to_.x0 && box.y0 >= from_.y0 && box.y0 < to_.y0 &&
           box.x1 >= from_.x1 && box.x1 < to_.x1 && box.y1 >= from_.y1 && box.y1 < to_.y1;
  }

  const CellRect& rect() const { return rect_; }
  // Lines in the region, in the order they entered; each appears once.
  std::span<const uint32_t> lines() const { return lines_; }
  // One byte per line for the owner, parallel to lines(); 0 when the line enters. The world caches
  // there whether the line is pierceable for this entity.
  std::span<uint8_t> flags() { return flags_; }
  size_t cellsVisited() const { return cellsVisited_; }

 private:
  void addCell(const Grid& grid, int x, int y);
  void removeCell(const Grid& grid, int x, int y);
  uint32_t* find(uint32_t line);
  void insertSlot(uint32_t line, uint32_t count);
  void eraseSlot(uint32_t line);
  void grow();

  CellRect rect_;
  const Grid* grid_ = nullptr;  // the grid rect_ is in; null: none yet
  Box from_{}, to_{};           // per corner of a box, the range of its cell in rect_ (see keeps)
  std::vector<uint32_t> lines_;
  std::vector<uint8_t> flags_;
  // Open addressing, linear probing: key line + 1 (0 = empty), value = covering-cell count,
  // position in lines_.
  struct Slot {
    uint32_t key = 0;
    uint32_t count = 0;
    uint32_t index = 0;
  };
  std::vector<Slot> table_;
  size_t cellsVisited_ = 0;
};

}  // namespace platon::physics
