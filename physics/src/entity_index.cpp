#include "entity_index.h"

#include <algorithm>
#include <bit>

namespace platon::physics {
namespace {
constexpr int64_t kBigCells = 16;  // an instance spanning more cells than this goes to the big list
}

EntityIndex::Filed EntityIndex::fileFor(const Instance& inst) {
  const int64_t x0 = inst.low.x, y0 = inst.low.y, x1 = inst.high.x, y1 = inst.high.y;  // relative to position
  if (shift_ < 0) {  // cells about twice the first entity's size
    const uint64_t extent = static_cast<uint64_t>(std::max<int64_t>({x1 - x0, y1 - y0, 8}));
    shift_ = static_cast<int>(std::bit_width(extent));
  }
  Filed f;
  f.part = inst.part;
  f.x0 = (inst.position.x + x0) >> shift_, f.x1 = (inst.position.x + x1) >> shift_;
  f.y0 = (inst.position.y + y0) >> shift_, f.y1 = (inst.position.y + y1) >> shift_;
  f.big = (f.x1 - f.x0 + 1) * (f.y1 - f.y0 + 1) > kBigCells;
  return f;
}

void EntityIndex::add(uint32_t slot, const Filed& f) {
  if (f.big) {
    big_[f.part].push_back(slot);
    return;
  }
  for (int64_t y = f.y0; y <= f.y1; ++y)
    for (int64_t x = f.x0; x <= f.x1; ++x) cells_[{f.part, x, y}].push_back(slot);
}

void EntityIndex::take(uint32_t slot, const Filed& f) {
  auto drop = [slot](std::vector<uint32_t>& v) {
    auto it = std::find(v.begin(), v.end(), slot);
    if (it != v.end()) *it = v.back(), v.pop_back();
  };
  if (f.big) {
    drop(big_[f.part]);
    return;
  }
  for (int64_t y = f.y0; y <= f.y1; ++y)
    for (int64_t x = f.x0; x <= f.x1; ++x) {
      auto it = cells_.find({f.part, x, y});
      if (it == cells_.end()) continue;
      drop(it->second);
      if (it->second.empty()) cells_.erase(it);
    }
}

void EntityIndex::update(const Entity& e) {
  const uint32_t slot = e.id.index;
  if (slot >= filed_.size()) filed_.resize(slot + 1), stamp_.resize(slot + 1, 0);
  std::vector<Filed>& was = filed_[slot];
  // The usual case, one instance still in the same cells, costs one filing and a comparison.
  if (was.size() == 1 && e.instances.size() == 1 && fileFor(e.instances[0]) == was[0]) return;
  if (was.empty() && !e.instances.empty()) ++entities_;
  now_.clear();
  for (const Instance& inst : e.instances) now_.push_back(fileFor(inst));
  if (now_ == was) return;
  for (const Filed& f : was) take(slot, f);
  for (const Filed& f : now_) add(slot, f);
  if (!was.empty() && now_.empty()) --entities_;
  was = now_;
}

void EntityIndex::remove(const Entity& e) {
  const uint32_t slot = e.id.index;
  if (slot >= filed_.size() || filed_[slot].empty()) return;
  for (const Filed& f : filed_[slot]) take(slot, f);
  filed_[slot].clear();
  --entities_;
}

}  // namespace platon::physics
