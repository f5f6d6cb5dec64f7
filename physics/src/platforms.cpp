// Moving platforms: groups of lines of one map part that move by whole units once a frame, before
// the entities step, pushing what is in their way and carrying what stands on them.
#include <algorithm>

#include "bounds.h"
#include "world_impl.h"

namespace platon::physics {
namespace {

Box boxOf(const std::vector<PlatformLine>& lines) {
  Box b{INT64_MAX, INT64_MAX, INT64_MIN, INT64_MIN};
  for (const PlatformLine& l : lines)
    for (const Vec2 p : {l.segment.a, l.segment.b}) {
      b.x0 = std::min<int64_t>(b.x0, p.x), b.x1 = std::max<int64_t>(b.x1, p.x);
      b.y0 = std::min<int64_t>(b.y0, p.y), b.y1 = std::max<int64_t>(b.y1, p.y);
    }
  return b;
}

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
  pl.lines.assign(lines.begin(), lines.end());
  pl.offset = pl.motion = {};
  pl.box = boxOf(pl.lines);
  pl.alive = true;
  ++w.platformEpochs[pl.part];  // what rests in its part is looked at again
  return {index, pl.generation};
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
  pl.alive = false;
  pl.lines.clear();
  ++pl.generation;
  impl_->freePlatforms.push_back(id.index);
}

void World::setPlatformMotion(PlatformId id, Vec2 perFrame) {
  if (std::max(std::abs(int64_t{perFrame.x}), std::abs(int64_t{perFrame.y})) > kMaxMove)
    throw Error("setPlatformMotion: " + toString(perFrame) + " exceeds the largest move per frame, 2^30 units");
  live(*impl_, id).motion = perFrame;
}

PlatformView World::platform(PlatformId id) const {
  const Platform& pl = live(*impl_, id);
  return {pl.part, pl.offset, pl.motion, pl.lines};
}

std::vector<PlatformId> World::platforms() const {
  std::vector<PlatformId> ids;
  for (uint32_t slot = 0; slot < impl_->platforms.size(); ++slot)
    if (impl_->platforms[slot].alive) ids.push_back({slot, impl_->platforms[slot].generation});
  return ids;
}

// The entities standing on platform `slot`: touching one of its lines from the side its face's
// gravity presses them onto, with where they stood, in handle order.
std::vector<WorldImpl::Rider> WorldImpl::ridersOf(uint32_t slot) {
  const MapPartId partId = platforms[slot].part;
  const Vec2w gravity = part(partId).gravity();
  std::vector<Rider> riders;
  std::vector<Vec2> verts;
  Box near = platforms[slot].box;
  near.x0 -= 1, near.y0 -= 1, near.x1 += 1, near.y1 += 1;
  entityIndex.forEachNear(partId, near, [&](uint32_t s) {
    const Entity& e = *slots[s].entity;
    const Instance* inst = e.instanceIn(partId);
    if (!inst) return;
    worldVertices(*inst, verts);
    for (const PlatformLine& l : platforms[slot].lines) {
      if (!stops(l, verts) || !touchesOrOverlaps(verts, l.segment)) continue;
      const Vec2w d = l.segment.b - l.segment.a;
      i128 side = 0;
      for (const Vec2 v : verts) side += cross(d, v - l.segment.a);
      const Vec2w up = side >= 0 ? Vec2w{-d.y, d.x} : Vec2w{d.y, -d.x};
      if (dot128(up, gravity) < 0) {
        riders.push_back({s, inst->position});
        return;
      }
    }
  });
  std::sort(riders.begin(), riders.end(), [](const Rider& a, const Rider& b) { return a.entity < b.entity; });
  return riders;
}

// The first entity the platform's lines meet moving by `motion`: each entity seen from the lines,
// moving by -motion. `at` is one (no hit) when none is met; ties go to the lower slot, then line.
WorldImpl::PlatformHit WorldImpl::firstPlatformHit(uint32_t slot, Vec2w motion) {
  const Platform& pl = platforms[slot];
  Box swept = pl.box;
  (motion.x < 0 ? swept.x0 : swept.x1) += motion.x;
  (motion.y < 0 ? swept.y0 : swept.y1) += motion.y;
  PlatformHit hit;
  std::vector<Vec2> verts;
  entityIndex.forEachNear(pl.part, swept, [&](uint32_t s) {
    const Instance* inst = slots[s].entity->instanceIn(pl.part);
    if (!inst) return;
    worldVertices(*inst, verts);
    for (uint32_t k = 0; k < pl.lines.size(); ++k) {
      if (!stops(pl.lines[k], verts)) continue;
      const Sweep sw = sweep(verts, -motion, pl.lines[k].segment);
      if (!sw.hitsWithinFrame()) continue;
      if (sw.enter < hit.at || (sw.enter == hit.at && (s < hit.entity || (s == hit.entity && k < hit.line))))
        hit = {sw.enter, s, k};
    }
  });
  return hit;
}

// `step`, or the longest step a unit at a time shorter, that the platform's lines make without
// meeting or entering any entity near them (a one-way line may start inside one). `blocker` gets
// the last entity (its slot) that made a step shorter.
Vec2w WorldImpl::clearPlatformStep(uint32_t slot, Vec2w step, std::optional<uint32_t>& blocker) {
  const Platform& pl = platforms[slot];
  std::vector<Vec2> verts;
  for (;;) {
    bool clear = true;
    Box at = pl.box;
    at.x0 += std::min<int64_t>(0, step.x), at.x1 += std::max<int64_t>(0, step.x);
    at.y0 += std::min<int64_t>(0, step.y), at.y1 += std::max<int64_t>(0, step.y);
    entityIndex.forEachNear(pl.part, at, [&](uint32_t s) {
      const Instance* inst = slots[s].entity->instanceIn(pl.part);
      if (!clear || !inst) return;
      worldVertices(*inst, verts);
      for (const PlatformLine& l : pl.lines) {
        if (!stops(l, verts)) continue;
        const Sweep sw = sweep(verts, -step, l.segment);
        if (sw.hitsWithinFrame() || (sw.startsInside() && l.kind != LineKind::OneWay)) clear = false;
      }
      if (!clear) blocker = s;
    });
    if (clear || step == Vec2w{}) return step;
    step = {step.x - (step.x > 0) + (step.x < 0), step.y - (step.y > 0) + (step.y < 0)};  // a unit back
  }
}

void WorldImpl::shiftPlatform(uint32_t slot, Vec2w step) {
  Platform& pl = platforms[slot];
  if (step != Vec2w{}) ++platformEpochs[pl.part];
  for (PlatformLine& l : pl.lines)
    l.segment = {{static_cast<int32_t>(l.segment.a.x + step.x), static_cast<int32_t>(l.segment.a.y + step.y)},
                 {static_cast<int32_t>(l.segment.b.x + step.x), static_cast<int32_t>(l.segment.b.y + step.y)}};
  pl.offset = {static_cast<int32_t>(pl.offset.x + step.x), static_cast<int32_t>(pl.offset.y + step.y)};
  pl.box = boxOf(pl.lines);
}

// Moves platform `slot` by its motion, or until a push is impossible. A platform never moves less
// than its motion without saying why: a frame it ends short of it calls Rules::crushed with the
// entity that stopped it (once). Returns how far it moved.
Vec2w WorldImpl::advancePlatform(uint32_t slot) {
  const MapPartId partId = platforms[slot].part;
  Vec2w remaining = wide(platforms[slot].motion);
  Vec2w moved{};
  std::optional<uint32_t> blocker;  // the last entity in its way
  bool crushedSaid = false;
  for (int attempt = 0; attempt < 8 && remaining != Vec2w{}; ++attempt) {
    // Move to the first contact (all the way if none), rounded towards the start, and proved
    // free of every entity near it.
    const PlatformHit hit = firstPlatformHit(slot, remaining);
    if (hit.at != Fraction::one()) blocker = hit.entity;
    const Vec2w step = clearPlatformStep(slot, roundedStep(remaining, hit.at), blocker);
    shiftPlatform(slot, step);
    moved = moved + step;
    remaining = remaining - step;
    if (remaining == Vec2w{} || hit.at == Fraction::one()) break;
    // Push the entity met by all the platform still has to go; if it cannot make room, the
    // platform stops here.
    Entity& pushed = *slots[hit.entity].entity;
    const Instance& inst = *pushed.instanceIn(partId);
    const Vec2w inFrame = inst.frame == 0 ? remaining : rotateWideInverse(inst.rotation, remaining);
    const bool made = push(pushed, inFrame);
    if (!made && step == Vec2w{}) {
      crushed(slot, hit.entity, hit.line);
      crushedSaid = true;
      break;
    }
  }
  // Short of its motion, whatever stopped it (a push that made only part of the room, the
  // attempts running out, an entity it could not clear): the rules hear of it, as of a crush.
  if (remaining != Vec2w{} && !crushedSaid && blocker && slots[*blocker].entity &&
      slots[*blocker].entity->instanceIn(partId))
    crushed(slot, *blocker, 0);
  return moved;
}

void WorldImpl::crushed(uint32_t slot, uint32_t entity, uint32_t line) {
  Entity& e = *slots[entity].entity;
  Contact c = makeContact(e, *e.instanceIn(platforms[slot].part), kPlatformLineBit | (slot << 16) | line,
                          Fraction::zero(), {}, {});
  callRules([&](Rules& r) { r.crushed(c); });
}

// Carries the riders by what their platform moved, less what it pushed them already.
void WorldImpl::carryRiders(MapPartId partId, const std::vector<Rider>& riders, Vec2w moved) {
  for (const Rider& r : riders) {
    Entity& e = *slots[r.entity].entity;
    const Instance* inst = e.instanceIn(partId);
    if (!inst) continue;
    const Vec2w already = inst->position - r.start;
    const Vec2w carry = moved - already;
    if (carry == Vec2w{}) continue;
    push(e, inst->frame == 0 ? carry : rotateWideInverse(inst->rotation, carry));
  }
}

// One platform's frame: find who stands on it, move it as far as its motion goes or until a push
// is impossible, then carry those standing on it by what it moved (less what it pushed them).
void WorldImpl::movePlatforms() {
  for (uint32_t slot = 0; slot < platforms.size(); ++slot) {
    if (!platforms[slot].alive || platforms[slot].motion == Vec2{}) continue;
    const std::vector<Rider> riders = ridersOf(slot);
    const Vec2w moved = advancePlatform(slot);
    carryRiders(platforms[slot].part, riders, moved);
  }
}

}  // namespace platon::physics
