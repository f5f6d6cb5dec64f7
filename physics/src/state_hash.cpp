// A 64-bit FNV-1a hash of everything that determines the future: equal hashes across runs and
// machines show determinism.
#include "world_impl.h"

namespace platon::physics {
namespace {
struct Hasher {
  uint64_t h = 1469598103934665603ull;
  void add(uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      h ^= (v >> (8 * i)) & 0xff;
      h *= 1099511628211ull;
    }
  }
};
}  // namespace

uint64_t World::stateHash() const {
  const WorldImpl& w = *impl_;
  Hasher h;
  h.add(w.frame);
  for (uint32_t s = 0; s < w.slots.size(); ++s) {
    const Entity* e = w.slots[s].entity.get();
    if (!e) continue;
    h.add(s);
    h.add(w.slots[s].generation);
    h.add(e->angle);
    h.add(static_cast<uint64_t>(e->velocityQ16.x));
    h.add(static_cast<uint64_t>(e->velocityQ16.y));
    h.add(static_cast<uint64_t>(e->subunitQ17.x));
    h.add(static_cast<uint64_t>(e->subunitQ17.y));
    h.add(static_cast<uint64_t>(e->angularVelocity));
    for (const Instance& inst : e->instances) {
      h.add(inst.part);
      h.add(static_cast<uint64_t>(inst.position.x));
      h.add(static_cast<uint64_t>(inst.position.y));
      h.add(inst.frame);
      h.add(static_cast<uint64_t>(inst.idealQ30.x));
      h.add(static_cast<uint64_t>(inst.idealQ30.y));
      for (const Vec2 v : inst.shape) h.add((uint64_t{static_cast<uint32_t>(v.x)} << 32) | static_cast<uint32_t>(v.y));
      for (const LineIndex l : inst.overlapping) h.add(l);
    }
    for (const WarpLink& l : e->links) {
      h.add(l.fromPart);
      h.add(l.warpLine);
      h.add(l.toPart);
      h.add(l.fromState | (l.toState << 2));
    }
  }
  return h.h;
}

}  // namespace platon::physics
