// Contact events, warps and instance bookkeeping.
#include <algorithm>

#include "platon/physics/world.h"

namespace platon::physics {
namespace {

Vec2w mapThroughWarp(const Warp& w, Segment from, Vec2w pointQ30) {
  const Vec2w rel{pointQ30.x - (int64_t{from.a.x} << 30), pointQ30.y - (int64_t{from.a.y} << 30)};
  const Vec2w turned = rotateWide(w.rotation, rel);
  return {(int64_t{w.targetSegment.a.x} << 30) + turned.x, (int64_t{w.targetSegment.a.y} << 30) + turned.y};
}

uint8_t edgeState(const std::vector<Vec2>& verts, Segment s) {
  return overlapsInterior(verts, s) ? 2 : (touchesOrOverlaps(verts, s) ? 1 : 0);
}

// Which side of the directed line a (non-overlapping) polygon lies on: > 0 left, <= 0 right.
int64_t sideOf(const std::vector<Vec2>& verts, Segment s) {
  i128 sum = 0;
  for (const Vec2 v : verts) sum += cross(s.b - s.a, v - s.a);
  return sum > 0 ? 1 : (sum < 0 ? -1 : 0);
}

}  // namespace

Contact World::makeContact(EntityId id, const Instance& inst, LineIndex line, Fraction t, Vec2w normal,
                           ContactPoints points) const {
  Contact c;
  c.entity = id;
  c.part = inst.part;
  c.line.part = inst.part;
  c.line.index = line;
  if (line != kWorldBoundLine) {
    const Line& l = mapPart(inst.part).lines()[line];
    c.line.tag = l.tag;
    c.line.kind = l.kind;
  }
  c.fraction = t;
  c.normal = normal;
  c.points = points;
  return c;
}

bool World::createWarpInstance(EntityId id, Entity& e, size_t from, LineIndex warpLine, Vec2w fromQ30) {
  const Instance& source = e.instances[from];
  const MapPart& part = mapPart(source.part);
  const Warp& warp = part.warps()[part.lines()[warpLine].warp];
  const Segment seg = part.segments()[warpLine];
  if (e.instanceIn(warp.target)) return true;
  const MapPart& target = mapPart(warp.target);
  if (!target.initialized()) return false;
  // Start where the touching position maps, rounded into the target face (to the right of
  // t0 -> t1) so the new instance touches or just overlaps its side of the edge.
  const Vec2w at = mapThroughWarp(warp, seg, fromQ30);
  const Vec2w d = warp.targetSegment.b - warp.targetSegment.a;
  auto roundInward = [](int64_t q, int64_t inward) {
    if (inward > 0) return static_cast<int64_t>(ceilDiv(q, i128{1} << 30));
    if (inward < 0) return static_cast<int64_t>(floorDiv(q, i128{1} << 30));
    return static_cast<int64_t>(roundDiv(q, i128{1} << 30));
  };
  int64_t px = roundInward(at.x, d.y), py = roundInward(at.y, -d.x);
  Instance inst;
  // Rotated shapes are rounded, so the copy may still sit a unit off its edge: step it inwards
  // until it touches (the edge is pierceable; solid lines are checked below).
  for (int tries = 0;; ++tries) {
    if (std::abs(px) > kCoordLimit || std::abs(py) > kCoordLimit) return false;
    try {
      inst = makeInstance(e, warp.target, {static_cast<int32_t>(px), static_cast<int32_t>(py)},
                          static_cast<Angle>(source.frame + warp.turn));
    } catch (const Error&) {
      return false;  // out of range, or the shape cannot take that rotation: the edge holds
    }
    if (touchesOrOverlaps(worldVertices(inst), warp.targetSegment) || tries == 3) break;
    px += (d.y > 0) - (d.y < 0);
    py += (d.x < 0) - (d.x > 0);
  }
  // Follow the anchor through the same mapping.
  const Vec2w sourceIdeal = from == 0 ? Vec2w{int64_t{source.position.x} << 30, int64_t{source.position.y} << 30}
                                      : source.idealQ30;
  inst.idealQ30 = mapThroughWarp(warp, seg, sourceIdeal);
  coverMotion(inst, {});
  const std::vector<Vec2> verts = worldVertices(inst);
  const auto lines = inst.region.lines();
  for (size_t k = 0; k < lines.size(); ++k)
    if (!isPierceable(id, inst, k) && overlapsInterior(verts, target.segments()[lines[k]])) return false;
  const uint8_t toState = edgeState(verts, warp.targetSegment);
  const uint8_t fromState = edgeState(worldVertices(source), seg);
  const MapPartId fromPart = source.part;
  e.instances.push_back(std::move(inst));
  e.links.push_back({fromPart, warpLine, warp.target, fromState, toState});
  ++report_.warpsCreated;
  return true;
}

void World::createOverlappedWarps(EntityId id, Entity& e) {
  for (size_t i = 0; i < e.instances.size(); ++i) {
    const MapPart& part = mapPart(e.instances[i].part);
    for (const LineIndex line : e.instances[i].overlapping) {
      if (part.lines()[line].kind != LineKind::Warp) continue;
      if (e.instanceIn(part.warps()[part.lines()[line].warp].target)) continue;
      const Instance& inst = e.instances[i];
      const Vec2w q = i == 0 ? Vec2w{int64_t{inst.position.x} << 30, int64_t{inst.position.y} << 30} : inst.idealQ30;
      if (!createWarpInstance(id, e, i, line, q)) e.instances[i].blockedWarps.push_back(line);
    }
  }
}

void World::updatePierceState(EntityId id, Entity& e, const std::vector<std::vector<Vec2>>* startVerts,
                              const std::vector<Vec2w>* steps, const std::vector<uint8_t>* pierceNear) {
  struct Event {
    Fraction t;
    size_t instance;
    LineIndex line;
    bool begin;
    Vec2w normal;
    ContactPoints points;
  };
  std::vector<Event> events;
  for (size_t i = 0; i < e.instances.size(); ++i) {
    Instance& inst = e.instances[i];
    // Nothing pierceable near the path and nothing overlapped: no event is possible.
    if (pierceNear && i < pierceNear->size() && !(*pierceNear)[i] && inst.overlapping.empty()) continue;
    const MapPart& part = mapPart(inst.part);
    std::vector<Vec2>& now = scratch_.now;
    worldVertices(inst, now);
    const bool haveMove = startVerts && i < startVerts->size() && (*steps)[i] != Vec2w{};
    if (!haveMove) coverMotion(inst, {});  // after a move the region still covers the whole path
    std::vector<LineIndex> overlapping;
    const auto lines = inst.region.lines();
    for (size_t k = 0; k < lines.size(); ++k) {
      if (!isPierceable(id, inst, k) && inst.region.flags()[k] != 2) continue;
      const LineIndex line = lines[k];
      const Segment seg = part.segments()[line];
      const bool was = std::binary_search(inst.overlapping.begin(), inst.overlapping.end(), line);
      const bool is = overlapsInterior(now, seg);
      if (is) overlapping.push_back(line);
      if (was && is) continue;
      Sweep s;
      if (haveMove) s = sweep((*startVerts)[i], (*steps)[i], seg);
      if (!was && !is && !(haveMove && s.hitsWithinFrame())) continue;  // never met
      const Fraction enter = haveMove && s.hasEnter && s.enter > Fraction::zero() ? s.enter : Fraction::zero();
      const Fraction exit = haveMove && s.hasExit && s.exit < Fraction::one() ? s.exit : Fraction::one();
      if (!was) {
        ContactPoints pts;
        if (haveMove && s.hitsWithinFrame()) pts = contactPoints((*startVerts)[i], (*steps)[i], seg, s);
        events.push_back({enter, i, line, true, haveMove ? s.normal() : Vec2w{}, pts});
      }
      if (!is) events.push_back({exit, i, line, false, {}, {}});
    }
    std::sort(overlapping.begin(), overlapping.end());
    inst.overlapping = std::move(overlapping);
  }
  // Time order; ties in a fixed order (instance, line, begin before end), never region order.
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
    if (a.t != b.t) return a.t < b.t;
    if (a.instance != b.instance) return a.instance < b.instance;
    if (a.line != b.line) return a.line < b.line;
    return a.begin > b.begin;
  });
  for (const Event& ev : events) {
    const Contact c = makeContact(id, e.instances[ev.instance], ev.line, ev.t, ev.normal, ev.points);
    ++report_.pierceEvents;
    if (ev.begin)
      callRules([&](Rules& r) { r.beginContact(c); });
    else
      callRules([&](Rules& r) { r.endContact(c); });
  }
}

