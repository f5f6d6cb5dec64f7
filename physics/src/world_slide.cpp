// The frame step of one entity: gravity, rotation, then the slide: sweep every instance, move all
// of them to the earliest contact, project the rest of the motion along the line, repeat.
#include <algorithm>
#include <cmath>

#include "platon/physics/world.h"

namespace platon::physics {
namespace {

constexpr int64_t kQ16 = 1 << 16;
constexpr int64_t kQ17 = 1 << 17;

// Removes the part of v that points into the surface with normal n, rounding so that what is left
// never points into it (dot(result, n) >= 0).
Vec2w removeInto(Vec2w v, Vec2w n) {
  const i128 vn = dot128(v, n);
  if (vn >= 0) return v;
  const i128 nn = dot128(n, n);
  auto one = [&](int64_t vk, int64_t nk) -> int64_t {
    if (nk == 0) return vk;
    const i128 q = vn * nk;
    return static_cast<int64_t>(vk - (nk > 0 ? floorDiv(q, nn) : ceilDiv(q, nn)));
  };
  return {one(v.x, n.x), one(v.y, n.y)};
}

// Like removeInto for a whole-unit motion, and also returns, in Q17, what the rounding left out:
// carried into the next frame, it keeps a slide along a sloped line from drifting by a unit a frame.
Vec2w removeIntoCarrying(Vec2w v, Vec2w n, Vec2w& carryQ17) {
  const Vec2w kept = removeInto(v, n);
  const i128 vn = dot128(v, n);
  if (vn >= 0) return kept;
  const i128 nn = dot128(n, n);
  auto left = [&](int64_t vk, int64_t nk, int64_t keptk) {
    const i128 exactQ17 = i128{vk} * kQ17 - roundDiv(vn * nk * kQ17, nn);
    return static_cast<int64_t>(exactQ17 - i128{keptk} * kQ17);
  };
  carryQ17 = {left(v.x, n.x, kept.x), left(v.y, n.y, kept.y)};
  return kept;
}

// v minus its component along n, to the nearest unit of v's scale.
Vec2w withoutComponent(Vec2w v, Vec2w n) {
  const i128 vn = dot128(v, n), nn = dot128(n, n);
  return {v.x - static_cast<int64_t>(roundDiv(vn * n.x, nn)), v.y - static_cast<int64_t>(roundDiv(vn * n.y, nn))};
}

// Scales a direction down (keeping its sign pattern) so its components fit in 31 bits.
Vec2w shortDirection(Vec2w n) {
  while (n.x > (int64_t{1} << 30) || n.x < -(int64_t{1} << 30) || n.y > (int64_t{1} << 30) ||
         n.y < -(int64_t{1} << 30)) {
    n.x /= 2;
    n.y /= 2;
  }
  return n;
}

// Constraints that keep every vertex inside the coordinate range, in the sweep's form.
void boundConstraints(const std::vector<Vec2>& verts, Constraint out[4]) {
  int64_t x0 = INT64_MAX, x1 = INT64_MIN, y0 = INT64_MAX, y1 = INT64_MIN;
  for (const Vec2 v : verts) {
    x0 = std::min<int64_t>(x0, v.x), x1 = std::max<int64_t>(x1, v.x);
    y0 = std::min<int64_t>(y0, v.y), y1 = std::max<int64_t>(y1, v.y);
  }
  out[0] = {kCoordLimit - x1, {1, 0}};
  out[1] = {x0 + kCoordLimit, {-1, 0}};
  out[2] = {kCoordLimit - y1, {0, 1}};
  out[3] = {y0 + kCoordLimit, {0, -1}};
}

enum class HitKind { None, Solid, Bound, Warp };

struct Hit {
  HitKind kind = HitKind::None;
  Fraction t = Fraction::one();
  size_t instance = 0;
  LineIndex line = 0;
  Sweep sweep;
  Constraint axis;

