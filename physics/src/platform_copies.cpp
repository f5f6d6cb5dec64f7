// A platform across the edges of a face: its copies on the faces beside it, and its crossing to the
// face beyond (World::createPlatform).
#include <algorithm>

#include "bounds.h"
#include "faces.h"
#include "platon/physics/sweep.h"
#include "projection.h"
#include "world_impl.h"

namespace platon::physics {
namespace {

// How near a warp edge a platform's lines come (beyond this frame's motion) before its copy is placed
// on the face beyond: the copy is there before the lines are, so the bodies there are pushed, not
// overlapped.
constexpr int64_t kCopyReach = 4;

// How far the lines come over the warp edge `seg` (its face to its left) by the frame's end: the
// least cross(d, p - a) over their ends then (`then`), against |d| rounded up. Nothing when they
// come nowhere near it: no end within kCopyReach units of the edge's line or beyond it, now, on
// the way (`between`: a turn's) or then; or, all on the face's side of its line, all to one side
// of the edge's slab (past its ends by more than the reach, along it).
struct EdgeReach {
  i128 cross = 0, length = 1;
  // Further over than `o` by more than `by` units.
  bool beyond(const EdgeReach& o, int64_t by) const {
    return cross * o.length + by * length * o.length < o.cross * length;
  }
};
std::optional<EdgeReach> reachOver(std::span<const Vec2w> now, std::span<const Vec2w> between,
                                   std::span<const Vec2w> then, const Segment& seg) {
  const Vec2w d = seg.b - seg.a;
  const i128 length = static_cast<i128>(isqrt(static_cast<u128>(dot128(d, d)))) + 1;
  EdgeReach after{INT64_MAX, length};
  i128 least = INT64_MAX, alongLow = INT64_MAX, alongHigh = INT64_MIN;
  auto reach = [&](std::span<const Vec2w> points, bool atEnd) {
    for (const Vec2w p : points) {
      const Vec2w at = p - wide(seg.a);
      const i128 cross = cross128(d, at), along = dot128(d, at);
      least = std::min(least, cross);
      if (atEnd) after.cross = std::min(after.cross, cross);
      alongLow = std::min(alongLow, along), alongHigh = std::max(alongHigh, along);
    }
  };
  reach(now, false);
  reach(between, false);
  reach(then, true);
  const i128 margin = kCopyReach * length;
  // Beside the slab only while on the face's side of the edge's line: lines inside the face near
  // that line are near the edge itself, and lines over the line (past a vertex) are over the edge
  // wherever they are along it (else a platform driven past a vertex, over one edge's line and past
  // its end, had no copy anywhere and never crossed).
  if (least > margin || (least >= 0 && (alongHigh < -margin || alongLow > dot128(d, d) + margin))) return std::nullopt;
  return after;
}

// How far (whole units, rounded up) the polygon goes along `away` before it is out of the segment:
// where its way out of the line through `s` (as deep as its vertices are behind that line) leaves
// the segment. Only as far as the segment is in it: an end of the line poking into a body a unit
// or two is left by that much, however deep the line through it would cut.
int64_t unitsOutOf(std::span<const Vec2> verts, Segment s, Vec2w away) {
  const int64_t deepest = depthBehind(verts, s, away) + 1;
  const Sweep way = sweep(verts, stepAlong(away, deepest), s);
  if (way.empty || !way.hasExit || way.exit >= Fraction::one()) return deepest;
  return std::max<int64_t>(0, static_cast<int64_t>(ceilDiv(i128{way.exit.num} * deepest, way.exit.den)));
}

// Whether every line is wholly beyond the warp edge `seg`.
bool whollyBeyond(const Platform& pl, const Segment& seg) {
  const Vec2w d = seg.b - seg.a;
  return std::all_of(pl.lines.begin(), pl.lines.end(), [&](const PlatformLine& l) {
    return cross128(d, l.segment.a - seg.a) < 0 && cross128(d, l.segment.b - seg.a) < 0;
  });
}

// The warp line of `from`'s face loop into part `to`, if any.
std::optional<LineIndex> warpInto(const MapPart& from, MapPartId to) {
  for (const LineIndex line : from.faceLoop())
    if (from.warps()[from.lines()[line].warp].target == to) return line;
  return std::nullopt;
}

}  // namespace

Vec2w WorldImpl::pointThrough(const Platform& pl, LineIndex edge, Vec2w point) const {
  const MapPart& home = part(pl.part);
  const Vec2w at = mapThroughWarp(home.warps()[home.lines()[edge].warp], home.segments()[edge],
                                  {point.x << kQ30Bits, point.y << kQ30Bits});
  return {unitsFromQ30(at.x), unitsFromQ30(at.y)};
}

bool WorldImpl::linesThrough(const Platform& pl, LineIndex edge, std::vector<PlatformLine>& lines) const {
  for (PlatformLine& l : lines)
    for (Vec2* p : {&l.segment.a, &l.segment.b}) {
      const Vec2w at = pointThrough(pl, edge, wide(*p));
      // Beyond the coordinate range there: no entity can be where it goes.
      if (std::max(std::abs(at.x), std::abs(at.y)) > kCoordLimit) return false;
      *p = {static_cast<int32_t>(at.x), static_cast<int32_t>(at.y)};
    }
  return true;
}

// The first body with an instance in the copy's part that `meets` there and is in one of its lines.
template <class Meets>
std::optional<WorldImpl::PlatformHit> WorldImpl::firstBodyIn(const PlatformCopy& c, Meets&& meets) {
  std::optional<PlatformHit> over;
  std::vector<Vec2> verts;
  entityIndex.forEachNear(c.part, c.box, [&](uint32_t s) {
    const Instance* inst = slots[s].entity->instanceIn(c.part);
    if (over || !inst || !meets(*slots[s].entity)) return;
    worldVertices(*inst, verts);
    if (const std::optional<uint32_t> k = lineItIsIn(c.lines, verts))
      over = PlatformHit{Fraction::zero(), s, *k, c.part};
  });
  return over;
}

bool WorldImpl::anyBodyIn(const PlatformCopy& c) {
  return firstBodyIn(c, [](const Entity&) { return true; }).has_value();
}

// The face edge the platform's one copy goes over this frame, if any. Across it its lines come
// furthest over (the one it has is kept unless another is further over by more than kCopyReach: a
// line over a vertex does not make copies come and go). Over two edges at once (beside a vertex)
// the faces beyond each would hold copies carried over different edges, which disagree by the angle
// the faces leave there; the bodies there would meet two platforms a few units apart. A turning
// platform's reach is the square about its pivot that its turns stay in.
std::optional<LineIndex> WorldImpl::copyEdgeOf(const Platform& pl, Vec2w motion) {
  const MapPart& home = part(pl.part);
  // The ends now, and where the frame takes them: moved by its motion, and a turning platform turned
  // by all of its spin too (and half of it on the way: a sub-step's lines stray a few units from
  // those at most).
  std::vector<Vec2w> now, between, then;
  for (const PlatformLine& l : pl.lines) now.insert(now.end(), {wide(l.segment.a), wide(l.segment.b)});
  if (pl.spin == 0) {
    for (const Vec2w p : now) then.push_back(p + motion);
  } else {
    Platform moved = pl;
    moved.offset = {static_cast<int32_t>(pl.offset.x + motion.x), static_cast<int32_t>(pl.offset.y + motion.y)};
    std::vector<PlatformLine> turned;
    for (std::vector<Vec2w>* points : {&between, &then}) {
      placePlatformLines(moved, static_cast<Angle>(pl.angle + (points == &then ? pl.spin : pl.spin / 2)), turned);
      for (const PlatformLine& l : turned) points->insert(points->end(), {wide(l.segment.a), wide(l.segment.b)});
    }
  }
  std::optional<LineIndex> chosen;
  std::optional<EdgeReach> furthest;
  bool chosenHeld = false;
  for (const LineIndex line : home.faceLoop()) {
    const std::optional<EdgeReach> r = reachOver(now, between, then, home.segments()[line]);
    if (!r) continue;
    const bool held = platformCopyIn(pl, home.warps()[home.lines()[line].warp].target) != nullptr;
    const int64_t margin = held ? -kCopyReach : chosenHeld ? kCopyReach : 0;  // what `r` must beat `furthest` by
    if (!chosen || r->beyond(*furthest, margin)) chosen = line, furthest = r, chosenHeld = held;
  }
  return chosen;
}

std::optional<WorldImpl::PlatformHit> WorldImpl::updatePlatformCopies(uint32_t slot, Vec2w motion,
                                                                      CopyPlacing placing) {
  Platform& pl = platforms[slot];
  const MapPart& home = part(pl.part);
  auto targetOf = [&](LineIndex line) { return home.warps()[home.lines()[line].warp].target; };
  const std::optional<LineIndex> chosen = copyEdgeOf(pl, motion);
  std::optional<PlatformCopy> made;
  if (chosen && !platformCopyIn(pl, targetOf(*chosen)) && targetOf(*chosen) != pl.part &&
      part(targetOf(*chosen)).initialized()) {
    PlatformCopy c;
    c.part = targetOf(*chosen);
    c.rotation = home.warps()[home.lines()[*chosen].warp].rotation;
    c.edge = *chosen;
    c.lines = pl.lines;
    if (linesThrough(pl, c.edge, c.lines)) {
      c.box = boxOfLines(c.lines);
      // Created over a body it would meet there (it has no other copy: one also in its own part is
      // met there): refused.
      if (placing == CopyPlacing::Create)
        if (const std::optional<PlatformHit> over =
                firstBodyIn(c, [&](const Entity& e) { return !e.instanceIn(pl.part); }))
          return over;
      made = std::move(c);
    }
  }
  // Just crossed: a copy over another edge only where no body at all is in its lines (the lines came
  // over that edge with no copy: a body there is met the next frame, where it may have gone).
  if (placing == CopyPlacing::Crossed && made && anyBodyIn(*made)) return std::nullopt;
  std::erase_if(pl.copies, [&](const PlatformCopy& c) {
    const bool kept = chosen && targetOf(*chosen) == c.part;
    if (!kept) ++platformEpochs[c.part];
    return !kept;
  });
  if (!made) return std::nullopt;
  // A body in its lines is in the platform already (its lines came over that edge with no copy:
  // beside a vertex, or the frame it crossed): it is one left in a copy's line (clearPlatformCopies
  // clears it off, or the platform passes through it), rather than a reason to stop where no push
  // can help (for good, whatever the platform's motion, while the body stays).
  ++platformEpochs[made->part];
  pl.copies.push_back(std::move(*made));
  return std::nullopt;
}

// A body met where the platform's own lines are (platformMeets) has its copies on the faces beyond
// rounded in their own frames, as the platform's copies are: the two roundings can leave one of its
// copies a unit into a copy line. Such a copy is lifted off it, as a copy is off any line it meets by
// rounding (it may sit up to three units off its exact place); an anchor there is pushed off it, as
// far as it takes. So is a body the platform has come to meet there since (it left the
// platform's own part: pushed, or carried, through a vertex, where its instances' places disagree
// by more than rounding) still in one of the copy's lines.
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
    const std::optional<uint32_t> k = lineItIsIn(c->lines, verts);
    if (!k) continue;
    const Segment& line = c->lines[*k].segment;
    const Vec2w away = normalTowards(verts, line);
    if (inst != &e.instances[0]) {
      liftCopy(e, *inst, away, {});
    } else {  // pushed out of the line's side, as far as it takes (and a unit)
      const Vec2w by = stepAlong(away, unitsOutOf(verts, line, away) + 1);
      push(e, inst->frame == 0 ? by : rotateWideInverse(inst->rotation, by));
    }
    reindex(e);
  }
}