void World::eraseInstance(EntityId id, Entity& e, size_t index, Vec2w* motion, std::vector<Vec2w>* normals) {
  // The instance leaves its part: its pierceable overlaps end.
  const Instance& gone = e.instances[index];
  for (const LineIndex line : gone.overlapping) {
    const Contact c = makeContact(id, gone, line, Fraction::one(), {}, {});
    ++report_.pierceEvents;
    callRules([&](Rules& r) { r.endContact(c); });
  }
  const MapPartId part = gone.part;
  if (index == 0 && e.instances.size() > 1) {
    rebase(e, 1, motion);
    if (normals) normals->clear();
    index = 1;  // the old anchor moved to slot 1
  }
  e.instances.erase(e.instances.begin() + static_cast<long>(index));
  std::erase_if(e.links, [&](const WarpLink& l) { return l.fromPart == part || l.toPart == part; });
  ++report_.instancesErased;
}

void World::updateLinks(EntityId id, Entity& e, Vec2w* motion, std::vector<Vec2w>* normals) {
  for (size_t l = 0; l < e.links.size();) {
    WarpLink& link = e.links[l];
    const Instance* a = e.instanceIn(link.fromPart);
    const Instance* b = e.instanceIn(link.toPart);
    if (!a || !b) {
      e.links.erase(e.links.begin() + static_cast<long>(l));
      continue;
    }
    const MapPart& part = mapPart(link.fromPart);
    const Segment warpSeg = part.segments()[link.warpLine];
    const Segment targetSeg = part.warps()[part.lines()[link.warpLine].warp].targetSegment;
    const std::vector<Vec2> va = worldVertices(*a), vb = worldVertices(*b);
    const uint8_t aNow = edgeState(va, warpSeg);
    const uint8_t bNow = edgeState(vb, targetSeg);
    // The pair ends when a side comes off its edge (or both are off): the side the source is on
    // says which copy stays. The source's face is left of p0 -> p1; the target's is right of t0 -> t1.
    MapPartId eraseAt = 0;
    if (link.fromState > 0 && aNow == 0) {
      eraseAt = sideOf(va, warpSeg) > 0 ? link.toPart : link.fromPart;
    } else if (link.toState > 0 && bNow == 0) {
      eraseAt = sideOf(vb, targetSeg) > 0 ? link.toPart : link.fromPart;
    } else if (aNow == 0 && bNow == 0) {
      eraseAt = sideOf(va, warpSeg) > 0 ? link.toPart : link.fromPart;
    } else {
      link.fromState = aNow;
      link.toState = bNow;
      ++l;
      continue;
    }
    for (size_t i = 0; i < e.instances.size(); ++i)
      if (e.instances[i].part == eraseAt) {
        eraseInstance(id, e, i, motion, normals);
        break;
      }
    l = 0;  // erasing removed links: start over
  }
}

void World::fireOverContacts() {
  for (uint32_t s = 0; s < slots_.size(); ++s) {
    Entity* e = slots_[s].entity.get();
    if (!e) continue;
    const EntityId id{s, slots_[s].generation};
    for (const Instance& inst : e->instances)
      for (const LineIndex line : inst.overlapping) {
        const Contact c = makeContact(id, inst, line, Fraction::one(), {}, {});
        callRules([&](Rules& r) { r.overContact(c); });
      }
  }
}

}  // namespace platon::physics
