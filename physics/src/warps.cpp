// Instances across warp edges: creating the copy on the far side, placing it where rounding left
// room, lifting it off a floor that continues across the edge, and erasing the copy the entity
// has left.
#include <algorithm>
#include <array>

#include "faces.h"
#include "fixed_point.h"
#include "projection.h"
#include "world_impl.h"

namespace platon::physics {
namespace {

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

bool WorldImpl::createWarpInstance(Entity& e, size_t from, LineIndex warpLine, Vec2w fromQ30, Vec2w probe) {
  const Instance& source = e.instances[from];
  const MapPart& sourcePart = part(source.part);
  const Warp& warp = sourcePart.warps()[sourcePart.lines()[warpLine].warp];
  const Segment seg = sourcePart.segments()[warpLine];
  if (e.instanceIn(warp.target)) return true;
  if (!part(warp.target).initialized()) return false;
  // The copy goes where the touching position maps. Rotated shapes and positions are rounded, so
  // that spot can be a unit off: the copy may miss its edge, or graze a line that the original
  // only touched. placeNear picks a free whole-unit position within two units of it.
  const Vec2w at = mapThroughWarp(warp, seg, fromQ30);
  const Angle turn = static_cast<Angle>(source.frame + warp.turn);
  Instance inst;
  try {
    inst = makeInstance(e, warp.target, pointFromQ30(at), turn);
  } catch (const Error&) {
    return false;  // out of range, or the shape cannot take that rotation: the edge holds
  }
  if (!placeNear(e, inst, at, &warp.targetSegment, rotateWide(rotationOf(turn), probe))) return false;
  // Follow the anchor through the same mapping.
  const Vec2w sourceIdeal = from == 0 ? q30FromPoint(source.position) : source.idealQ30;
  inst.idealQ30 = mapThroughWarp(warp, seg, sourceIdeal);
  const uint8_t toState = edgeState(worldVertices(inst), warp.targetSegment);
  const uint8_t fromState = edgeState(worldVertices(source), seg);
  const MapPartId fromPart = source.part;
  e.instances.push_back(std::move(inst));
  e.links.push_back({fromPart, warpLine, warp.target, fromState, toState});
  ++report.warpsCreated;
  return true;
}

bool WorldImpl::placeNear(const Entity& e, Instance& inst, Vec2w targetQ30, const Segment* mustTouch, Vec2w probe) {
  const Vec2 base = pointFromQ30(targetQ30);
  std::array<Vec2, 25> offsets;
  for (int k = 0; k < 25; ++k) offsets[k] = {k % 5 - 2, k / 5 - 2};
  auto distance = [&](Vec2 o) {  // from the target, in Q30 squared; ties keep a fixed order
    const i128 dx = (i128{base.x + o.x} << kQ30Bits) - targetQ30.x, dy = (i128{base.y + o.y} << kQ30Bits) - targetQ30.y;
    return dx * dx + dy * dy;
  };
  std::stable_sort(offsets.begin(), offsets.end(), [&](Vec2 a, Vec2 b) { return distance(a) < distance(b); });
  probe = {std::clamp<int64_t>(probe.x, -kMaxMove, kMaxMove), std::clamp<int64_t>(probe.y, -kMaxMove, kMaxMove)};
  inst.position = base;
  coverMotion(inst, probe, 2);  // every candidate, and where the probe takes it
  std::vector<Vec2>& verts = scratch.probe;
  bool placed = false;
  Vec2 best = base;
  Fraction bestFree = Fraction::zero();
  for (const Vec2 o : offsets) {
    inst.position = {base.x + o.x, base.y + o.y};
    worldVertices(inst, verts);
    if (mustTouch && !touchesOrOverlaps(verts, *mustTouch)) continue;
    if (!isFree(e, inst, verts)) continue;
    const Fraction go = probe == Vec2w{} ? Fraction::one() : firstBlock(e, inst, verts, probe);
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

bool WorldImpl::liftCopy(const Entity& e, Instance& copy, Vec2w direction, Vec2w move) {
  const Vec2 was = copy.position;
  std::vector<Vec2>& verts = scratch.probe;
  for (int64_t lift = 1; lift <= 3; ++lift) {
    const Vec2w by = stepAlong(direction, lift);
    copy.position = {was.x + static_cast<int32_t>(by.x), was.y + static_cast<int32_t>(by.y)};
    if (copy.position == was) continue;
    worldVertices(copy, verts);
    coverMotion(copy, move, 3);
    if (isFree(e, copy, verts) && firstBlock(e, copy, verts, move) > Fraction::zero()) return true;
  }
  copy.position = was;
  return false;
}

void WorldImpl::makeOverlappedWarpInstances(Entity& e) {
  for (size_t i = 0; i < e.instances.size(); ++i) {
    if (e.instances[i].overlapping.empty()) continue;
    const MapPart& p = part(e.instances[i].part);
    for (const LineIndex line : e.instances[i].overlapping) {
      if (p.lines()[line].kind != LineKind::Warp) continue;
      if (e.instanceIn(p.warps()[p.lines()[line].warp].target)) continue;
      const Instance& inst = e.instances[i];
      const Vec2w q = i == 0 ? q30FromPoint(inst.position) : inst.idealQ30;
      const Vec2w perFrame{e.velocityQ16.x >> 16, e.velocityQ16.y >> 16};
      if (!createWarpInstance(e, i, line, q, perFrame)) e.instances[i].blockedWarps.push_back(line);
    }
  }
}

// Whether the instance may move by `gap` (a few units) outside the slide: the way is free, it
// overlaps the same lines after as before (no trigger entered or left without its events) and
// touches no warp edge it did not touch (none straddled without its copy).
bool WorldImpl::snapKeepsTouches(const Entity& e, Instance& inst, Vec2w gap) {
  std::vector<Vec2>& before = scratch.probe;
  worldVertices(inst, before);
  coverMotion(inst, gap);
  if (firstBlock(e, inst, before, gap) < Fraction::one()) return false;
  std::vector<Vec2> after(before);
  for (Vec2& v : after) v = {static_cast<int32_t>(v.x + gap.x), static_cast<int32_t>(v.y + gap.y)};
  const MapPart& p = part(inst.part);
  for (const LineIndex line : inst.region.lines()) {
    const Segment s = p.segments()[line];
    if (overlapsInterior(before, s) != overlapsInterior(after, s)) return false;
    if (p.lines()[line].kind == LineKind::Warp && !touchesOrOverlaps(before, s) && touchesOrOverlaps(after, s))
      return false;
  }
  return true;
}

void WorldImpl::rebase(Move& move, size_t k) {
  Entity& e = move.entity;
  const Angle theta = e.instances[k].frame;
  std::rotate(e.instances.begin(), e.instances.begin() + static_cast<long>(k),
              e.instances.begin() + static_cast<long>(k) + 1);
  for (Instance& inst : e.instances) {
    inst.frame = static_cast<Angle>(inst.frame - theta);
    inst.rotation = rotationOf(inst.frame);
  }
  Instance& anchor = e.instances[0];
  // The new anchor was a copy, which may sit a unit or three off its exact place (placed where
  // rounding left room, or lifted off a floor at a seam). As the anchor it defines the entity's
  // place from now on, so it goes to that exact place where the way there is free: otherwise each
  // crossing would keep its copy's offset and a path retraced would not come back to its start.
  const Vec2 ideal = pointFromQ30(anchor.idealQ30);
  const Vec2w gap{int64_t{ideal.x} - anchor.position.x, int64_t{ideal.y} - anchor.position.y};
  if (gap != Vec2w{} && snapKeepsTouches(e, anchor, gap)) anchor.position = ideal;
  anchor.idealQ30 = q30FromPoint(anchor.position);
  e.angle = static_cast<Angle>(e.angle + theta);
  const Rotation r = rotationOf(theta);
  e.velocityQ16 = clampVelocityQ16(rotateWide(r, e.velocityQ16));
  e.subunitQ17 = rotateWide(r, e.subunitQ17);
  // Keep the carried remainder below one unit after rounding.
  e.subunitQ17.x = std::clamp<int64_t>(e.subunitQ17.x, 0, kQ17 - 1);
  e.subunitQ17.y = std::clamp<int64_t>(e.subunitQ17.y, 0, kQ17 - 1);
  turnMove(move, theta);
}

void WorldImpl::turnMove(Move& move, Angle theta) {
  const Rotation r = rotationOf(theta);
  move.motion = rotateWide(r, move.motion);
  move.primalMotion = rotateWide(r, move.primalMotion);
  move.primalVelocity = rotateWide(r, move.primalVelocity);
  move.exactQ17 = rotateWide(r, move.exactQ17);
  // The rest of the frame falls as the new anchor's part pulls (parts have gravity of their own).
  if (move.gravityQ16 != Vec2w{})
    move.gravityQ16 = move.actingGravityQ16 = part(move.entity.instances[0].part).gravity();
  // The frame's earlier contact normals were in the old frame, and belong to the part it left.
  move.normals.clear();
}

void WorldImpl::eraseInstance(Move& move, size_t index) {
  Entity& e = move.entity;
  // The instance leaves its part: its pierceable overlaps end.
  const Instance& gone = e.instances[index];
  for (const LineIndex line : gone.overlapping) {
    const Contact c = makeContact(e, gone, line, Fraction::one(), {}, {});
    ++report.pierceEvents;
    callRules([&](Rules& r) { r.endContact(c); });
  }
  const MapPartId goneFrom = gone.part;
  endEntityOverlaps(e, goneFrom);
  if (index == 0 && e.instances.size() > 1) {
    rebase(move, 1);
    index = 1;  // the old anchor moved to slot 1
  }
  e.instances.erase(e.instances.begin() + static_cast<long>(index));
  std::erase_if(e.links, [&](const WarpLink& l) { return l.fromPart == goneFrom || l.toPart == goneFrom; });
  ++report.instancesErased;
}

void WorldImpl::updateLinks(Move& move) {
  Entity& e = move.entity;
  for (size_t l = 0; l < e.links.size();) {
    WarpLink& link = e.links[l];
    const Instance* a = e.instanceIn(link.fromPart);
    const Instance* b = e.instanceIn(link.toPart);
    if (!a || !b) {
      e.links.erase(e.links.begin() + static_cast<long>(l));
      continue;
    }
    const MapPart& p = part(link.fromPart);
    const Segment warpSeg = p.segments()[link.warpLine];
    const Segment targetSeg = p.warps()[p.lines()[link.warpLine].warp].targetSegment;
    const std::vector<Vec2> va = worldVertices(*a), vb = worldVertices(*b);
    const uint8_t aNow = edgeState(va, warpSeg);
    const uint8_t bNow = edgeState(vb, targetSeg);
    // The pair ends when a side comes off its edge (or both are off): the side the source is on
    // says which copy stays. The source's face is left of p0 -> p1; the target's is right of t0 -> t1.
    // The source's side decides when it came off its edge, or when both sides are off and the target
    // was not on its edge before (had it been, the target's side decides).
    MapPartId eraseAt = 0;
    if (aNow == 0 && (link.fromState > 0 || (bNow == 0 && link.toState == 0))) {
      eraseAt = sideOf(va, warpSeg) > 0 ? link.toPart : link.fromPart;
    } else if (link.toState > 0 && bNow == 0) {
      eraseAt = sideOf(vb, targetSeg) > 0 ? link.toPart : link.fromPart;
    } else {
      link.fromState = aNow;
      link.toState = bNow;
      ++l;
      continue;
    }
    for (size_t i = 0; i < e.instances.size(); ++i)
      if (e.instances[i].part == eraseAt) {
        eraseInstance(move, i);
        break;
      }
    l = 0;  // erasing removed links: start over
  }
}

// Copies hold together through warp links; near a vertex a copy can be linked only to a copy
// that has since been erased, and then nothing would ever erase it (it drifts off its face). The
// copies linked, directly or not, to the anchor stay; on faces, if none of those has its origin on
// its face but another copy has, that copy's group stays instead (it becomes the anchor).
void WorldImpl::eraseUnlinkedCopies(Move& move) {
  Entity& e = move.entity;
  const size_t n = e.instances.size();
  std::vector<size_t> group(n);
  for (size_t i = 0; i < n; ++i) group[i] = i;
  auto root = [&](size_t i) {
    while (group[i] != i) i = group[i] = group[group[i]];
    return i;
  };
  auto indexOf = [&](MapPartId p) {
    for (size_t i = 0; i < n; ++i)
      if (e.instances[i].part == p) return i;
    return n;
  };
  for (const WarpLink& l : e.links) {
    const size_t a = indexOf(l.fromPart), b = indexOf(l.toPart);
    if (a < n && b < n) group[root(a)] = root(b);
  }
  size_t keep = root(0);
  bool anyOutside = false;
  for (size_t i = 0; i < n; ++i) anyOutside = anyOutside || root(i) != keep;
  if (!anyOutside) return;
  auto onFace = [&](size_t i) {
    const MapPart& p = part(e.instances[i].part);
    return !p.faceLoop().empty() && insideFace(p, centreOf(e.instances[i]));
  };
  bool keptOnFace = false;
  for (size_t i = 0; i < n; ++i) keptOnFace = keptOnFace || (root(i) == keep && onFace(i));
  size_t newAnchor = 0;
  if (!keptOnFace)
    for (size_t i = 0; i < n; ++i)
      if (onFace(i)) {
        keep = root(i);
        newAnchor = i;
        break;
      }
  std::vector<MapPartId> gone;
  for (size_t i = 0; i < n; ++i)
    if (root(i) != keep) gone.push_back(e.instances[i].part);
  if (newAnchor != 0) rebase(move, newAnchor);
  for (const MapPartId p : gone)
    for (size_t i = 1; i < e.instances.size(); ++i)
      if (e.instances[i].part == p) {
        eraseInstance(move, i);
        break;
      }
}

}  // namespace platon::physics
