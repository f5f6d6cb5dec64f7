// World: ownership, handles and the checked API. The frame step lives in world_slide.cpp, contact
// events and warps in world_contacts.cpp.
#include "platon/physics/world.h"

#include <algorithm>
#include <utility>

namespace platon::physics {

World::World() = default;
World::~World() = default;

void World::checkUnlocked(const char* what) const {
  if (locked_) throw Error(std::string(what) + " is not allowed inside a contact callback (during solve)");
}

MapPart& World::createMapPart(MapPartId id) {
  checkUnlocked("createMapPart");
  auto it = std::lower_bound(partIndex_.begin(), partIndex_.end(), id,
                             [](const MapPart* p, MapPartId v) { return p->id() < v; });
  if (it != partIndex_.end() && (*it)->id() == id)
    throw Error("map part " + std::to_string(id) + " already exists");
  parts_.push_back(MapPart(*this, id));
  partIndex_.insert(it, &parts_.back());
  return parts_.back();
}

const MapPart* World::findMapPart(MapPartId id) const {
  auto it = std::lower_bound(partIndex_.begin(), partIndex_.end(), id,
                             [](const MapPart* p, MapPartId v) { return p->id() < v; });
  return it != partIndex_.end() && (*it)->id() == id ? *it : nullptr;
}

const MapPart& World::mapPart(MapPartId id) const {
  const MapPart* p = findMapPart(id);
  if (!p) throw Error("map part " + std::to_string(id) + " does not exist");
  return *p;
}

MapPart& World::mapPart(MapPartId id) { return const_cast<MapPart&>(std::as_const(*this).mapPart(id)); }

EntityId World::createEntity(const Convex& shape) {
  checkUnlocked("createEntity");
  uint32_t index;
  if (!freeSlots_.empty()) {
    index = freeSlots_.back();
    freeSlots_.pop_back();
  } else {
    index = static_cast<uint32_t>(slots_.size());
    slots_.push_back({});
  }
  Slot& slot = slots_[index];
  slot.entity = std::make_unique<Entity>(shape);
  return {index, slot.generation};
}

bool World::valid(EntityId id) const {
  return id.index < slots_.size() && slots_[id.index].entity && slots_[id.index].generation == id.generation;
}

const Entity& World::entity(EntityId id) const {
  if (!valid(id))
    throw Error("entity " + std::to_string(id.index) + ":" + std::to_string(id.generation) +
                " does not exist (destroyed or never created)");
  return *slots_[id.index].entity;
}

Entity& World::mutableEntity(EntityId id) { return const_cast<Entity&>(entity(id)); }

void World::destroyEntity(EntityId id) {
  checkUnlocked("destroyEntity");
  mutableEntity(id);  // validates
  Slot& slot = slots_[id.index];
  slot.entity.reset();
  ++slot.generation;
  freeSlots_.push_back(id.index);
}

std::vector<EntityId> World::entities() const {
  std::vector<EntityId> out;
  for (uint32_t i = 0; i < slots_.size(); ++i)
    if (slots_[i].entity) out.push_back({i, slots_[i].generation});
  return out;
}

void World::setVelocity(EntityId id, Vec2w v) {
  const int64_t limit = int64_t{kMaxMove} << 16;
  if (v.x < -limit || v.x > limit || v.y < -limit || v.y > limit)
    throw Error("velocity (" + std::to_string(v.x) + ", " + std::to_string(v.y) +
                ") / 65536 exceeds the largest move per frame, 2^30 units");
  mutableEntity(id).velocityQ16 = v;
}
void World::setAngularVelocity(EntityId id, int32_t a) { mutableEntity(id).angularVelocity = a; }
void World::setGravityEnabled(EntityId id, bool on) { mutableEntity(id).gravity = on; }
void World::setUserData(EntityId id, uint64_t value) { mutableEntity(id).userData = value; }

void World::setRules(Rules* rules) {
  checkUnlocked("setRules");
  rules_ = rules ? rules : &defaultRules_;
  // Pierceability is cached per region line; ask the new rules afresh.
  for (Slot& s : slots_)
    if (s.entity)
      for (Instance& inst : s.entity->instances)
        std::fill(inst.region.flags().begin(), inst.region.flags().end(), uint8_t{0});
}

Instance World::makeInstance(const Entity& e, MapPartId part, Vec2 position, Angle frame) const {
  Instance inst;
  inst.part = part;
  inst.position = position;
  inst.frame = frame;
  inst.rotation = rotationOf(frame);
  inst.idealQ30 = {int64_t{position.x} << 30, int64_t{position.y} << 30};
  const Convex turned = e.shape.rotated(static_cast<Angle>(e.angle + frame));
  inst.shape.assign(turned.vertices().begin(), turned.vertices().end());
  for (const Vec2 v : inst.shape)
    if (std::abs(int64_t{position.x} + v.x) > kCoordLimit || std::abs(int64_t{position.y} + v.y) > kCoordLimit)
      throw Error("instance at " + toString(position) + " would reach outside the coordinate range (vertex " +
                  toString(v) + ")");
  return inst;
}

bool World::isPierceable(EntityId id, Instance& inst, size_t k) {
  uint8_t& flag = inst.region.flags()[k];
  if (flag == 0) {
    const MapPart& part = mapPart(inst.part);
    const LineIndex index = inst.region.lines()[k];
    const Line& line = part.lines()[index];
    const LineRef ref{part.id(), index, line.tag, line.kind};
    bool pierce = line.kind == LineKind::Warp;
    callRules([&](Rules& r) { pierce = r.pierce(id, ref); });
    flag = pierce ? 2 : 1;
  }
  if (flag == 2 && !inst.blockedWarps.empty()) {
    const LineIndex index = inst.region.lines()[k];
    if (std::find(inst.blockedWarps.begin(), inst.blockedWarps.end(), index) != inst.blockedWarps.end())
      return false;
  }
  return flag == 2;
}

namespace {
Box shapeBox(const Instance& inst, Vec2w motion) {
  Box b{INT64_MAX, INT64_MAX, INT64_MIN, INT64_MIN};
  for (const Vec2 v : inst.shape) {
    const int64_t x = int64_t{inst.position.x} + v.x, y = int64_t{inst.position.y} + v.y;
    b.x0 = std::min({b.x0, x, x + motion.x});
    b.x1 = std::max({b.x1, x, x + motion.x});
    b.y0 = std::min({b.y0, y, y + motion.y});
    b.y1 = std::max({b.y1, y, y + motion.y});
  }
  return b;
}
}  // namespace

void World::coverMotion(Instance& inst, Vec2w motion, int64_t slack) {
  Box b = shapeBox(inst, motion);
  // One unit of margin: points on the box edge round into the next cell's range.
  b.x0 -= 1 + slack, b.y0 -= 1 + slack, b.x1 += 1 + slack, b.y1 += 1 + slack;
  const Grid& grid = mapPart(inst.part).grid();
  inst.region.update(grid, grid.cellsCovering(b, inst.region.rect()));
}

void World::rebase(Entity& e, size_t k, Vec2w* motion) {
  const Angle theta = e.instances[k].frame;
  std::rotate(e.instances.begin(), e.instances.begin() + static_cast<long>(k),
              e.instances.begin() + static_cast<long>(k) + 1);
  for (Instance& inst : e.instances) {
    inst.frame = static_cast<Angle>(inst.frame - theta);
    inst.rotation = rotationOf(inst.frame);
  }
  Instance& anchor = e.instances[0];
  anchor.idealQ30 = {int64_t{anchor.position.x} << 30, int64_t{anchor.position.y} << 30};
  e.angle = static_cast<Angle>(e.angle + theta);
  const Rotation r = rotationOf(theta);
  e.velocityQ16 = clampVelocityQ16(rotateWide(r, e.velocityQ16));
  e.subunitQ17 = rotateWide(r, e.subunitQ17);
  // Keep the carried remainder below one unit after rounding.
  e.subunitQ17.x = std::clamp<int64_t>(e.subunitQ17.x, 0, (1 << 17) - 1);
  e.subunitQ17.y = std::clamp<int64_t>(e.subunitQ17.y, 0, (1 << 17) - 1);
  if (motion) *motion = rotateWide(r, *motion);
}

void World::insert(EntityId id, MapPartId partId, Vec2 origin, Angle angle) {
  checkUnlocked("insert");
  Entity& e = mutableEntity(id);
  const MapPart& part = mapPart(partId);
  if (!part.initialized())
    throw Error("insert: map part " + std::to_string(partId) + " is not initialized");
  if (e.instanceIn(partId))
    throw Error("insert: entity already has an instance in map part " + std::to_string(partId));
  if (!inRange(origin)) throw Error("insert: origin " + toString(origin) + " is outside the coordinate range");
  const bool first = e.instances.empty();
  const Angle frame = first ? 0 : static_cast<Angle>(angle - e.angle);
  if (first) e.angle = angle;
  Instance inst;
  try {
    inst = makeInstance(e, partId, origin, frame);
  } catch (...) {
    if (first) e.angle = 0;
    throw;
  }
  coverMotion(inst, {});
  std::vector<Vec2> verts;
  for (const Vec2 v : inst.shape) verts.push_back({origin.x + v.x, origin.y + v.y});
  for (size_t k = 0; k < inst.region.lines().size(); ++k) {
    const LineIndex line = inst.region.lines()[k];
    if (!isPierceable(id, inst, k) && overlapsInterior(verts, part.segments()[line])) {
      if (first) e.angle = 0;
      const Segment s = part.segments()[line];
      throw Error("insert: the entity at " + toString(origin) + " in map part " + std::to_string(partId) +
                  " would overlap solid line " + std::to_string(line) + " " + toString(s.a) + "-" +
                  toString(s.b));
    }
  }
  if (!first) {
    // Follow the anchor from here on: the ideal position is where it is now.
    inst.idealQ30 = {int64_t{origin.x} << 30, int64_t{origin.y} << 30};
  }
  e.instances.push_back(std::move(inst));
  locked_ = true;
  updatePierceState(id, e, nullptr, nullptr);
  createOverlappedWarps(id, e);
  locked_ = false;
  if (pendingError_) std::rethrow_exception(std::exchange(pendingError_, nullptr));
}

void World::erase(EntityId id, MapPartId partId) {
  checkUnlocked("erase");
  Entity& e = mutableEntity(id);
  for (size_t i = 0; i < e.instances.size(); ++i)
    if (e.instances[i].part == partId) {
      locked_ = true;
      eraseInstance(id, e, i);
      locked_ = false;
      if (pendingError_) std::rethrow_exception(std::exchange(pendingError_, nullptr));
      return;
    }
  throw Error("erase: entity has no instance in map part " + std::to_string(partId));
}

bool World::rotate(EntityId id, Angle angle) {
  checkUnlocked("rotate");
  Entity& e = mutableEntity(id);
  const int64_t delta = static_cast<int32_t>(static_cast<Angle>(angle - e.angle));
  for (const Instance& inst : e.instances)  // refuse shapes that cannot turn, before moving anything
    (void)e.shape.rotated(static_cast<Angle>(angle + inst.frame));
  locked_ = true;
  const bool done = rotateBy(id, e, delta);
  locked_ = false;
  if (pendingError_) std::rethrow_exception(std::exchange(pendingError_, nullptr));
  return done;
}

size_t World::countOverlaps() const {
  size_t count = 0;
  for (uint32_t i = 0; i < slots_.size(); ++i) {
    const Entity* e = slots_[i].entity.get();
    if (!e) continue;
    const EntityId id{i, slots_[i].generation};
    for (const Instance& inst : e->instances) {
      const MapPart& part = mapPart(inst.part);
      std::vector<Vec2> verts;
      for (const Vec2 v : inst.shape) verts.push_back({inst.position.x + v.x, inst.position.y + v.y});
      for (LineIndex l = 0; l < part.lines().size(); ++l) {
        const Line& line = part.lines()[l];
        if (rules_->pierce(id, {part.id(), l, line.tag, line.kind})) continue;
        if (overlapsInterior(verts, part.segments()[l])) ++count;
      }
    }
  }
  return count;
}

SolveReport World::solve() {
  checkUnlocked("solve");
  struct Lock {
    bool& flag;
    explicit Lock(bool& f) : flag(f) { flag = true; }
    ~Lock() { flag = false; }
  } lock(locked_);
  report_ = {};
  report_.frame = ++frame_;
  for (uint32_t i = 0; i < slots_.size(); ++i) {
    Entity* e = slots_[i].entity.get();
    if (e && !e->instances.empty()) stepEntity({i, slots_[i].generation}, *e);
  }
  fireOverContacts();
  if (pendingError_) std::rethrow_exception(std::exchange(pendingError_, nullptr));
  return report_;
}

}  // namespace platon::physics
