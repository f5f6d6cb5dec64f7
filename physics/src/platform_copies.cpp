// A platform across the edges of a face: its copies on the faces beside it, and its crossing to the
// face beyond (World::createPlatform).
#include <algorithm>

#include "bounds.h"
#include "faces.h"
#include "projection.h"
#include "world_impl.h"

namespace platon::physics {
namespace {

// How near a warp edge a platform's lines come (beyond this frame's motion) before its copy is placed
// on the face beyond: the copy is there before the lines are, so the bodies there are pushed, not
// overlapped.
constexpr int64_t kCopyReach = 4;

bool boxesMeet(const Box& a, const Box& b) { return a.x0 <= b.x1 && a.x1 >= b.x0 && a.y0 <= b.y1 && a.y1 >= b.y0; }

// Whether the lines, moved by up to `motion`, come within reach of the warp edge `seg` (its face to
// its left): the box they sweep meets the edge's, and an end is beyond the edge's line or within
// reach of it.
bool reachesEdge(const Platform& pl, const Segment& seg, Vec2w motion) {
  const int64_t reach = std::max(std::abs(motion.x), std::abs(motion.y)) + kCopyReach;
  const Box near{pl.box.x0 - reach, pl.box.y0 - reach, pl.box.x1 + reach, pl.box.y1 + reach};
  const Box edge{std::min(seg.a.x, seg.b.x), std::min(seg.a.y, seg.b.y), std::max(seg.a.x, seg.b.x),
                 std::max(seg.a.y, seg.b.y)};
  if (!boxesMeet(near, edge)) return false;
  const Vec2w d = seg.b - seg.a;
  // |d| rounded up: an end within `reach` of the line has cross(d, p - a) <= reach |d|.
  const i128 length = static_cast<i128>(isqrt(static_cast<u128>(dot128(d, d)))) + 1;
  for (const PlatformLine& l : pl.lines)
    for (const Vec2 p : {l.segment.a, l.segment.b})
      if (cross128(d, p - seg.a) <= reach * length) return true;
  return false;
}

// Whether every line is wholly beyond the warp edge `seg`.
bool whollyBeyond(const Platform& pl, const Segment& seg) {
  const Vec2w d = seg.b - seg.a;
  return std::all_of(pl.lines.begin(), pl.lines.end(), [&](const PlatformLine& l) {
    return cross128(d, l.segment.a - seg.a) < 0 && cross128(d, l.segment.b - seg.a) < 0;
  });
}

// The warp of `from`'s face loop into part `to`, if any.
const Warp* warpInto(const MapPart& from, MapPartId to) {
  for (const LineIndex line : from.faceLoop()) {
    const Warp& w = from.warps()[from.lines()[line].warp];
    if (w.target == to) return &w;
  }
  return nullptr;
}

}  // namespace

std::optional<WorldImpl::PlatformHit> WorldImpl::updatePlatformCopies(uint32_t slot, Vec2w motion) {
  Platform& pl = platforms[slot];
  const MapPart& home = part(pl.part);
  // A turning platform stays in its part (World::createPlatform): it has no copies.
  std::vector<LineIndex> reached;
  if (pl.spin == 0)
    for (const LineIndex line : home.faceLoop())
      if (reachesEdge(pl, home.segments()[line], motion)) reached.push_back(line);
  auto targetOf = [&](LineIndex line) { return home.warps()[home.lines()[line].warp].target; };
  std::erase_if(pl.copies, [&](const PlatformCopy& c) {
    const bool kept = std::any_of(reached.begin(), reached.end(), [&](LineIndex l) { return targetOf(l) == c.part; });
    if (!kept) ++platformEpochs[c.part];
    return !kept;
  });
  std::vector<Vec2> verts;
  for (const LineIndex line : reached) {
    const Warp& w = home.warps()[home.lines()[line].warp];
    if (w.target == pl.part || platformCopyIn(pl, w.target) || !part(w.target).initialized()) continue;
    PlatformCopy c;
    c.part = w.target;
    c.rotation = w.rotation;
    c.lines = pl.lines;
    bool inside = true;
    for (PlatformLine& l : c.lines)
      for (Vec2* p : {&l.segment.a, &l.segment.b}) {
        const Vec2w at = mapThroughWarp(w, home.segments()[line], q30FromPoint(*p));
        const Vec2w units{unitsFromQ30(at.x), unitsFromQ30(at.y)};
        inside = inside && std::max(std::abs(units.x), std::abs(units.y)) <= kCoordLimit;
        *p = inside ? pointFromQ30(at) : Vec2{};
      }
    if (!inside) continue;  // beyond the coordinate range there: no entity can be where it goes
    c.box = boxOfLines(c.lines);
    // Nothing of that part may be inside it (no push made room for it).
    std::optional<PlatformHit> over;
    entityIndex.forEachNear(c.part, c.box, [&](uint32_t s) {
      const Instance* inst = slots[s].entity->instanceIn(c.part);
      if (over || !inst || platformMeets(pl, *slots[s].entity)) return;  // met where it is first
      worldVertices(*inst, verts);
      for (uint32_t k = 0; k < c.lines.size() && !over; ++k)
        if ((c.lines[k].kind != LineKind::OneWay || wholyInFront(verts, c.lines[k].segment)) &&
            overlapsInterior(verts, c.lines[k].segment))
          over = PlatformHit{Fraction::zero(), s, k, c.part};
    });
    if (over) return over;
    ++platformEpochs[c.part];
    pl.copies.push_back(std::move(c));
  }
  return std::nullopt;
}

// A body met where the platform's own lines are (platformMeets) has its copies on the faces beyond
// rounded in their own frames, as the platform's copies are: the two roundings can leave one of its
// copies a unit into a copy line. Such a copy is lifted off it, as a copy is off any line it meets by
// rounding (it may sit up to three units off its exact place); an anchor there is pushed off it.
void WorldImpl::clearPlatformCopies(uint32_t slot) {
  std::vector<std::pair<uint32_t, MapPartId>> near;
  for (const PlatformCopy& c : platforms[slot].copies)
    entityIndex.forEachNear(c.part, c.box, [&](uint32_t s) { near.push_back({s, c.part}); });
  std::sort(near.begin(), near.end());  // slot order: the index's order is not part of the result
  std::vector<Vec2> verts;
  for (const auto& [s, partId] : near) {
    Entity& e = *slots[s].entity;
    const PlatformCopy* c = platformCopyIn(platforms[slot], partId);
    Instance* inst = e.instanceIn(partId);
    if (!c || !inst || platformMeets(platforms[slot], e) == partId) continue;
    worldVertices(*inst, verts);
    for (const PlatformLine& l : c->lines) {
      if ((l.kind == LineKind::OneWay && !wholyInFront(verts, l.segment)) || !overlapsInterior(verts, l.segment))
        continue;
      const Vec2w d = l.segment.b - l.segment.a;
      i128 side = 0;
      for (const Vec2 v : verts) side += cross(d, v - l.segment.a);
      const Vec2w away = side >= 0 ? Vec2w{-d.y, d.x} : Vec2w{d.y, -d.x};
      if (inst != &e.instances[0]) {
        liftCopy(e, *inst, away, {});
      } else {
        const Vec2w n = shortDirection(away);
        const int64_t length = static_cast<int64_t>(isqrt(static_cast<u128>(dot128(n, n))));
        const Vec2w by{static_cast<int64_t>(roundDiv(i128{n.x} * 2, length)),
                       static_cast<int64_t>(roundDiv(i128{n.y} * 2, length))};
        push(e, inst->frame == 0 ? by : rotateWideInverse(inst->rotation, by));
      }
      reindex(e);
      break;
    }
  }
}

void WorldImpl::crossPlatform(uint32_t slot) {
  Platform& pl = platforms[slot];
  if (pl.copies.empty() || pl.spin != 0) return;
  const MapPart& home = part(pl.part);
  for (const LineIndex line : home.faceLoop()) {
    const Segment seg = home.segments()[line];
    const Warp& w = home.warps()[home.lines()[line].warp];
    const PlatformCopy* beyond = platformCopyIn(pl, w.target);
    if (!beyond || !whollyBeyond(pl, seg)) continue;
    const MapPart& there = part(w.target);
    const Warp* back = warpInto(there, pl.part);
    if (!back) continue;
    // Its lines stay where they are in every part: the copy's become its own, its own a copy of the
    // new part's (following it back through the warp), and a copy on a face the new part has a warp
    // into follows it through that warp; any other copy is dropped (made again next frame if reached).
    std::vector<PlatformCopy> copies;
    copies.push_back({pl.part, pl.lines, pl.box, back->rotation, {}});
    for (PlatformCopy& c : pl.copies) {
      if (c.part == w.target) continue;
      const Warp* into = warpInto(there, c.part);
      ++platformEpochs[c.part];
      if (!into) continue;
      c.rotation = into->rotation;
      c.originQ30 = {};
      copies.push_back(std::move(c));
    }
    const Vec2 pivotNow{pl.pivot.x + pl.offset.x, pl.pivot.y + pl.offset.y};
    const Vec2w pivotThere = mapThroughWarp(w, seg, q30FromPoint(pivotNow));
    const Vec2w pivotUnits{unitsFromQ30(pivotThere.x), unitsFromQ30(pivotThere.y)};
    ++platformEpochs[pl.part];
    ++platformEpochs[w.target];
    pl.lines = beyond->lines;
    pl.box = beyond->box;
    pl.part = w.target;
    pl.base = pl.lines;
    pl.offset = {};
    pl.angle = 0;
    pl.pivot = std::max(std::abs(pivotUnits.x), std::abs(pivotUnits.y)) <= kCoordLimit ? pointFromQ30(pivotThere)
                                                                                       : pl.lines[0].segment.a;
    pl.motionQ30 = rotateWide(w.rotation, pl.motionQ30);
    pl.motionLeftQ30 = rotateWide(w.rotation, pl.motionLeftQ30);
    pl.motion = pointFromQ30(pl.motionQ30);
    pl.copies = std::move(copies);
    return;
  }
}

}  // namespace platon::physics
