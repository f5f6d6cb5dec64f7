// Where an instance may be: its region of nearby lines, which of them pierce, whether a place is
// free, and how far a step can go before a solid line stops it.
#include <algorithm>

#include "bounds.h"
#include "fixed_point.h"
#include "world_impl.h"

namespace platon::physics {

Instance WorldImpl::makeInstance(const Entity& e, MapPartId partId, Vec2 position, Angle turn) const {
  Instance inst;
  inst.part = partId;
  inst.position = position;
  inst.frame = turn;
  inst.rotation = rotationOf(turn);
  inst.idealQ30 = q30FromPoint(position);
  const Convex turned = e.shape.rotated(static_cast<Angle>(e.angle + turn));
  setShape(inst, {turned.vertices().begin(), turned.vertices().end()}, e.shape, static_cast<Angle>(e.angle + turn));
  for (const Vec2 v : inst.shape)
    if (std::abs(int64_t{position.x} + v.x) > kCoordLimit || std::abs(int64_t{position.y} + v.y) > kCoordLimit)
      throw Error("instance at " + toString(position) + " would reach outside the coordinate range (vertex " +
                  toString(v) + ")");
  return inst;
}

bool WorldImpl::askPierceable(const Entity& e, Instance& inst, size_t k) {
  uint8_t& flag = inst.region.flags()[k];
  if (flag == 0) {
    const MapPart& p = part(inst.part);
    const LineIndex index = inst.region.lines()[k];
    const Line& line = p.lines()[index];
    const LineRef ref{p.id(), index, line.tag, line.kind, {}};
    bool pierce = line.kind == LineKind::Warp;
    callRules([&](Rules& r) { pierce = r.pierce(e.id, ref); });
    // Turned solid while the instance overlaps it (refreshPierce): it stays passable for this
    // instance until it is clear, so the answer is not kept and the question comes back.
    if (!pierce && std::binary_search(inst.overlapping.begin(), inst.overlapping.end(), index)) return true;
    flag = pierce ? 2 : 1;
  }
  if (flag == 2 && !inst.blockedWarps.empty()) {
    const LineIndex index = inst.region.lines()[k];
    if (std::find(inst.blockedWarps.begin(), inst.blockedWarps.end(), index) != inst.blockedWarps.end()) return false;
  }
  return flag == 2;
}

std::optional<LineIndex> WorldImpl::solidOverlap(const Entity& e, Instance& inst, std::span<const Vec2> verts) {
  const MapPart& p = part(inst.part);
  const auto lines = inst.region.lines();
  for (size_t k = 0; k < lines.size(); ++k)
    if (blocks(e, inst, k, verts) && overlapsInterior(verts, p.segments()[lines[k]])) return lines[k];
  std::optional<LineIndex> found;
  forEachPlatformLine(inst.part, sweptBox(verts, {}), [&](const PlatformLine& l, LineIndex key) {
    if (!found && !inPocket(e, key) && (l.kind != LineKind::OneWay || wholyInFront(verts, l.segment)) &&
        overlapsInterior(verts, l.segment))
      found = key;
  });
  return found;
}

bool WorldImpl::isFree(const Entity& e, Instance& inst, std::span<const Vec2> verts) {
  return std::all_of(verts.begin(), verts.end(), inRange) && !solidOverlap(e, inst, verts) &&
         !entityOverlap(e, inst, verts);
}

Fraction WorldImpl::firstBlock(const Entity& e, Instance& inst, std::span<const Vec2> verts, Vec2w step) {
  const MapPart& p = part(inst.part);
  const auto lines = inst.region.lines();
  const Box box = sweptBox(verts, step);
  Fraction first = Fraction::one();
  for (size_t k = 0; k < lines.size(); ++k) {
    const Segment& seg = p.segments()[lines[k]];
    if (outside(seg, box) || !blocks(e, inst, k, verts)) continue;
    const Sweep s = sweep(verts, step, seg);
    if (s.hitsWithinFrame() && s.enter < first) first = s.enter;
  }
  Constraint bounds[4];
  for (const Constraint& c : boundConstraints(verts, box, bounds)) {
    const int64_t rate = dot(c.c, step);
    if (rate > 0 && Fraction{c.slack, rate} < first) first = Fraction{c.slack, rate};
  }
  forEachPlatformLine(inst.part, box, [&](const PlatformLine& l, LineIndex key) {
    if ((l.kind == LineKind::OneWay && !wholyInFront(verts, l.segment)) || inPocket(e, key)) return;
    const Sweep s = sweep(verts, step, l.segment);
    if (s.hitsWithinFrame() && s.enter < first) first = s.enter;
  });
  std::vector<Vec2>& other = scratch.other;
  forEachSolidNear(e, inst.part, box, [&](const Entity&, const Instance& oi) {
    worldVertices(oi, other);
    const Sweep s = sweep(verts, step, other);
    if (s.hitsWithinFrame() && s.enter < first) first = s.enter;
  });
  return first;
}

}  // namespace platon::physics