bool WorldImpl::crossPlatform(uint32_t slot) {
  Platform& pl = platforms[slot];
  if (pl.copies.empty()) return false;
  const MapPart& home = part(pl.part);
  for (const LineIndex line : home.faceLoop()) {
    const Segment seg = home.segments()[line];
    const Warp& w = home.warps()[home.lines()[line].warp];
    const PlatformCopy* beyond = platformCopyIn(pl, w.target);
    if (!beyond || !whollyBeyond(pl, seg)) continue;
    const MapPart& there = part(w.target);
    const std::optional<LineIndex> back = warpInto(there, pl.part);
    // Until it crosses, the platform meets the bodies also in its own part there (platformMeets);
    // their copies beyond the edge, rounded in their own frame, can be a unit or so into the copy's
    // lines, and it goes over only once it would meet none of them so.
    if (!back || anyBodyIn(*beyond)) continue;
    // Its lines stay where they are in every part: the copy's become its own, its own a copy of the
    // new part's (following it back through the warp), and a copy on a face the new part has a warp
    // into follows it through that warp; any other copy is dropped (made again next frame if reached).
    std::vector<PlatformCopy> copies;
    copies.push_back({pl.part, pl.lines, pl.box, there.warps()[there.lines()[*back].warp].rotation, {}, *back});
    for (PlatformCopy& c : pl.copies) {
      if (c.part == w.target) continue;
      const std::optional<LineIndex> into = warpInto(there, c.part);
      ++platformEpochs[c.part];
      if (!into) continue;
      c.rotation = there.warps()[there.lines()[*into].warp].rotation;
      c.originQ30 = {};
      c.edge = *into;
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
    return true;
  }
  return false;
}

}  // namespace platon::physics
