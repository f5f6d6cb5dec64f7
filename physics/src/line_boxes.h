// The boxes of a part's lines, indexed for one question: which lines' boxes meet a given box. The
// overlap check (World::countOverlaps) asks it for every body, each frame of every test and
// scenario, so it must cost what the bodies meet, not what the map holds: no pass over every line,
// never a pair of lines. It is a check of the solver, so it uses none of the solver's indexes.
//
// The lines are sorted by their boxes' low side along one axis (the one along which they overlap
// least: stacked floors are indexed along y, a row of walls along x), over a tree that keeps each
// range's highest high side: a query walks only the ranges that can reach the box.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "grid.h"

namespace platon::physics {

class LineBoxes {
 public:
  using Box = physics::Box;  // grid.h's closed integer box
  struct Item {
    Box box;
    uint32_t key;  // the caller's: a line's index, or which platform line
  };

  explicit LineBoxes(std::vector<Item> items);

  // Calls visit(key) for every item whose box meets `box` (closed boxes); returns the work done (the
  // tree's nodes walked and the items looked at), which a caller may charge.
  template <class Visit>
  size_t query(const Box& box, Visit&& visit) const {
    const Span s = along(box);
    size_t work = 0;
    // the items whose low side is at most the box's high side: a prefix of the sorted items
    size_t count = 0;
    for (size_t step = size_t{1} << 62; step; step >>= 1)
      if (count + step <= items_.size() && low(items_[count + step - 1]) <= s.hi) count += step;
    if (count) walk(1, 0, items_.size(), count, box, s.lo, visit, work);
    return work;
  }

  size_t size() const { return items_.size(); }

 private:
  struct Span {
    int64_t lo, hi;
  };
  Span along(const Box& b) const { return alongY_ ? Span{b.y0, b.y1} : Span{b.x0, b.x1}; }
  int64_t low(const Item& i) const { return alongY_ ? i.box.y0 : i.box.x0; }
  int64_t high(const Item& i) const { return alongY_ ? i.box.y1 : i.box.x1; }
  int64_t build(size_t node, size_t begin, size_t end);

  template <class Visit>
  void walk(size_t node, size_t begin, size_t end, size_t count, const Box& box, int64_t lo, Visit& visit,
            size_t& work) const {
    ++work;
    if (begin >= count || highest_[node] < lo) return;
    if (end - begin <= kLeaf) {
      for (size_t i = begin; i < end && i < count; ++i) {
        ++work;
        const Box& b = items_[i].box;
        if (b.x0 <= box.x1 && box.x0 <= b.x1 && b.y0 <= box.y1 && box.y0 <= b.y1) visit(items_[i].key);
      }
      return;
    }
    const size_t middle = begin + (end - begin) / 2;
    walk(2 * node, begin, middle, count, box, lo, visit, work);
    walk(2 * node + 1, middle, end, count, box, lo, visit, work);
  }

  static constexpr size_t kLeaf = 8;
  bool alongY_ = false;
  std::vector<Item> items_;       // sorted by low side along the axis
  std::vector<int64_t> highest_;  // per tree node: the highest high side in its range
};

}  // namespace platon::physics
