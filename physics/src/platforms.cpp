// Moving platforms: groups of lines of one map part that move by whole units once a frame, before
// the entities step, pushing what is in their way and carrying what stands on them.
#include <algorithm>
#include <array>

#include "bounds.h"
#include "fixed_point.h"
#include "projection.h"
#include "world_impl.h"

namespace platon::physics {

Box boxOfLines(const std::vector<PlatformLine>& lines) {
  Box b{INT64_MAX, INT64_MAX, INT64_MIN, INT64_MIN};
  for (const PlatformLine& l : lines)
    for (const Vec2 p : {l.segment.a, l.segment.b}) {
      b.x0 = std::min<int64_t>(b.x0, p.x), b.x1 = std::max<int64_t>(b.x1, p.x);
      b.y0 = std::min<int64_t>(b.y0, p.y), b.y1 = std::max<int64_t>(b.y1, p.y);
    }
  return b;
}

namespace {

// Whether the line stops an instance with these vertices (a one-way line only from its front).
bool stops(const PlatformLine& line, std::span<const Vec2> verts) {
  return line.kind != LineKind::OneWay || wholyInFront(verts, line.segment);
}

}  // namespace

PlatformId World::createPlatform(MapPartId partId, std::span<const PlatformLine> lines) {
  WorldImpl& w = *impl_;
  w.checkUnlocked("createPlatform");
  const MapPart& part = w.part(partId);
  if (lines.empty() || lines.size() > 65536)
    throw Error("createPlatform: a platform has 1..65536 lines, got " + std::to_string(lines.size()));
  for (size_t k = 0; k < lines.size(); ++k) {
    const PlatformLine& l = lines[k];
    if (l.kind != LineKind::Solid && l.kind != LineKind::OneWay)
      throw Error("createPlatform: line " + std::to_string(k) + " must be Solid or OneWay");
    if (l.segment.a == l.segment.b || !inRange(l.segment.a) || !inRange(l.segment.b))
      throw Error("createPlatform: line " + std::to_string(k) + " " + toString(l.segment.a) + "-" +
                  toString(l.segment.b) + " is empty or outside the coordinate range");
  }
  // Nothing may be inside it from the start.
  for (const WorldImpl::Slot& slot : w.slots) {
    const Entity* e = slot.entity.get();
    const Instance* inst = e ? e->instanceIn(partId) : nullptr;
    if (!inst) continue;
    const std::vector<Vec2> verts = worldVertices(*inst);
    for (size_t k = 0; k < lines.size(); ++k)
      if (stops(lines[k], verts) && overlapsInterior(verts, lines[k].segment))
        throw Error("createPlatform: line " + std::to_string(k) + " would overlap entity " +
                    std::to_string(e->id.index));
  }
  uint32_t index;
  if (!w.freePlatforms.empty()) {
    index = w.freePlatforms.back();
    w.freePlatforms.pop_back();
  } else {
    if (w.platforms.size() >= (1u << 14)) throw Error("createPlatform: too many platforms (16,384)");
    index = static_cast<uint32_t>(w.platforms.size());
    w.platforms.push_back({});
  }
  Platform& pl = w.platforms[index];
  pl.part = part.id();
  pl.base.assign(lines.begin(), lines.end());
  pl.lines = pl.base;
  pl.offset = pl.motion = pl.pivot = {};
  pl.motionQ30 = pl.motionLeftQ30 = {};
  pl.angle = 0;
  pl.spin = 0;
  pl.box = boxOfLines(pl.lines);
  pl.copies.clear();
  pl.alive = true;
  ++w.platformEpochs[pl.part];  // what rests in its part is looked at again
  const PlatformId id{index, pl.generation};
  if (const std::optional<WorldImpl::PlatformHit> over =
          w.updatePlatformCopies(index, {}, WorldImpl::CopyPlacing::Create)) {
    destroyPlatform(id);
    throw Error("createPlatform: line " + std::to_string(over->line) + " would overlap entity " +
                std::to_string(over->entity) + " in map part " + std::to_string(over->part) +
                ", beyond a warp edge its lines reach");
  }
  return id;
}

namespace {
Platform& live(WorldImpl& w, PlatformId id) {
  if (id.index >= w.platforms.size() || !w.platforms[id.index].alive ||
      w.platforms[id.index].generation != id.generation)
    throw Error("platform " + std::to_string(id.index) + ":" + std::to_string(id.generation) +
                " does not exist (destroyed or never created)");
  return w.platforms[id.index];
}
}  // namespace

void World::destroyPlatform(PlatformId id) {
  impl_->checkUnlocked("destroyPlatform");
  Platform& pl = live(*impl_, id);
  ++impl_->platformEpochs[pl.part];
  for (const PlatformCopy& c : pl.copies) ++impl_->platformEpochs[c.part];
  pl.copies.clear();
  pl.alive = false;
  pl.lines.clear();
  pl.base.clear();
  ++pl.generation;
  impl_->freePlatforms.push_back(id.index);
}

void World::setPlatformMotion(PlatformId id, Vec2 perFrame) {
  if (std::max(std::abs(int64_t{perFrame.x}), std::abs(int64_t{perFrame.y})) > kMaxMove)
    throw Error("setPlatformMotion: " + toString(perFrame) + " exceeds the largest move per frame, 2^30 units");
  Platform& pl = live(*impl_, id);
  pl.motion = perFrame;
  pl.motionQ30 = q30FromPoint(perFrame);
  pl.motionLeftQ30 = {};
}

int64_t turnRadius2(const std::vector<PlatformLine>& lines, Vec2 pivot) {
  int64_t radius2 = 1;
  for (const PlatformLine& l : lines)
    for (const Vec2 p : {l.segment.a, l.segment.b}) {
      const Vec2w r = wide(p) - wide(pivot);
      radius2 = std::max<int64_t>(radius2, static_cast<int64_t>(std::min<i128>(dot128(r, r), INT64_MAX)));
    }
  return radius2;
}

void World::setPlatformSpin(PlatformId id, Vec2 pivot, int32_t anglePerFrame) {
  if (anglePerFrame > kMaxPlatformSpin || anglePerFrame < -kMaxPlatformSpin)
    throw Error("setPlatformSpin: " + std::to_string(anglePerFrame) +
                " exceeds the largest turn per frame, 2^28 binary-angle units (1/16 of a turn)");
  if (!inRange(pivot)) throw Error("setPlatformSpin: pivot " + toString(pivot) + " is outside the coordinate range");
  Platform& pl = live(*impl_, id);
  const Vec2 pivotBase{pivot.x - pl.offset.x, pivot.y - pl.offset.y};
  // A new pivot for a turned platform: its lines where they are now become its lines as created,
  // so nothing jumps (the turn so far is kept in them, rounded once).
  const bool rebase = pivotBase != pl.pivot && pl.angle != 0;
  std::vector<PlatformLine> base = pl.base;
  if (rebase)
    for (size_t k = 0; k < base.size(); ++k)
      base[k].segment = {{pl.lines[k].segment.a.x - pl.offset.x, pl.lines[k].segment.a.y - pl.offset.y},
                         {pl.lines[k].segment.b.x - pl.offset.x, pl.lines[k].segment.b.y - pl.offset.y}};
  // What a frame of it costs, bounded (a far pivot and a fast turn make many sub-steps).
  const int64_t steps = anglePerFrame == 0 ? 0 : rotationSubSteps(turnRadius2(base, pivotBase), anglePerFrame);
  const int64_t lineSteps = steps * static_cast<int64_t>(base.size());
  if (steps > kMaxPlatformTurnSubSteps || lineSteps > kMaxPlatformTurnLineSteps)
    throw Error("setPlatformSpin: turning its " + std::to_string(base.size()) + " lines about " + toString(pivot) +
                " by " + std::to_string(anglePerFrame) + " a frame takes " + std::to_string(steps) +
                " sub-steps a frame (at most " + std::to_string(kMaxPlatformTurnSubSteps) + ", and " +
                std::to_string(kMaxPlatformTurnLineSteps) +
                " sub-steps times lines): turn it slower, or about a nearer point");
  if (rebase) {
    pl.base = std::move(base);
    pl.angle = 0;
  }
  pl.pivot = pivotBase;
  pl.spin = anglePerFrame;
}

PlatformView World::platform(PlatformId id) const {
  const Platform& pl = live(*impl_, id);
  const Vec2 pivot{pl.pivot.x + pl.offset.x, pl.pivot.y + pl.offset.y};
  PlatformView view{pl.part, pl.offset, pl.motion, pl.lines, pivot, pl.angle, pl.spin, pl.work, {}};
  for (const PlatformCopy& c : pl.copies) view.copies.push_back({c.part, c.lines});
  return view;
}

std::vector<PlatformId> World::platforms() const {
  std::vector<PlatformId> ids;
  for (uint32_t slot = 0; slot < impl_->platforms.size(); ++slot)
    if (impl_->platforms[slot].alive) ids.push_back({slot, impl_->platforms[slot].generation});
  return ids;
}

namespace {

void shift(std::vector<Vec2>& verts, Vec2w by) {
  for (Vec2& v : verts) v = {static_cast<int32_t>(v.x + by.x), static_cast<int32_t>(v.y + by.y)};
}

}  // namespace

// The entities standing on platform `slot`, in its part or a copy's (where it meets them:
// platformMeets): touching one of its lines from the side that part's gravity presses them onto,
// with where they stood, in handle order.
std::vector<WorldImpl::Rider> WorldImpl::ridersOf(uint32_t slot) {
  const Platform& pl = platforms[slot];
  const bool turning = pl.spin != 0 || pl.angle != 0;
  std::vector<Rider> riders;
  std::vector<Vec2> verts, lower;
  auto ridersIn = [&](const PlatformPlace& at) {
    const Vec2w gravity = part(at.part).gravity();
    const PlatformCopy* copy = platformCopyIn(pl, at.part);
    const Vec2 origin = copy ? pointFromQ30(copy->originQ30) : pl.offset;
    // A tilted line (turned, or a copy's, or sloped as made) is where whole-unit positions leave a
    // body that came to rest on it up to a unit and a half off it (the rest test's reach), and its
    // slide along it a unit more now and then (each step rounded to whole units): it stands on it
    // all the same. A copy's lines and the body's copy are also each rounded in their own frame.
    const Vec2w down = stepAlong(gravity, 1);
    auto standsOn = [&](const Segment& s) {
      if (!turning && !copy && (s.a.x == s.b.x || s.a.y == s.b.y)) return touchesOrOverlaps(verts, s);
      std::vector<Vec2w>& normals = scratch.lineNormals;
      normals.clear();
      if (nearNormals(verts, s, normals) != Nearness::Apart) return true;
      lower = verts;
      shift(lower, down);
      return nearNormals(lower, s, normals) != Nearness::Apart;
    };
    const Box near{at.box.x0 - 2, at.box.y0 - 2, at.box.x1 + 2, at.box.y1 + 2};
    entityIndex.forEachNear(at.part, near, [&](uint32_t s) {
      const Entity& e = *slots[s].entity;
      const Instance* inst = e.instanceIn(at.part);
      if (!inst || platformMeets(pl, e) != at.part) return;
      worldVertices(*inst, verts);
      if (passesThrough(at.lines, verts)) return;  // not carried
      for (const PlatformLine& l : at.lines) {
        if (!stops(l, verts) || !standsOn(l.segment)) continue;
        if (dot128(normalTowards(verts, l.segment), gravity) < 0) {  // it stands on the line's upper side
          riders.push_back({s, at.part, inst->position, origin});
          return;
        }
      }
    });
  };
  forEachPlatformPlace(pl, {}, ridersIn);
  std::sort(riders.begin(), riders.end(), [](const Rider& a, const Rider& b) { return a.entity < b.entity; });
  return riders;
}

// The first entity the platform's lines meet moving by `motion`, in its part or a copy's (there by
// the copy's step; each entity where platformMeets it): each entity seen from the lines, moving by
// -motion. `at` is one (no hit) when none is met; ties go to the lower slot, then line.
WorldImpl::PlatformHit WorldImpl::firstPlatformHit(uint32_t slot, Vec2w motion) {
  const Platform& pl = platforms[slot];
  PlatformHit hit;
  std::vector<Vec2> verts;
  uint64_t work = 0;
  auto firstIn = [&](const PlatformPlace& at) {
    const Vec2w m = at.step;
    work += at.lines.size();
    Box swept = at.box;
    (m.x < 0 ? swept.x0 : swept.x1) += m.x;
    (m.y < 0 ? swept.y0 : swept.y1) += m.y;
    entityIndex.forEachNear(at.part, swept, [&](uint32_t s) {
      const Instance* inst = slots[s].entity->instanceIn(at.part);
      if (!inst || platformMeets(pl, *slots[s].entity) != at.part || (pocket.platform == slot && pocket.entity == s))
        return;
      work += at.lines.size();
      worldVertices(*inst, verts);
      if (at.part != pl.part && passesThrough(at.lines, verts)) return;
      for (uint32_t k = 0; k < at.lines.size(); ++k) {
        if (!stops(at.lines[k], verts)) continue;
        const Sweep sw = sweep(verts, -m, at.lines[k].segment);
        if (!sw.hitsWithinFrame()) continue;
        if (sw.enter < hit.at || (sw.enter == hit.at && (s < hit.entity || (s == hit.entity && k < hit.line))))
          hit = {sw.enter, s, k, at.part};
      }
    });
  };
  forEachPlatformPlace(pl, motion, firstIn);
  platforms[slot].work += work;
  return hit;
}

// `step`, or the longest step a unit at a time shorter, that the platform's lines make (in its part
// and its copies') without meeting or entering any entity near them (a one-way line may start inside
// one). `blocker` gets the last entity that made a step shorter, and where.
Vec2w WorldImpl::clearPlatformStep(uint32_t slot, Vec2w step, std::optional<PlatformHit>& blocker) {
  const Platform& pl = platforms[slot];
  std::vector<Vec2> verts;
  bool clear = true;
  auto clearIn = [&](const PlatformPlace& at) {
    const Vec2w m = at.step;
    Box swept = at.box;
    swept.x0 += std::min<int64_t>(0, m.x), swept.x1 += std::max<int64_t>(0, m.x);
    swept.y0 += std::min<int64_t>(0, m.y), swept.y1 += std::max<int64_t>(0, m.y);
    entityIndex.forEachNear(at.part, swept, [&](uint32_t s) {
      const Instance* inst = slots[s].entity->instanceIn(at.part);
      if (!clear || !inst || platformMeets(pl, *slots[s].entity) != at.part ||
          (pocket.platform == slot && pocket.entity == s))
        return;
      platforms[slot].work += at.lines.size();
      worldVertices(*inst, verts);
      if (at.part != pl.part && passesThrough(at.lines, verts)) return;
      for (const PlatformLine& l : at.lines) {
        if (!stops(l, verts)) continue;
        const Sweep sw = sweep(verts, -m, l.segment);
        // In its own part, a body in one of its lines stops it (never left there); in a copy's, one
        // is passed through (above).
        const bool inside = sw.startsInside() && l.kind != LineKind::OneWay && at.part == pl.part;
        if (sw.hitsWithinFrame() || inside) clear = false;
      }
      if (!clear) blocker = PlatformHit{Fraction::zero(), s, 0, at.part};
    });
  };
  for (;;) {
    clear = true;
    forEachPlatformPlace(pl, step, clearIn);
    if (clear || step == Vec2w{}) return step;
    step = {step.x - (step.x > 0) + (step.x < 0), step.y - (step.y > 0) + (step.y < 0)};  // a unit back
  }
}

void WorldImpl::shiftPlatform(uint32_t slot, Vec2w step) {
  Platform& pl = platforms[slot];
  auto shift = [](std::vector<PlatformLine>& lines, Vec2w by) {
    for (PlatformLine& l : lines)
      l.segment = {{static_cast<int32_t>(l.segment.a.x + by.x), static_cast<int32_t>(l.segment.a.y + by.y)},
                   {static_cast<int32_t>(l.segment.b.x + by.x), static_cast<int32_t>(l.segment.b.y + by.y)}};
  };
  if (step != Vec2w{}) ++platformEpochs[pl.part];
  shift(pl.lines, step);
  pl.offset = {static_cast<int32_t>(pl.offset.x + step.x), static_cast<int32_t>(pl.offset.y + step.y)};
  pl.box = boxOfLines(pl.lines);
  for (PlatformCopy& c : pl.copies) {
    const Vec2w by = c.stepFor(step);
    c.originQ30 = c.originQ30 + rotateQ30(c.rotation, step);
    if (by == Vec2w{}) continue;
    ++platformEpochs[c.part];
    shift(c.lines, by);
    c.box = boxOfLines(c.lines);
  }
}

// Moves platform `slot` by its motion, or until a push is impossible. A platform never moves less
// than its motion without saying why: a frame it ends short of it calls Rules::crushed with the
// entity that stopped it (once). Returns how far it moved.
Vec2w WorldImpl::frameMotion(Platform& pl) {
  const Vec2w exact = pl.motionLeftQ30 + pl.motionQ30;
  const Vec2w whole{exact.x >> kQ30Bits, exact.y >> kQ30Bits};  // rounded down: what is left is below a unit
  pl.motionLeftQ30 = exact - q30FromPoint({static_cast<int32_t>(whole.x), static_cast<int32_t>(whole.y)});
  return whole;
}

Vec2w WorldImpl::advancePlatform(uint32_t slot, Vec2w motion) {
  const MapPartId partId = platforms[slot].part;
  Vec2w remaining = motion;
  Vec2w moved{};
  std::optional<PlatformHit> blocker;  // the last entity in its way
  bool crushedSaid = false;
  for (int attempt = 0; attempt < 8 && remaining != Vec2w{}; ++attempt) {
    // Move to the first contact (all the way if none), rounded towards the start, and proved
    // free of every entity near it.
    const PlatformHit hit = firstPlatformHit(slot, remaining);
    if (hit.at != Fraction::one()) blocker = hit;
    const Vec2w step = clearPlatformStep(slot, roundedStep(remaining, hit.at), blocker);
    shiftPlatform(slot, step);
    moved = moved + step;
    remaining = remaining - step;
    if (remaining == Vec2w{} || hit.at == Fraction::one()) break;
    // Push the entity met by all the platform still has to go (in the part it was met in, by the
    // lines' step there); if it cannot make room, the platform stops here.
    Entity& pushed = *slots[hit.entity].entity;
    const Instance& inst = *pushed.instanceIn(hit.part);
    const Vec2w there = hit.part == partId ? remaining : platformCopyIn(platforms[slot], hit.part)->stepFor(remaining);
    const Vec2w inFrame = inst.frame == 0 ? there : rotateWideInverse(inst.rotation, there);
    // Held by the platform's own lines on the far side (in a pocket of them), it goes along.
    if (hit.part == partId && heldByOwnLines(slot, pushed, remaining)) {
      if (const Vec2w carried = carryInPocket(slot, hit.entity, remaining); carried != Vec2w{}) {
        moved = moved + carried;
        remaining = remaining - carried;
        continue;
      }
    }
    const bool made = push(pushed, inFrame);
    if (!made && step == Vec2w{}) {
      crushed(slot, hit.entity, hit.line, hit.part);
      crushedSaid = true;
      break;
    }
  }
  // Short of its motion, whatever stopped it (a push that made only part of the room, the
  // attempts running out, an entity it could not clear): the rules hear of it, as of a crush.
  if (remaining != Vec2w{} && !crushedSaid && blocker && slots[blocker->entity].entity &&
      !slots[blocker->entity].entity->instances.empty())
    crushed(slot, blocker->entity, 0, blocker->part);
  return moved;
}

// Whether the instance's way by `step` (a few units wider) comes near a warp line of its part.
bool WorldImpl::nearAWarp(Instance& inst, Vec2w step) {
  coverMotion(inst, step, 3);
  std::vector<Vec2> verts;
  worldVertices(inst, verts);
  Box box = sweptBox(verts, step);
  box.x0 -= 3, box.y0 -= 3, box.x1 += 3, box.y1 += 3;
  const MapPart& p = part(inst.part);
  const auto lines = inst.region.lines();
  return std::any_of(lines.begin(), lines.end(),
                     [&](uint32_t k) { return p.lines()[k].kind == LineKind::Warp && !outside(p.segments()[k], box); });
}

// Whether the platform's own lines stop `e` (wholly in the platform's part) going straight by
// `motion`, the platform's, before it is through: they are in its way on the side the platform goes
// to, so it is in a pocket of its lines, which go along with it.
bool WorldImpl::heldByOwnLines(uint32_t slot, const Entity& e, Vec2w motion) {
  const Platform& pl = platforms[slot];
  if (e.instances.size() != 1 || e.instances[0].part != pl.part) return false;
  std::vector<Vec2> verts;
  worldVertices(e.instances[0], verts);
  return std::any_of(pl.lines.begin(), pl.lines.end(), [&](const PlatformLine& l) {
    return stops(l, verts) && sweep(verts, motion, l.segment).hitsWithinFrame();
  });
}

// A body the platform's line cannot push because the platform's own lines hold it on the far side
// (a body snug in a pocket of its lines: a cage, a cup with a lid) is no crush: it goes with the
// platform as if fixed to it. The platform steps as far as it is free of every other body; the body
// goes straight that way as far as it is free of everything but this platform (a push of its own,
// events and all); the platform then steps by what the body went, less where that is not free, and
// the body goes back by the difference, the way it came. Both end where they were to each other.
// Only a body wholly in the platform's part that stays so: over an edge its copy, rounded in its
// own frame, could be carried into the platform's copy. Returns the step they made (nothing: the
// body cannot go, and the push that follows is the crush it was).
Vec2w WorldImpl::carryInPocket(uint32_t slot, uint32_t entity, Vec2w remaining) {
  Entity& e = *slots[entity].entity;
  auto inFrame = [&](Vec2w step) {
    const Instance& inst = e.instances[0];
    return inst.frame == 0 ? step : rotateWideInverse(inst.rotation, step);
  };
  // Each coordinate between none and all of `along`'s.
  auto partOf = [](Vec2w v, Vec2w along) {
    auto within = [](int64_t x, int64_t a) { return a >= 0 ? x >= 0 && x <= a : x <= 0 && x >= a; };
    return within(v.x, along.x) && within(v.y, along.y);
  };
  pocket = {slot, entity};
  std::optional<PlatformHit> blocker;
  const Vec2w free = clearPlatformStep(slot, remaining, blocker);
  const Vec2 before = e.instances[0].position;
  Vec2w went{};
  if (free != Vec2w{} && !nearAWarp(e.instances[0], free)) {
    push(e, inFrame(free), true);
    went = wide(e.instances[0].position) - wide(before);
    if (e.instances.size() != 1 || !partOf(went, free)) {  // off the way (not expected): back, no carry
      push(e, inFrame(-went), true);
      went = {};
    }
  }
  // Straight on, it goes a part of the way (each coordinate towards zero): the platform's step that
  // far is proved again, and what the platform cannot make the body takes back.
  const Vec2w step = went == Vec2w{} ? went : clearPlatformStep(slot, went, blocker);
  if (step != went) push(e, inFrame(step - went), true);
  pocket = {};
  if (step != Vec2w{}) shiftPlatform(slot, step);
  return step;
}

void WorldImpl::crushed(uint32_t slot, uint32_t entity, uint32_t line, MapPartId part) {
  Entity& e = *slots[entity].entity;
  // In the part it was met in; pushed out of it since (over an edge), where it is now.
  const Instance& inst = e.instanceIn(part) ? *e.instanceIn(part) : e.instances.front();
  Contact c = makeContact(e, inst, kPlatformLineBit | (slot << 16) | line, Fraction::zero(), {}, {});
  callRules([&](Rules& r) { r.crushed(c); });
}

// Carries the riders as if fixed to their platform: by what it moved, then turned about its pivot
// by what it turned, less what it pushed them already.
void WorldImpl::carryRiders(uint32_t slot, const std::vector<Rider>& riders, Vec2w moved, Angle turned) {
  const Platform& pl = platforms[slot];
  const Vec2w pivot{int64_t{pl.pivot.x} + pl.offset.x, int64_t{pl.pivot.y} + pl.offset.y};
  const Rotation rotation = rotationOf(turned);
  for (const Rider& r : riders) {
    Entity& e = *slots[r.entity].entity;
    const Instance* inst = e.instanceIn(r.part);
    if (!inst) continue;
    Vec2w to;
    const std::vector<PlatformLine>* lines = &pl.lines;
    if (r.part == pl.part) {
      const Vec2w moved0 = wide(r.start) + moved;
      to = turned == 0 ? moved0 : pivot + rotateWide(rotation, moved0 - pivot);
    } else {  // on a copy: by what the copy moved, then turned about the pivot placed there
      const PlatformCopy* copy = platformCopyIn(pl, r.part);
      if (!copy) continue;
      const Vec2w moved0 = wide(r.start) + (pointFromQ30(copy->originQ30) - r.origin);
      const Vec2w there = turned == 0 ? Vec2w{} : pointThrough(pl, copy->edge, pivot);
      to = turned == 0 ? moved0 : there + rotateWide(rotation, moved0 - there);
      lines = &copy->lines;
    }
    const Vec2w carry = to - wide(inst->position);
    if (carry != Vec2w{}) push(e, inst->frame == 0 ? carry : rotateWideInverse(inst->rotation, carry));
    if (turned != 0) settleOn(r.part, *lines, e);
  }
}

// A rider carried by a turn ends where rounding put it, up to two units off the turned line: it is
// let down along its part's gravity (a slide, so it stops on the first thing it meets) to stand on
// it again, as a body fixed to the platform would.
void WorldImpl::settleOn(MapPartId partId, const std::vector<PlatformLine>& lines, Entity& e) {
  const Instance* inst = e.instanceIn(partId);
  const Vec2w g = part(partId).gravity();
  if (!inst || g == Vec2w{}) return;
  std::vector<Vec2> verts;
  worldVertices(*inst, verts);
  for (const PlatformLine& l : lines)
    if (stops(l, verts) && touchesOrOverlaps(verts, l.segment)) return;  // standing on it
  const Vec2w down = stepAlong(g, 2);
  if (down != Vec2w{}) push(e, inst->frame == 0 ? down : rotateWideInverse(inst->rotation, down));
}

void WorldImpl::placePlatformLines(const Platform& pl, Angle angle, std::vector<PlatformLine>& out) const {
  out = pl.base;
  const Rotation rotation = rotationOf(angle);
  auto place = [&](Vec2 p) {
    const Vec2w turned = wide(pl.pivot) + rotateWide(rotation, wide(p) - wide(pl.pivot));
    return Vec2w{turned.x + pl.offset.x, turned.y + pl.offset.y};
  };
  for (PlatformLine& l : out) {
    const Vec2w a = place(l.segment.a), b = place(l.segment.b);
    l.segment = {{static_cast<int32_t>(std::clamp<int64_t>(a.x, INT32_MIN, INT32_MAX)),
                  static_cast<int32_t>(std::clamp<int64_t>(a.y, INT32_MIN, INT32_MAX))},
                 {static_cast<int32_t>(std::clamp<int64_t>(b.x, INT32_MIN, INT32_MAX)),
                  static_cast<int32_t>(std::clamp<int64_t>(b.y, INT32_MIN, INT32_MAX))}};
  }
}

namespace {

// Whether turning `from` to `to` about `pivot` sweeps over the vertices: they overlap the line's
// new place, or what a part of it passed over in between. A line turning about a point moves
// across itself one way on one side of the point nearest the pivot and the other way on the other
// side, so each side is taken on its own (the hull of its old and new place), and only for a body
// on the side that side moves towards: a plank turning about its middle sweeps the body its rising
// end lifts, not the one its sinking end leaves.
bool sweptOver(const Segment& from, const Segment& to, Vec2w pivot, std::span<const Vec2> verts) {
  if (overlapsInterior(verts, to)) return true;
  const Vec2w d = from.b - from.a, dn = to.b - to.a;
  const i128 dd = dot128(d, d);
  if (dd == 0) return false;
  const i128 u = std::clamp<i128>(dot128(pivot - wide(from.a), d), 0, dd);  // the foot, as u / dd along
  auto at = [&](const Segment& s, Vec2w dir) {
    return Vec2{static_cast<int32_t>(s.a.x + roundDiv(u * dir.x, dd)),
                static_cast<int32_t>(s.a.y + roundDiv(u * dir.y, dd))};
  };
  const Vec2 foot = at(from, d), footNew = at(to, dn);
  i128 side = 0;  // which side of the line the body is on (the sum over its vertices)
  for (const Vec2 v : verts) side += cross(d, v - from.a);
  const Vec2w left{-d.y, d.x};
  for (const auto& [end, endNew] : {std::pair{from.a, to.a}, std::pair{from.b, to.b}}) {
    if (end == foot) continue;
    const i128 towards = dot128(endNew - end, left);  // how that side's far end moves across the line
    if ((towards > 0 && side < 0) || (towards < 0 && side > 0) || towards == 0) continue;
    const std::vector<Vec2> hull = convexHull({end, foot, endNew, footNew});
    if (hull.size() >= 3 && overlapsInterior(verts, hull)) return true;
  }
  return false;
}

// How far the point of `from` nearest to `p` goes when `from` turns to `to` (the same fraction
// along both), each component rounded away from zero.
Vec2w sweepAt(const Segment& from, const Segment& to, Vec2w p) {
  const Vec2w d = from.b - from.a, da = to.a - from.a, db = to.b - from.b;
  const i128 dd = dot128(d, d);
  const i128 along = dd == 0 ? 0 : std::clamp<i128>(dot128(p - wide(from.a), d), 0, dd);
  auto away = [&](int64_t start, int64_t end) {
    if (dd == 0) return start;
    const i128 q = i128{start} * dd + along * (end - start);
    return static_cast<int64_t>(q >= 0 ? ceilDiv(q, dd) : floorDiv(q, dd));
  };
  return {away(da.x, db.x), away(da.y, db.y)};
}

}  // namespace

namespace {

Box boxOfSegments(const Segment& a, const Segment& b) {
  const std::array<Vec2, 4> ends{a.a, a.b, b.a, b.b};
  return sweptBox(ends, {});
}

bool boxesMeet(const Box& a, const Box& b) { return a.x0 <= b.x1 && a.x1 >= b.x0 && a.y0 <= b.y1 && a.y1 >= b.y0; }

// The ring about the pivot that a turn's lines sweep: from the nearest any line comes to the pivot
// to the farthest end (squared). A body wholly inside or outside it is met by none of them.
struct Ring {
  i128 near2 = -1, far2 = 0;
  void add(const Segment& s, Vec2w pivot) {
    const Vec2w d = s.b - s.a, pa = pivot - wide(s.a);
    const i128 dd = dot128(d, d), along = dd == 0 ? 0 : std::clamp<i128>(dot128(pa, d), 0, dd);
    // The squared distance from the pivot to the segment, rounded down (a unit's margin below).
    const i128 cx = i128{pa.x} * dd - along * d.x, cy = i128{pa.y} * dd - along * d.y;
    const i128 toLine = dd == 0 ? dot128(pa, pa) : (cx / dd) * (cx / dd) + (cy / dd) * (cy / dd);
    near2 = near2 < 0 ? toLine : std::min(near2, toLine);
    for (const Vec2 p : {s.a, s.b}) far2 = std::max(far2, dot128(wide(p) - pivot, wide(p) - pivot));
  }
  // Whether the box can meet the ring (with a few units of margin for rounding).
  bool meets(const Box& b, Vec2w pivot) const {
    const i128 dx = std::max<i128>({0, i128{b.x0} - pivot.x, i128{pivot.x} - b.x1});
    const i128 dy = std::max<i128>({0, i128{b.y0} - pivot.y, i128{pivot.y} - b.y1});
    const i128 fx = std::max<i128>(i128{b.x1} - pivot.x, i128{pivot.x} - b.x0);
    const i128 fy = std::max<i128>(i128{b.y1} - pivot.y, i128{pivot.y} - b.y0);
    const i128 nearest2 = dx * dx + dy * dy, farthest2 = fx * fx + fy * fy;
    const i128 margin = 4 * (isqrtWide(far2) + 4);  // (r + 2)^2 - r^2 > 4r: a couple of units either way
    return nearest2 <= far2 + margin && farthest2 + margin >= near2;
  }
  static i128 isqrtWide(i128 v) { return static_cast<i128>(isqrt(static_cast<u128>(v))); }
};

}  // namespace

namespace {

// What one sub-step of a turn sweeps: each line's box (its old and new place, a unit wider), all
// of them together, and the ring about the pivot they sweep.
struct TurnSweep {
  Vec2w pivot;
  std::vector<Box> lineBoxes;
  Box area{INT64_MAX, INT64_MAX, INT64_MIN, INT64_MIN};
  Ring ring;
};

TurnSweep sweepOfTurn(const WorldImpl::TurnPlace& at) {
  const std::vector<PlatformLine>& from = *at.from;
  const std::vector<PlatformLine>& next = at.to;
  TurnSweep t;
  t.pivot = at.pivot;
  for (size_t k = 0; k < next.size(); ++k) {
    const Box b = boxOfSegments(from[k].segment, next[k].segment);
    t.lineBoxes.push_back({b.x0 - 1, b.y0 - 1, b.x1 + 1, b.y1 + 1});
    const Box& w = t.lineBoxes.back();
    t.area = {std::min(t.area.x0, w.x0), std::min(t.area.y0, w.y0), std::max(t.area.x1, w.x1),
              std::max(t.area.y1, w.y1)};
    t.ring.add(from[k].segment, t.pivot);
    t.ring.add(next[k].segment, t.pivot);
  }
  return t;
}

// The first line (in order) whose sweep passes over the vertices, or next.size(); `work` counts the
// lines tested.
size_t lineSweepingOver(const WorldImpl::TurnPlace& at, const TurnSweep& t, std::span<const Vec2> verts,
                        uint64_t& work) {
  const std::vector<PlatformLine>& from = *at.from;
  const Box b = sweptBox(verts, {});
  if (!t.ring.meets(b, t.pivot)) return at.to.size();
  size_t k = 0;
  for (; k < at.to.size(); ++k) {
    ++work;
    if (boxesMeet(b, t.lineBoxes[k]) && stops(from[k], verts) &&
        sweptOver(from[k].segment, at.to[k].segment, t.pivot, verts))
      break;
  }
  return k;
}

// The push that clears a body of a line's sweep from `from` to `to`: where the line's point
// nearest the body's centre goes; on a retry (or when that is nothing), a unit more off the line's
// new place, on the body's side.
Vec2w turnPush(const Segment& from, const Segment& to, Vec2w centre, std::span<const Vec2> verts, bool retry) {
  Vec2w by = sweepAt(from, to, centre);
  if (!retry && by != Vec2w{}) return by;
  const Vec2w out = normalTowards(verts, to);
  return by + Vec2w{out.x > 0 ? 1 : out.x < 0 ? -1 : 0, out.y > 0 ? 1 : out.y < 0 ? -1 : 0};
}

}  // namespace

// Passes over the bodies near, in slot order, pushing each one the lines sweep over (a few times:
// the sweep, then what rounding left). A push can move a body already passed (a chain of pushable
// bodies), so passes go on until one pushes nothing: then every body is clear. A body that cannot
// be cleared stops the sub-step. In a copy's part, only the bodies the platform meets there
// (platformMeets). Not `pushing`, the first body swept over stops it.
bool WorldImpl::clearTurn(uint32_t slot, const TurnPlace& at, uint32_t& blocker, bool& pushedAny, bool pushing) {
  const TurnSweep sweep = sweepOfTurn(at);
  std::vector<Vec2> verts;
  for (int pass = 0; pass < 4; ++pass) {
    std::vector<uint32_t> near;
    entityIndex.forEachNear(at.part, sweep.area, [&](uint32_t s) {
      if (platformMeets(platforms[slot], *slots[s].entity) == at.part) near.push_back(s);
    });
    std::sort(near.begin(), near.end());  // slot order: the index's order is not part of the result
    platforms[slot].work += near.size();
    bool pushed = false;
    for (const uint32_t s : near) {
      Entity& e = *slots[s].entity;
      for (int attempt = 0;; ++attempt) {
        const Instance* inst = e.instanceIn(at.part);
        if (!inst) break;
        worldVertices(*inst, verts);
        if (at.part != platforms[slot].part && passesThrough(*at.from, verts)) break;
        const size_t k = lineSweepingOver(at, sweep, verts, platforms[slot].work);
        if (k == at.to.size()) break;
        if (!pushing) {
          blocker = s;
          return false;
        }
        const Vec2w by = turnPush((*at.from)[k].segment, at.to[k].segment, wide(inst->position) + wide(inst->centre),
                                  verts, attempt > 0);
        if (attempt == 3 || pass == 3 || !push(e, inst->frame == 0 ? by : rotateWideInverse(inst->rotation, by))) {
          blocker = s;
          return false;
        }
        pushed = pushedAny = true;
      }
    }
    if (!pushed) return true;
  }
  return true;  // not reached: the last pass returns at its first body still swept over
}

// Each sub-step turns the lines in the platform's part and its copy's (placed through the warp
// again from the turned lines, about the pivot placed there: a warp moves the plane rigidly, so the
// copy turns by the same angle), clearing the bodies each place meets; a body that cannot be
// cleared stops the turn there.
Angle WorldImpl::turnPlatform(uint32_t slot) {
  const int64_t delta = platforms[slot].spin;
  const int64_t steps = rotationSubSteps(turnRadius2(platforms[slot].base, platforms[slot].pivot), delta);
  std::vector<TurnPlace> places;
  Angle turned = 0;
  for (int64_t j = 1; j <= steps; ++j) {
    const Angle by = static_cast<Angle>(delta * j / steps - delta * (j - 1) / steps);
    const Platform& pl = platforms[slot];
    const Vec2w pivot{int64_t{pl.pivot.x} + pl.offset.x, int64_t{pl.pivot.y} + pl.offset.y};
    places.assign(1, {pl.part, &pl.lines, {}, pivot});
    placePlatformLines(pl, static_cast<Angle>(pl.angle + by), places[0].to);
    const bool inside = std::all_of(places[0].to.begin(), places[0].to.end(),
                                    [](const PlatformLine& l) { return inRange(l.segment.a) && inRange(l.segment.b); });
    platforms[slot].work += places[0].to.size();
    if (!inside) break;  // the coordinate range's edge: no entity can be beyond it to hear of it
    for (const PlatformCopy& c : pl.copies) {
      // Turned beyond the coordinate range there: that part has no entity where it goes; the copy
      // is dropped below (its place is made again when the lines come back).
      TurnPlace there{c.part, &c.lines, places[0].to, pointThrough(pl, c.edge, pivot)};
      if (linesThrough(pl, c.edge, there.to)) places.push_back(std::move(there));
    }
    // A body pushed in one place can come to be met in another (pushed from the copy's part into
    // the platform's own, where that was cleared already): the places are gone over again until a
    // round pushes nothing. Rounds that keep pushing (a body beside a vertex, where its instances'
    // places disagree, pushed out of one place into the other and back) end in a round that only
    // looks: a body still swept over stops the turn there.
    uint32_t blocker = 0;
    std::optional<MapPartId> stopped;
    for (int round = 0; round < 4 && !stopped; ++round) {
      bool pushed = false;
      for (const TurnPlace& at : places)
        if (!stopped && !clearTurn(slot, at, blocker, pushed, round < 3)) stopped = at.part;
      if (!pushed) break;
    }
    if (stopped) {
      crushed(slot, blocker, 0, *stopped);
      break;
    }
    Platform& p = platforms[slot];
    p.angle = static_cast<Angle>(p.angle + by);
    p.lines = places[0].to;
    p.box = boxOfLines(p.lines);
    ++platformEpochs[p.part];
    std::erase_if(p.copies, [&](PlatformCopy& c) {
      ++platformEpochs[c.part];
      const auto at =
          std::find_if(places.begin() + 1, places.end(), [&](const TurnPlace& t) { return t.part == c.part; });
      if (at == places.end()) return true;
      c.lines = std::move(at->to);
      c.box = boxOfLines(c.lines);
      return false;
    });
    turned = static_cast<Angle>(turned + by);
  }
  return turned;
}

// One platform's frame: its copies on the faces beside it that this frame's motion reaches, then
// who stands on it; move it as far as its motion goes or until a push is impossible, turn it as far
// as its spin goes or until a push is impossible, then carry those standing on it as if fixed to it
// (less what it pushed them), clearing its copies' lines of what the moves left in them before and
// after the carry (a rider carried through a vertex can land in one); wholly beyond an edge, it
// belongs to the face beyond, and has the copies its lines need there.
void WorldImpl::movePlatforms() {
  for (uint32_t slot = 0; slot < platforms.size(); ++slot) {
    platforms[slot].work = 0;
    if (!platforms[slot].alive || (platforms[slot].motionQ30 == Vec2w{} && platforms[slot].spin == 0)) continue;
    const Vec2w motion = frameMotion(platforms[slot]);
    updatePlatformCopies(slot, motion, CopyPlacing::Frame);
    const std::vector<Rider> riders = ridersOf(slot);
    const Vec2w moved = motion == Vec2w{} ? Vec2w{} : advancePlatform(slot, motion);
    const Angle turned = platforms[slot].spin == 0 ? 0 : turnPlatform(slot);
    clearPlatformCopies(slot);
    carryRiders(slot, riders, moved, turned);
    clearPlatformCopies(slot);
    // Crossed: the lines may be over another edge of the face they came to; a copy there now, where
    // it meets no body at all, rather than the next frame (the entities step meanwhile).
    if (crossPlatform(slot)) updatePlatformCopies(slot, {}, CopyPlacing::Crossed);
  }
}

}  // namespace platon::physics
