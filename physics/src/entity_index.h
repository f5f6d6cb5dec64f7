// Where the instances of entities that meet other entities are: a uniform grid of cells per map
// part, kept up to date as they move (every place that moves an entity calls update()). Only
// entities with a filter that meets something are in it, so a world of entities that ignore each
// other pays nothing. Queries return candidates whose box may meet a given box; callers test the
// exact geometry.
#pragma once
#include <unordered_map>
#include <vector>

#include "entity.h"
#include "grid.h"

namespace platon::physics {

class EntityIndex {
 public:
  // Puts the entity's instances where they are now: adds, moves or removes them.
  void update(const Entity& e);
  void remove(const Entity& e);

  // Calls visit(slot) once for each indexed entity with an instance in `part` whose box may meet
  // the closed box `box`.
  template <class Visit>
  void forEachNear(MapPartId part, const Box& box, Visit&& visit);
  // Calls visit(slot) for each entity filed in the cells where `slot` is filed or next to them (a
  // cell is at least 16 units wide: every entity within a few units of it); for an entity filed
  // among the big ones, every entity of its parts. Possibly the same slot more than once.
  template <class Visit>
  void forEachAround(uint32_t slot, Visit&& visit) const;
  bool empty() const { return entities_ == 0; }

 private:
  struct Key {
    MapPartId part;
    int64_t x, y;
    friend bool operator==(const Key&, const Key&) = default;
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      uint64_t h = k.part * 0x9e3779b97f4a7c15ull;
      h ^= static_cast<uint64_t>(k.x) + 0x7f4a7c159e3779b9ull + (h << 6) + (h >> 2);
      h ^= static_cast<uint64_t>(k.y) + 0x94d049bb133111ebull + (h << 6) + (h >> 2);
      return h;
    }
  };
  // Where one instance is filed: a rectangle of cells, or the part's list of big ones.
  struct Filed {
    MapPartId part = 0;
    bool big = false;
    int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    friend bool operator==(const Filed&, const Filed&) = default;
  };
  Filed fileFor(const Instance& inst);
  void add(uint32_t slot, const Filed& f);
  void take(uint32_t slot, const Filed& f);

  std::unordered_map<Key, std::vector<uint32_t>, KeyHash> cells_;
  std::unordered_map<MapPartId, std::vector<uint32_t>> big_;  // instances spanning many cells
  std::vector<std::vector<Filed>> filed_;                     // per entity slot
  std::vector<uint32_t> stamp_;                               // per slot, the last query that saw it
  std::vector<Filed> now_;                                    // update()'s scratch
  uint32_t query_ = 0;
  int shift_ = -1;  // cells are 2^shift units wide; chosen from the first entity filed
  size_t entities_ = 0;
};

template <class Visit>
void EntityIndex::forEachNear(MapPartId part, const Box& box, Visit&& visit) {
  if (entities_ == 0) return;
  if (++query_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0), query_ = 1;
  auto once = [&](uint32_t slot) {
    if (stamp_[slot] == query_) return;
    stamp_[slot] = query_;
    visit(slot);
  };
  if (auto it = big_.find(part); it != big_.end())
    for (const uint32_t slot : it->second) once(slot);
  const int64_t x0 = box.x0 >> shift_, x1 = box.x1 >> shift_, y0 = box.y0 >> shift_, y1 = box.y1 >> shift_;
  if ((x1 - x0 + 1) * (y1 - y0 + 1) > 4096) {  // a huge query: every filed entity of the part
    for (auto& [key, slots] : cells_)
      if (key.part == part)
        for (const uint32_t slot : slots) once(slot);
    return;
  }
  for (int64_t y = y0; y <= y1; ++y)
    for (int64_t x = x0; x <= x1; ++x)
      if (auto it = cells_.find({part, x, y}); it != cells_.end())
        for (const uint32_t slot : it->second) once(slot);
}

template <class Visit>
void EntityIndex::forEachAround(uint32_t slot, Visit&& visit) const {
  if (slot >= filed_.size()) return;
  for (const Filed& f : filed_[slot]) {
    if (auto it = big_.find(f.part); it != big_.end())
      for (const uint32_t other : it->second) visit(other);
    if (f.big) {  // a big one reaches anything of its part
      for (const auto& [key, slots] : cells_)
        if (key.part == f.part)
          for (const uint32_t other : slots) visit(other);
      continue;
    }
    for (int64_t y = f.y0 - 1; y <= f.y1 + 1; ++y)
      for (int64_t x = f.x0 - 1; x <= f.x1 + 1; ++x)
        if (auto it = cells_.find({f.part, x, y}); it != cells_.end())
          for (const uint32_t other : it->second) visit(other);
  }
}

}  // namespace platon::physics
