#include "region.h"

namespace platon::physics {
namespace {
inline size_t hashLine(uint32_t line, size_t mask) { return (size_t{line} * 2654435761u) & mask; }
}  // namespace

void Region::clear() {
  rect_ = {};
  grid_ = nullptr;
  lines_.clear();
  flags_.clear();
  table_.clear();
}

void Region::grow() {
  std::vector<Slot> old = std::move(table_);
  table_.assign(old.empty() ? 64 : old.size() * 2, Slot{});
  const size_t mask = table_.size() - 1;
  for (const Slot& s : old) {
    if (s.key == 0) continue;
    size_t i = hashLine(s.key - 1, mask);
    while (table_[i].key != 0) i = (i + 1) & mask;
    table_[i] = s;
  }
}

uint32_t* Region::find(uint32_t line) {
  if (table_.empty()) return nullptr;
  const size_t mask = table_.size() - 1;
  for (size_t i = hashLine(line, mask);; i = (i + 1) & mask) {
    if (table_[i].key == 0) return nullptr;
    if (table_[i].key == line + 1) return &table_[i].count;
  }
}

void Region::insertSlot(uint32_t line, uint32_t count) {
  if ((lines_.size() + 1) * 2 > table_.size()) grow();
  const size_t mask = table_.size() - 1;
  size_t i = hashLine(line, mask);
  while (table_[i].key != 0) i = (i + 1) & mask;
  table_[i] = {line + 1, count, static_cast<uint32_t>(lines_.size())};
  lines_.push_back(line);
  flags_.push_back(0);
}

void Region::eraseSlot(uint32_t line) {
  const size_t mask = table_.size() - 1;
  size_t i = hashLine(line, mask);
  while (table_[i].key != line + 1) i = (i + 1) & mask;
  // Swap-remove from the dense list and fix the moved line's index.
  const uint32_t index = table_[i].index;
  const uint32_t last = lines_.back();
  if (last != line) {
    size_t j = hashLine(last, mask);
    while (table_[j].key != last + 1) j = (j + 1) & mask;
    table_[j].index = index;
    lines_[index] = last;
    flags_[index] = flags_.back();
  }
  lines_.pop_back();
  flags_.pop_back();
  // Backward-shift deletion keeps probe chains intact.
  table_[i] = Slot{};
  for (size_t j = (i + 1) & mask; table_[j].key != 0; j = (j + 1) & mask) {
    const size_t home = hashLine(table_[j].key - 1, mask);
    const bool movable = (j > i) ? (home <= i || home > j) : (home <= i && home > j);
    if (movable) {
      table_[i] = table_[j];
      table_[j] = Slot{};
      i = j;
    }
  }
}

void Region::addCell(const Grid& grid, int x, int y) {
  ++cellsVisited_;
  for (const uint32_t line : grid.cell(x, y)) {
    if (uint32_t* count = find(line)) {
      ++*count;
    } else {
      insertSlot(line, 1);
    }
  }
}

void Region::removeCell(const Grid& grid, int x, int y) {
  ++cellsVisited_;
  for (const uint32_t line : grid.cell(x, y)) {
    uint32_t* count = find(line);
    if (--*count == 0) eraseSlot(line);
  }
}

void Region::update(const Grid& grid, const CellRect& want) {
  // The ranges of an empty rectangle are kept by nobody: a grid with lines covers every box with
  // some cells, and one with none is looked at again (it answers at once).
  if (want.empty()) {
    grid_ = nullptr;
  } else if (grid_ != &grid || want != rect_) {
    grid_ = &grid;
    grid.cellRanges(want, from_, to_);
  }
  if (want == rect_) return;
  const CellRect old = rect_;
  if (!old.empty()) {
    for (int y = old.y0; y <= old.y1; ++y)
      for (int x = old.x0; x <= old.x1; ++x)
        if (!want.contains(x, y)) removeCell(grid, x, y);
  }
  if (!want.empty()) {
    for (int y = want.y0; y <= want.y1; ++y)
      for (int x = want.x0; x <= want.x1; ++x)
        if (!old.contains(x, y)) addCell(grid, x, y);
  }
  rect_ = want;
}

}  // namespace platon::physics