  // Earlier wins. At equal times: a solid contact before a warp (so walls at edges hold), then the
  // lower instance, then the lower line index. The order never depends on the grid or on the
  // order lines entered a region, so the same map gives the same motion however it is indexed.
  bool improvedBy(Fraction when, HitKind kind2, size_t instance2, LineIndex line2) const {
    if (kind == HitKind::None) return when < Fraction::one();
    if (when != t) return when < t;
    const bool warp = kind == HitKind::Warp, warp2 = kind2 == HitKind::Warp;
    if (warp != warp2) return warp;
    if (instance2 != instance) return instance2 < instance;
    return line2 < line;
  }
};

}  // namespace

void World::stepEntity(EntityId id, Entity& e) {
  for (Instance& inst : e.instances) inst.blockedWarps.clear();
  if (e.angularVelocity != 0) rotateBy(id, e, e.angularVelocity);
  if (e.instances.empty()) return;
  const Vec2w before = e.velocityQ16;
  if (e.gravity) {
    const Vec2w g = mapPart(e.instances[0].part).gravity();
    e.velocityQ16 = clampVelocityQ16(e.velocityQ16 + g);
  }
  // The frame moves by the average of the velocities at its start and end: for constant gravity
  // that is the exact parabola at every frame, not the first-order step most engines take. The
  // sum of the two Q16 velocities is the average in Q17; whole units move now, the remainder
  // below one unit waits for the next frame.
  const Vec2w acc = e.subunitQ17 + before + e.velocityQ16;
  const Vec2w move{acc.x >> 17, acc.y >> 17};
  e.subunitQ17 = {acc.x - move.x * kQ17, acc.y - move.y * kQ17};
  slide(id, e, move);
}

namespace {

// The box swept by a polygon moving by m; lines wholly outside it cannot be met.
Box sweptBox(const std::vector<Vec2>& verts, Vec2w m) {
  Box b{INT64_MAX, INT64_MAX, INT64_MIN, INT64_MIN};
  for (const Vec2 v : verts) {
    b.x0 = std::min<int64_t>(b.x0, v.x), b.x1 = std::max<int64_t>(b.x1, v.x);
    b.y0 = std::min<int64_t>(b.y0, v.y), b.y1 = std::max<int64_t>(b.y1, v.y);
  }
  if (m.x < 0) b.x0 += m.x; else b.x1 += m.x;
  if (m.y < 0) b.y0 += m.y; else b.y1 += m.y;
  return b;
}

inline bool outside(const Segment& s, const Box& b) {
  return std::max(s.a.x, s.b.x) < b.x0 || std::min(s.a.x, s.b.x) > b.x1 ||
         std::max(s.a.y, s.b.y) < b.y0 || std::min(s.a.y, s.b.y) > b.y1;
}

// Whether t * m is whole: then the rounded step lies on the swept path itself.
bool exactMove(Vec2w m, Fraction t) {
  return t == Fraction::one() || ((i128{t.num} * m.x) % t.den == 0 && (i128{t.num} * m.y) % t.den == 0);
}

}  // namespace

// The earliest time in [0, limit) at which `verts` moved by `step` meets a solid line or the range's
// edge; `limit` when none.
Fraction World::firstBlock(EntityId id, Instance& inst, const std::vector<Vec2>& verts, Vec2w step) {
  const MapPart& part = mapPart(inst.part);
  const auto lines = inst.region.lines();
  const Box box = sweptBox(verts, step);
  Fraction first = Fraction::one();
  for (size_t k = 0; k < lines.size(); ++k) {
    const Segment& seg = part.segments()[lines[k]];
    if (outside(seg, box) || isPierceable(id, inst, k)) continue;
    const Sweep s = sweep(verts, step, seg);
    if (s.hitsWithinFrame() && s.enter < first) first = s.enter;
  }
  Constraint bounds[4];
  boundConstraints(verts, bounds);
  for (const Constraint& c : bounds) {
    const int64_t rate = dot(c.c, step);
    if (rate > 0 && Fraction{c.slack, rate} < first) first = Fraction{c.slack, rate};
  }
  return first;
}

bool World::liftCopy(EntityId id, Instance& copy, Vec2w floorNormal, Vec2w move) {
  const Vec2w n = shortDirection(rotateWide(copy.rotation, floorNormal));
  const uint64_t length2 = static_cast<uint64_t>(n.x * n.x + n.y * n.y);
  uint64_t length = static_cast<uint64_t>(std::sqrt(static_cast<double>(length2)));
  while (length * length > length2) --length;  // exact integer square root, rounded down
  while ((length + 1) * (length + 1) <= length2) ++length;
  if (length == 0) return false;
  const Vec2 was = copy.position;
  std::vector<Vec2> verts;
  for (int64_t lift = 1; lift <= 3; ++lift) {
    copy.position = {was.x + static_cast<int32_t>(roundDiv(i128{n.x} * lift, length)),
                     was.y + static_cast<int32_t>(roundDiv(i128{n.y} * lift, length))};
    if (copy.position == was) continue;
    worldVertices(copy, verts);
    coverMotion(copy, move, 3);
    const MapPart& part = mapPart(copy.part);
    const auto lines = copy.region.lines();
    bool free = true;
    for (const Vec2 v : verts) free = free && inRange(v);
    for (size_t k = 0; k < lines.size() && free; ++k)
      free = isPierceable(id, copy, k) || !overlapsInterior(verts, part.segments()[lines[k]]);
    if (free && firstBlock(id, copy, verts, move) > Fraction::zero()) return true;
  }
  copy.position = was;
  return false;
}

void World::slide(EntityId id, Entity& e, Vec2w motion) {
  std::vector<Vec2w>& normals = scratch_.normals;  // this frame's contact normals, entity frame
  std::vector<std::vector<Vec2>>& verts = scratch_.verts;
  std::vector<Vec2w>& moves = scratch_.moves;
  std::vector<Vec2w>& steps = scratch_.steps;
  std::vector<uint8_t>& pierceNear = scratch_.pierceNear;
  normals.clear();
  for (int iteration = 0; iteration < kMaxSubMoves && !e.instances.empty(); ++iteration) {
    createOverlappedWarps(id, e);
    const size_t n = e.instances.size();
    if (motion == Vec2w{}) {
      bool idle = true;  // non-anchor instances may still owe a correction towards their ideal
      for (size_t i = 1; i < n; ++i) {
        const Instance& inst = e.instances[i];
        const Vec2 target{static_cast<int32_t>(roundDiv(inst.idealQ30.x, i128{1} << 30)),
                          static_cast<int32_t>(roundDiv(inst.idealQ30.y, i128{1} << 30))};
        idle = idle && target == inst.position;
      }
      if (idle) break;
    }
    ++report_.subMoves;
    // 1. Each instance's motion: the anchor's own; the others move as their ideal position does
    //    (the anchor's motion turned into their frame). Closing the gap to the ideal is a separate
    //    step after the move (step 4), so a copy that rounding left a unit off never holds the
    //    entity back.
    verts.resize(n);
    moves.resize(n);
    pierceNear.assign(n, 0);
    for (size_t i = 0; i < n; ++i) {
      Instance& inst = e.instances[i];
      worldVertices(inst, verts[i]);
      if (i == 0) {
        moves[i] = motion;
      } else {
        const Vec2w aim = inst.idealQ30 + rotateQ30(inst.rotation, motion);
        moves[i] = {static_cast<int64_t>(roundDiv(aim.x, i128{1} << 30) - roundDiv(inst.idealQ30.x, i128{1} << 30)),
                    static_cast<int64_t>(roundDiv(aim.y, i128{1} << 30) - roundDiv(inst.idealQ30.y, i128{1} << 30))};
      }
      coverMotion(inst, moves[i]);
    }
    // 2. The earliest event over all instances: a solid line, the world's edge, or a warp whose
    //    target has no instance yet (the move stops there so the new instance starts touching).
    Hit hit;
    for (size_t i = 0; i < n; ++i) {
      Instance& inst = e.instances[i];
      const MapPart& part = mapPart(inst.part);
      const auto lines = inst.region.lines();
      const Box box = sweptBox(verts[i], moves[i]);
      for (size_t k = 0; k < lines.size(); ++k) {
        const Segment& seg = part.segments()[lines[k]];
        if (outside(seg, box)) continue;
        const bool pierce = isPierceable(id, inst, k);
        pierceNear[i] |= pierce;
        if (moves[i] == Vec2w{}) continue;
        const Line& line = part.lines()[lines[k]];
        if (pierce && (line.kind != LineKind::Warp || e.instanceIn(part.warps()[line.warp].target) != nullptr))
          continue;
        const Sweep s = sweep(verts[i], moves[i], seg);
        if (!s.hitsWithinFrame()) continue;
        const HitKind kind = pierce ? HitKind::Warp : HitKind::Solid;
        if (hit.improvedBy(s.enter, kind, i, lines[k])) hit = {kind, s.enter, i, lines[k], s, s.enterAxis};
      }
      Constraint bounds[4];
      boundConstraints(verts[i], bounds);
      for (const Constraint& c : bounds) {
        const int64_t rate = dot(c.c, moves[i]);
        if (rate <= 0) continue;
        const Fraction when{c.slack, rate};
        if (hit.improvedBy(when, HitKind::Bound, i, kWorldBoundLine)) hit = {HitKind::Bound, when, i, kWorldBoundLine, {}, c};
      }
    }
    // A copy that rounding left a hair low snags on the first point of a line that continues the
    // original's floor across the edge: it is stopped at once while the original slides freely.
    // The copy is then lifted off that floor, along the normal of the original's latest contact
    // turned into the copy's frame, by one to three units, if that frees it; the sub-move is redone.
    // A real wall is not helped by a lift along the floor's normal, so it still holds.
    if (hit.kind == HitKind::Solid && hit.instance > 0 && hit.t == Fraction::zero() && !normals.empty() &&
        liftCopy(id, e.instances[hit.instance], normals.back(), moves[hit.instance])) {
      ++report_.copiesReplaced;
      continue;
    }
    // 3. Move every instance to that time, rounded to the safe side. A step that is exactly on
    //    the swept path is free by the search above; a rounded one is proved free by an exact
    //    sweep of its own, and if rounding left the safe path, t is pulled back and retried.
    Fraction t = hit.t;
    bool moved = false;
    for (int attempt = 0; attempt < 4 && !moved; ++attempt) {
      if (attempt == 3) t = Fraction::zero();
      steps.assign(n, Vec2w{});
      bool ok = true;
      for (size_t i = 0; i < n && ok; ++i) {
        const bool keepAxis = attempt == 0 && hit.kind != HitKind::None && i == hit.instance;
        steps[i] = roundedStep(moves[i], t, keepAxis ? &hit.axis : nullptr);
        if (steps[i] == Vec2w{} || (attempt == 0 && exactMove(moves[i], t))) continue;
        const Fraction first = firstBlock(id, e.instances[i], verts[i], steps[i]);
        if (first < Fraction::one()) {
          ok = false;
          ++report_.roundingRetries;
          // Scale t by the free fraction, kept in 24 fractional bits (rounded down).
          const i128 tq = floorDiv(i128{t.num} << 24, t.den);
          t = {static_cast<int64_t>(floorDiv(tq * first.num, first.den)), int64_t{1} << 24};
        }
      }
      moved = ok;
    }
    // 4. Commit; then each copy closes its gap to its ideal position where that path is free.
    for (size_t i = 0; i < n; ++i) {
      Instance& inst = e.instances[i];
      inst.position.x += static_cast<int32_t>(steps[i].x);
      inst.position.y += static_cast<int32_t>(steps[i].y);
      if (i == 0) continue;
      inst.idealQ30 = inst.idealQ30 + rotateQ30(inst.rotation, steps[0]);
      const Vec2w gap{static_cast<int64_t>(roundDiv(inst.idealQ30.x, i128{1} << 30)) - inst.position.x,
                      static_cast<int64_t>(roundDiv(inst.idealQ30.y, i128{1} << 30)) - inst.position.y};
      // A copy keeps a lift of up to three units (see liftCopy); a larger gap, left by a blocked
      // step, is closed where the way is free.
      if (std::max(std::abs(gap.x), std::abs(gap.y)) <= 3) continue;
      std::vector<Vec2> at;
      worldVertices(inst, at);
      coverMotion(inst, gap);
      if (firstBlock(id, inst, at, gap) < Fraction::one()) continue;
      inst.position.x += static_cast<int32_t>(gap.x);
      inst.position.y += static_cast<int32_t>(gap.y);
      steps[i] = steps[i] + gap;  // pierce events see the whole way it went
    }
    const bool pulledBack = t < hit.t;
    motion = motion - steps[0];
    // 5. Pierce events along the way; a warp reached creates the instance on the other side; the
    //    warp links then erase instances the entity has left (which may change the anchor).
    updatePierceState(id, e, &verts, &steps, &pierceNear);
    const MapPartId hitPart = e.instances[hit.instance].part;
    const Vec2w hitMove = moves[hit.instance];
    if (hit.kind == HitKind::Warp && !pulledBack) {
      // The exact touching position, in Q30, maps to where the new instance starts.
      const Vec2 start = e.instances[hit.instance].position;
      const Vec2w before{start.x - steps[hit.instance].x, start.y - steps[hit.instance].y};
      const Vec2w exact{(before.x << 30) + static_cast<int64_t>(floorDiv((i128{hit.t.num} * hitMove.x) << 30, hit.t.den)),
                        (before.y << 30) + static_cast<int64_t>(floorDiv((i128{hit.t.num} * hitMove.y) << 30, hit.t.den))};
      if (!createWarpInstance(id, e, hit.instance, hit.line, exact, motion))
        e.instances[hit.instance].blockedWarps.push_back(hit.line);
    }
    if (!e.links.empty()) updateLinks(id, e, &motion, &normals);
    if (!moved) break;
    if (pulledBack) continue;
    if (hit.kind == HitKind::None) break;
    if (hit.kind == HitKind::Warp) continue;
    // 6. A solid contact: tell the rules, then slide along the line.
    ++report_.hits;
    const Instance* inst = e.instanceIn(hitPart);
    if (!inst) break;
    const Vec2w partNormal = -hit.axis.c;
    ContactPoints points;  // only the rules read them: skip the work when nobody listens
    if (hit.kind == HitKind::Solid && rules_ != &defaultRules_)
      points = contactPoints(verts[hit.instance], hitMove, mapPart(hitPart).segments()[hit.line], hit.sweep);
    const Contact contact = makeContact(id, *inst, hit.line, hit.t, partNormal, points);
    ContactResponse response;
    callRules([&](Rules& r) { r.contact(contact, response); });
    const Vec2w normal = shortDirection(rotateWideInverse(inst->rotation, shortDirection(partNormal)));
    if (response.removeNormalVelocity) e.velocityQ16 = clampVelocityQ16(removeInto(e.velocityQ16, normal));
    if (!response.slide) break;
    Vec2w carryQ17;
    motion = removeIntoCarrying(motion, normal, carryQ17);
    bool crease = false;
    for (const Vec2w& previous : normals) crease = crease || dot128(motion, previous) < 0;
    if (crease) {
      motion = {};  // a crease: the two lines hold it in place
      e.subunitQ17 = {};
    } else {
      // Touching the line, the entity has no fraction of a unit left to move across it, nor away
      // from it; along it, it keeps what rounding left out.
      e.subunitQ17 = withoutComponent(e.subunitQ17 + carryQ17, normal);
    }
    normals.push_back(normal);
  }
}

bool World::rotateBy(EntityId id, Entity& e, int64_t delta) {
  if (delta == 0 || e.instances.empty()) return true;
  // Sub-steps small enough that a vertex's arc leaves its chord by under half a unit; each step's
  // swept area is covered by the hull of the shapes before and after it.
  int64_t radius2 = 1;
  for (const Vec2 v : e.shape.vertices()) radius2 = std::max(radius2, dot(wide(v), wide(v)));
  const double radius = std::sqrt(static_cast<double>(radius2));
  const double turn = std::fabs(static_cast<double>(delta)) * (2.0 * 3.141592653589793 / 4294967296.0);
  const int64_t steps = std::clamp<int64_t>(static_cast<int64_t>(std::ceil(turn / (2.0 / std::sqrt(radius)))), 1, 4096);
  bool blocked = false;
  for (int64_t j = 1; j <= steps && !blocked; ++j) {
    const Angle angle = static_cast<Angle>(e.angle + static_cast<Angle>(delta * j / steps - delta * (j - 1) / steps));
    std::vector<std::vector<Vec2>> shapes;
    for (size_t i = 0; i < e.instances.size() && !blocked; ++i) {
      Instance& inst = e.instances[i];
      std::vector<Vec2> next;
      try {
        const Convex c = e.shape.rotated(static_cast<Angle>(angle + inst.frame));
        next.assign(c.vertices().begin(), c.vertices().end());
      } catch (const Error&) {
        blocked = true;
        break;
      }
      std::vector<Vec2> both = inst.shape;
      both.insert(both.end(), next.begin(), next.end());
      std::vector<Vec2> hull = convexHull(both);
      for (Vec2& v : hull) v = {inst.position.x + v.x, inst.position.y + v.y};
      for (const Vec2 v : hull)
        if (!inRange(v)) blocked = true;
      if (blocked) break;
      const std::vector<Vec2> saved = inst.shape;
      inst.shape = hull;  // cover the swept hull (relative to an origin at 0)
      for (Vec2& v : inst.shape) v = {v.x - inst.position.x, v.y - inst.position.y};
      coverMotion(inst, {});
      inst.shape = saved;
      const MapPart& part = mapPart(inst.part);
      const auto lines = inst.region.lines();
      for (size_t k = 0; k < lines.size() && !blocked; ++k) {
        if (isPierceable(id, inst, k)) continue;
        if (!overlapsInterior(hull, part.segments()[lines[k]])) continue;
        blocked = true;
        const Contact c = makeContact(id, inst, lines[k], Fraction::zero(), {}, {});
        callRules([&](Rules& r) { r.touchContact(c); });
      }
      shapes.push_back(std::move(next));
    }
    if (blocked) break;
    for (size_t i = 0; i < e.instances.size(); ++i) e.instances[i].shape = std::move(shapes[i]);
    e.angle = angle;
  }
  updatePierceState(id, e, nullptr, nullptr);
  updateLinks(id, e, nullptr, nullptr);
  return !blocked;
}

}  // namespace platon::physics
