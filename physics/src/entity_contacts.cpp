// Entities meeting entities: keeping the index, placing without overlap, pushing, and the begin and
// end events of entities that report overlaps with each other.
#include <algorithm>

#include "bounds.h"
#include "world_impl.h"

namespace platon::physics {
namespace {

Box boxOf(std::span<const Vec2> verts, Vec2w step) { return sweptBox(verts, step); }

}  // namespace

// Every entity in a part is in the index, so that moving platforms find whom to push and carry;
// the filters decide which entities meet which.
// An entity that moved (or changed shape or filter) may change the rest of those near where it was
// and where it is: they are woken on both sides of the update (nothing to do while none rests).
void WorldImpl::reindex(const Entity& e) {
  if (restingCount > 0) wakeAround(e);
  if (!e.instances.empty())
    entityIndex.update(e);
  else
    entityIndex.remove(e);
  if (restingCount > 0) wakeAround(e);
}

void WorldImpl::wakeAround(const Entity& e) {
  wake(*slots[e.id.index].entity);
  entityIndex.forEachAround(e.id.index, [&](uint32_t slot) {
    if (Entity* other = slots[slot].entity.get()) wake(*other);
  });
}

uint64_t WorldImpl::platformEpochOf(const Entity& e) const {
  if (platformEpochs.empty()) return 0;
  uint64_t sum = 0;
  for (const Instance& inst : e.instances)
    if (auto it = platformEpochs.find(inst.part); it != platformEpochs.end()) sum += it->second;
  return sum;
}

std::optional<EntityId> WorldImpl::entityOverlap(const Entity& e, const Instance& inst, std::span<const Vec2> verts) {
  std::optional<EntityId> found;
  std::vector<Vec2>& other = scratch.other;
  forEachSolidNear(e, inst.part, boxOf(verts, {}), [&](const Entity& o, const Instance& oi) {
    if (found) return;
    worldVertices(oi, other);
    if (overlapsInterior(verts, other)) found = o.id;
  });
  return found;
}

bool WorldImpl::push(Entity& b, Vec2w motion, bool straight) {
  if (pushDepth >= 4 || b.instances.empty() || motion == Vec2w{}) return false;
  ++pushDepth;
  std::vector<Vec2> before;
  for (const Instance& inst : b.instances) before.push_back(inst.position);
  const MapPartId anchorPart = b.instances[0].part;
  std::vector<Vec2w> normals;  // its own: the pusher's frame keeps scratch.normals
  Move move{b, motion, normals, motion, b.velocityQ16};
  move.straight = straight;
  slide(move);
  reindex(b);
  --pushDepth;
  if (b.instances.empty() || b.instances[0].part != anchorPart || b.instances.size() != before.size()) return true;
  for (size_t i = 0; i < before.size(); ++i)
    if (b.instances[i].position != before[i]) return true;
  return false;
}

void WorldImpl::entityOverlapEvents(Entity& e, const Path& path, std::vector<PathEvent>& events) {
  if (e.filter.overlapWith == 0 && e.filter.category == 0) return;
  std::vector<Vec2> now, other;
  for (size_t i = 0; i < e.instances.size(); ++i) {
    Instance& inst = e.instances[i];
    worldVertices(inst, now);
    const bool moved = i < path.start.size() && path.steps[i] != Vec2w{};
    const Box box = moved ? boxOf(path.start[i], path.steps[i]) : boxOf(now, {});
    forEachOverlappingNear(e, inst.part, box, [&](const Entity& o, const Instance& oi) {
      worldVertices(oi, other);
      const OverlapPair key{std::min(e.id.index, o.id.index), std::max(e.id.index, o.id.index), inst.part};
      const auto at = std::lower_bound(entityOverlaps.begin(), entityOverlaps.end(), key);
      const bool was = at != entityOverlaps.end() && *at == key;
      const bool is = overlapsInterior(now, other);
      Sweep s;
      if (moved) s = sweep(path.start[i], path.steps[i], other);
      if (!was && !is && !(moved && s.hitsWithinFrame())) return;  // never met
      if (was && is) return;
      const uint64_t order = (uint64_t{1} << 32) | o.id.index;
      if (!was) events.push_back({enterTime(moved, s), i, order, true, moved ? s.normal() : Vec2w{}, {}, o.id});
      if (!is) events.push_back({exitTime(moved, s), i, order, false, {}, {}, o.id});
      if (is && !was) entityOverlaps.insert(at, key);
      if (!is && was) entityOverlaps.erase(at);
    });
  }
}

void WorldImpl::endEntityOverlaps(Entity& e, MapPartId part) {
  for (size_t k = 0; k < entityOverlaps.size();) {
    const OverlapPair p = entityOverlaps[k];
    if (p.part != part || (p.a != e.id.index && p.b != e.id.index)) {
      ++k;
      continue;
    }
    entityOverlaps.erase(entityOverlaps.begin() + static_cast<long>(k));
    const uint32_t otherSlot = p.a == e.id.index ? p.b : p.a;
    const Entity* other = slots[otherSlot].entity.get();
    if (const Instance* inst = e.instanceIn(part); inst && other) {
      Contact c = makeContact(e, *inst, kNoLine, Fraction::one(), {}, {});
      c.other = other->id;
      ++report.pierceEvents;
      callRules([&](Rules& r) { r.endContact(c); });
    }
  }
}

}  // namespace platon::physics
