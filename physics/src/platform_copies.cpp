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

// How far the lines come over the warp edge `seg` (its face to its left) when they have moved by
// `motion`: the least cross(d, p - a) over their ends then, against |d| rounded up. Nothing when they
// come nowhere near it on the way: no end within kCopyReach units of the edge's line or beyond it,
// before or after the move, or all of them to one side of the edge's slab (past its ends by more
// than the motion and the reach, along it).
struct EdgeReach {
  i128 cross = 0, length = 1;
  // Further over than `o` by more than `by` units.
  bool beyond(const EdgeReach& o, int64_t by) const {
    return cross * o.length + by * length * o.length < o.cross * length;
  }
};
std::optional<EdgeReach> reachOver(const Platform& pl, const Segment& seg, Vec2w motion) {
  const Vec2w d = seg.b - seg.a;
  const i128 length = static_cast<i128>(isqrt(static_cast<u128>(dot128(d, d)))) + 1;
  EdgeReach after{INT64_MAX, length};
  i128 before = INT64_MAX, alongLow = INT64_MAX, alongHigh = INT64_MIN;
  for (const PlatformLine& l : pl.lines)
    for (const Vec2 p : {l.segment.a, l.segment.b}) {
      const Vec2w at = p - seg.a;
      before = std::min(before, cross128(d, at));
      after.cross = std::min(after.cross, cross128(d, at + motion));
      const i128 along = dot128(d, at), alongAfter = dot128(d, at + motion);
      alongLow = std::min({alongLow, along, alongAfter}), alongHigh = std::max({alongHigh, along, alongAfter});
    }
  const i128 margin = kCopyReach * length;
  if (std::min(before, after.cross) > margin || alongHigh < -margin || alongLow > dot128(d, d) + margin)
    return std::nullopt;
  return after;
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
  // One copy at most: across the edge its lines come furthest over (the one it has is kept unless
  // another is further over by more than kCopyReach: a line over a vertex does not make copies
  // come and go). Over two edges at once (beside a vertex) the faces beyond each would hold copies
  // carried over different edges, which disagree by the angle the faces leave there; the bodies
  // there would meet two platforms a few units apart. A turning platform stays in its part
  // (World::createPlatform): it has none.
  auto targetOf = [&](LineIndex line) { return home.warps()[home.lines()[line].warp].target; };
  std::optional<LineIndex> chosen;
  std::optional<EdgeReach> furthest;
  bool chosenHeld = false;
  if (pl.spin == 0)
    for (const LineIndex line : home.faceLoop()) {
      const std::optional<EdgeReach> r = reachOver(pl, home.segments()[line], motion);
      if (!r) continue;
      const bool held = platformCopyIn(pl, targetOf(line)) != nullptr;
      const int64_t margin = held ? -kCopyReach : chosenHeld ? kCopyReach : 0;  // what `r` must beat `furthest` by
      if (!chosen || r->beyond(*furthest, margin)) chosen = line, furthest = r, chosenHeld = held;
    }
  std::erase_if(pl.copies, [&](const PlatformCopy& c) {
    const bool kept = chosen && targetOf(*chosen) == c.part;
    if (!kept) ++platformEpochs[c.part];
    return !kept;
  });
  if (!chosen) return std::nullopt;
  const Warp& w = home.warps()[home.lines()[*chosen].warp];
  if (w.target == pl.part || platformCopyIn(pl, w.target) || !part(w.target).initialized()) return std::nullopt;
  PlatformCopy c;
  c.part = w.target;
  c.rotation = w.rotation;
  c.lines = pl.lines;
  for (PlatformLine& l : c.lines)
    for (Vec2* p : {&l.segment.a, &l.segment.b}) {
      const Vec2w at = mapThroughWarp(w, home.segments()[*chosen], q30FromPoint(*p));
      // Beyond the coordinate range there: no entity can be where it goes.
      if (std::max(std::abs(unitsFromQ30(at.x)), std::abs(unitsFromQ30(at.y))) > kCoordLimit) return std::nullopt;
      *p = pointFromQ30(at);
    }
  c.box = boxOfLines(c.lines);
  // Nothing of that part may be inside it (no push made room for it).
  std::optional<PlatformHit> over;
  std::vector<Vec2> verts;
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
  return std::nullopt;
}

// A body met where the platform's own lines are (platformMeets) has its copies on the faces beyond
// rounded in their own frames, as the platform's copies are: the two roundings can leave one of its
// copies a unit into a copy line. Such a copy is lifted off it, as a copy is off any line it meets by
// rounding (it may sit up to three units off its exact place); an anchor there is pushed off it. So
// is a body the platform has come to meet there since (it left the platform's own part) still in
// one of the copy's lines.
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
    if (!c || !inst) continue;
    worldVertices(*inst, verts);
    for (const PlatformLine& l : c->lines) {
      if ((l.kind == LineKind::OneWay && !wholyInFront(verts, l.segment)) || !overlapsInterior(verts, l.segment))
        continue;
      const Vec2w away = normalTowards(verts, l.segment);
      if (inst != &e.instances[0]) {
        liftCopy(e, *inst, away, {});
      } else {
        const Vec2w by = stepAlong(away, 2);
        push(e, inst->frame == 0 ? by : rotateWideInverse(inst->rotation, by));
      }
      reindex(e);
      break;
    }
  }
}

// Whether a body's instance in the copy's part overlaps one of its lines. Until it crosses, the
// platform meets the bodies that are also in its own part there (platformMeets); their copies beyond
// the edge, rounded in their own frame, can be a unit or so into the copy's lines, and the platform
// goes over only once it would meet none of them so.
bool WorldImpl::copyOverlapsABody(const PlatformCopy& c) {
  bool over = false;
  std::vector<Vec2> verts;
  entityIndex.forEachNear(c.part, c.box, [&](uint32_t s) {
    const Instance* inst = slots[s].entity->instanceIn(c.part);
    if (over || !inst) return;
    worldVertices(*inst, verts);
    for (const PlatformLine& l : c.lines)
      if ((l.kind != LineKind::OneWay || wholyInFront(verts, l.segment)) && overlapsInterior(verts, l.segment))
        over = true;
  });
  return over;
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
    if (!back || copyOverlapsABody(*beyond)) continue;
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
