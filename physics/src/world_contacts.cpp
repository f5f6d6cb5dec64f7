// Contact events, warps and instance bookkeeping.
#include <algorithm>
#include <array>

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

bool World::createWarpInstance(EntityId id, Entity& e, size_t from, LineIndex warpLine, Vec2w fromQ30,
                               Vec2w motion) {
  const Instance& source = e.instances[from];
  const MapPart& part = mapPart(source.part);
  const Warp& warp = part.warps()[part.lines()[warpLine].warp];
  const Segment seg = part.segments()[warpLine];
  if (e.instanceIn(warp.target)) return true;
  const MapPart& target = mapPart(warp.target);
  if (!target.initialized()) return false;
  // The copy goes where the touching position maps. Rotated shapes and positions are rounded, so
  // that spot can be a unit off: the copy may miss its edge, or graze a line that the original
  // only touched. placeNear picks a free whole-unit position within two units of it.
  const Vec2w at = mapThroughWarp(warp, seg, fromQ30);
  const Angle frame = static_cast<Angle>(source.frame + warp.turn);
  Instance inst;
  try {
    inst = makeInstance(e, warp.target, {static_cast<int32_t>(roundDiv(at.x, i128{1} << 30)),
                                         static_cast<int32_t>(roundDiv(at.y, i128{1} << 30))}, frame);
  } catch (const Error&) {
    return false;  // out of range, or the shape cannot take that rotation: the edge holds
  }
  if (!placeNear(id, inst, at, &warp.targetSegment, rotateWide(rotationOf(frame), motion))) return false;
  // Follow the anchor through the same mapping.
  const Vec2w sourceIdeal = from == 0 ? Vec2w{int64_t{source.position.x} << 30, int64_t{source.position.y} << 30}
                                      : source.idealQ30;
  inst.idealQ30 = mapThroughWarp(warp, seg, sourceIdeal);
  const uint8_t toState = edgeState(worldVertices(inst), warp.targetSegment);
  const uint8_t fromState = edgeState(worldVertices(source), seg);
  const MapPartId fromPart = source.part;
  e.instances.push_back(std::move(inst));
  e.links.push_back({fromPart, warpLine, warp.target, fromState, toState});
  ++report_.warpsCreated;
  return true;
}

bool World::placeNear(EntityId id, Instance& inst, Vec2w targetQ30, const Segment* mustTouch, Vec2w probe) {
  const Vec2 base{static_cast<int32_t>(roundDiv(targetQ30.x, i128{1} << 30)),
                  static_cast<int32_t>(roundDiv(targetQ30.y, i128{1} << 30))};
  std::array<Vec2, 25> offsets;
  for (int k = 0; k < 25; ++k) offsets[k] = {k % 5 - 2, k / 5 - 2};
  auto distance = [&](Vec2 o) {  // from the target, in Q30 squared; ties keep a fixed order
    const i128 dx = (i128{base.x + o.x} << 30) - targetQ30.x, dy = (i128{base.y + o.y} << 30) - targetQ30.y;
    return dx * dx + dy * dy;
  };
  std::stable_sort(offsets.begin(), offsets.end(), [&](Vec2 a, Vec2 b) { return distance(a) < distance(b); });
  probe = {std::clamp<int64_t>(probe.x, -kMaxMove, kMaxMove), std::clamp<int64_t>(probe.y, -kMaxMove, kMaxMove)};
  inst.position = base;
  coverMotion(inst, probe, 2);  // every candidate, and where the probe takes it
  const MapPart& part = mapPart(inst.part);
  std::vector<Vec2> verts;
  bool placed = false;
  Vec2 best = base;
  Fraction bestFree = Fraction::zero();
  for (const Vec2 o : offsets) {
    inst.position = {base.x + o.x, base.y + o.y};
    worldVertices(inst, verts);
    bool free = !mustTouch || touchesOrOverlaps(verts, *mustTouch);
    for (const Vec2 v : verts) free = free && inRange(v);
    const auto lines = inst.region.lines();
    for (size_t k = 0; k < lines.size() && free; ++k)
      free = isPierceable(id, inst, k) || !overlapsInterior(verts, part.segments()[lines[k]]);
    if (!free) continue;
    const Fraction go = probe == Vec2w{} ? Fraction::one() : firstBlock(id, inst, verts, probe);
    if (!placed || go > bestFree) {
      placed = true;
      best = inst.position;
      bestFree = go;
      if (go == Fraction::one()) break;
    }
  }
  inst.position = best;
  return placed;
}

void World::createOverlappedWarps(EntityId id, Entity& e) {
  for (size_t i = 0; i < e.instances.size(); ++i) {
    const MapPart& part = mapPart(e.instances[i].part);
    for (const LineIndex line : e.instances[i].overlapping) {
      if (part.lines()[line].kind != LineKind::Warp) continue;
      if (e.instanceIn(part.warps()[part.lines()[line].warp].target)) continue;
      const Instance& inst = e.instances[i];
      const Vec2w q = i == 0 ? Vec2w{int64_t{inst.position.x} << 30, int64_t{inst.position.y} << 30} : inst.idealQ30;
      const Vec2w perFrame{e.velocityQ16.x >> 16, e.velocityQ16.y >> 16};
      if (!createWarpInstance(id, e, i, line, q, perFrame)) e.instances[i].blockedWarps.push_back(line);
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
