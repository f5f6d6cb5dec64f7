// Begin, over and end events of pierceable lines, found along each instance's path in time order,
// and the Contact records every callback receives.
#include <algorithm>

#include "world_impl.h"

namespace platon::physics {

Contact WorldImpl::makeContact(const Entity& e, MapPartId partId, LineIndex line, Fraction t, Vec2w normal,
                               ContactPoints points) const {
  Contact c;
  c.entity = e.id;
  c.part = partId;
  c.line.part = partId;
  c.line.index = line;
  if (isPlatformLine(line)) {
    const uint32_t slot = (line & ~kPlatformLineBit) >> 16;
    const PlatformLine& l = platformLine(line);
    c.line.index = line & 0xffff;
    c.line.platform = {slot, platforms[slot].generation};
    c.line.tag = l.tag;
    c.line.kind = l.kind;
  } else if (line < part(partId).lines().size()) {
    const Line& l = part(partId).lines()[line];
    c.line.tag = l.tag;
    c.line.kind = l.kind;
  }
  c.fraction = t;
  c.normal = normal;
  c.points = points;
  return c;
}

void WorldImpl::firePierceEvents(Entity& e, const Path& path) {
  std::vector<PathEvent> events;
  for (size_t i = 0; i < e.instances.size(); ++i)
    if (!pierceQuiet(e, path, i)) instancePierceEvents(e, path, i, events);
  entityOverlapEvents(e, path, events);
  firePathEvents(e, events);
}

// Instance i's begin and end events with the pierceable lines it meets along its path, and the
// lines it overlaps at the end of it.
void WorldImpl::instancePierceEvents(Entity& e, const Path& path, size_t i, std::vector<PathEvent>& events) {
  Instance& inst = e.instances[i];
  const MapPart& p = part(inst.part);
  std::vector<Vec2>& now = scratch.now;
  worldVertices(inst, now);
  const bool moved = i < path.start.size() && path.steps[i] != Vec2w{};
  if (!moved) coverMotion(inst, {});  // after a move the region still covers the whole path
  std::vector<LineIndex> overlapping;
  const auto lines = inst.region.lines();
  for (size_t k = 0; k < lines.size(); ++k) {
    if (!isPierceable(e, inst, k) && inst.region.flags()[k] != 2) continue;
    const LineIndex line = lines[k];
    const Segment seg = p.segments()[line];
    const bool was = std::binary_search(inst.overlapping.begin(), inst.overlapping.end(), line);
    const bool is = overlapsInterior(now, seg);
    if (is) overlapping.push_back(line);
    if (was && is) continue;
    Sweep s;
    if (moved) s = sweep(path.start[i], path.steps[i], seg);
    const bool hits = moved && s.hitsWithinFrame();
    if (!was && !is && !hits) continue;  // never met
    if (!was) {
      const ContactPoints pts = hits ? contactPoints(path.start[i], path.steps[i], seg, s) : ContactPoints{};
      events.push_back({enterTime(moved, s), i, line, true, moved ? s.normal() : Vec2w{}, pts, {}});
    }
    if (!is) events.push_back({exitTime(moved, s), i, line, false, {}, {}, {}});
  }
  std::sort(overlapping.begin(), overlapping.end());
  inst.overlapping = std::move(overlapping);
  if (!inst.overlapping.empty()) overlappingSlots.push_back(e.id.index);
}

// The events in time order, ties in a fixed order (instance, line before entity, begin before
// end; never region order), each told to the rules.
void WorldImpl::firePathEvents(Entity& e, std::vector<PathEvent>& events) {
  std::sort(events.begin(), events.end(), [](const PathEvent& a, const PathEvent& b) {
    if (a.t != b.t) return a.t < b.t;
    if (a.instance != b.instance) return a.instance < b.instance;
    if (a.key != b.key) return a.key < b.key;
    return a.begin > b.begin;
  });
  for (const PathEvent& ev : events) {
    const LineIndex line = ev.other.isSet() ? kNoLine : static_cast<LineIndex>(ev.key);
    Contact c = makeContact(e, e.instances[ev.instance], line, ev.t, ev.normal, ev.points);
    c.other = ev.other;
    ++report.pierceEvents;
    if (ev.begin)
      callRules([&](Rules& r) { r.beginContact(c); });
    else
      callRules([&](Rules& r) { r.endContact(c); });
  }
}

void WorldImpl::fireOverContacts() {
  for (const OverlapPair& p : entityOverlaps) {
    const Entity* a = slots[p.a].entity.get();
    const Entity* b = slots[p.b].entity.get();
    const Instance* inst = a ? a->instanceIn(p.part) : nullptr;
    if (!inst || !b) continue;
    Contact c = makeContact(*a, *inst, kNoLine, Fraction::one(), {}, {});
    c.other = b->id;
    callRules([&](Rules& r) { r.overContact(c); });
  }
  // In slot order, as a walk over every body would be.
  std::sort(overlappingSlots.begin(), overlappingSlots.end());
  overlappingSlots.erase(std::unique(overlappingSlots.begin(), overlappingSlots.end()), overlappingSlots.end());
  size_t still = 0;
  for (const uint32_t slot : overlappingSlots) {
    const Entity* e = slots[slot].entity.get();
    if (!e) continue;
    bool any = false;
    for (const Instance& inst : e->instances)
      for (const LineIndex line : inst.overlapping) {
        any = true;
        const Contact c = makeContact(*e, inst, line, Fraction::one(), {}, {});
        callRules([&](Rules& r) { r.overContact(c); });
      }
    if (any) overlappingSlots[still++] = slot;
  }
  overlappingSlots.resize(still);
}

}  // namespace platon::physics
