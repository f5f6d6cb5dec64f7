#include "line_boxes.h"

#include <algorithm>

namespace platon::physics {

LineBoxes::LineBoxes(std::vector<Item> items) : items_(std::move(items)) {
  // The axis along which the boxes overlap least: the sum of their extents along it, over the
  // extent of them all (how many a line across that axis meets, on average).
  Box all{INT64_MAX, INT64_MAX, INT64_MIN, INT64_MIN};
  double sumX = 0, sumY = 0;
  for (const Item& i : items_) {
    all.x0 = std::min(all.x0, i.box.x0), all.y0 = std::min(all.y0, i.box.y0);
    all.x1 = std::max(all.x1, i.box.x1), all.y1 = std::max(all.y1, i.box.y1);
    sumX += double(i.box.x1 - i.box.x0 + 1), sumY += double(i.box.y1 - i.box.y0 + 1);
  }
  if (!items_.empty()) alongY_ = sumY / double(all.y1 - all.y0 + 1) < sumX / double(all.x1 - all.x0 + 1);
  std::sort(items_.begin(), items_.end(), [&](const Item& a, const Item& b) { return low(a) < low(b); });
  if (items_.empty()) return;
  size_t nodes = 1;
  while (nodes < items_.size()) nodes <<= 1;
  highest_.assign(2 * nodes, INT64_MIN);
  build(1, 0, items_.size());
}

int64_t LineBoxes::build(size_t node, size_t begin, size_t end) {
  if (end - begin <= kLeaf) {
    int64_t h = INT64_MIN;
    for (size_t i = begin; i < end; ++i) h = std::max(h, high(items_[i]));
    return highest_[node] = h;
  }
  const size_t middle = begin + (end - begin) / 2;
  return highest_[node] = std::max(build(2 * node, begin, middle), build(2 * node + 1, middle, end));
}

}  // namespace platon::physics
