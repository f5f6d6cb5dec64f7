// World: ownership, handles and the checked public API. The frame step lives in step.cpp.
#include "platon/physics/world.h"

#include <algorithm>
#include <array>
#include <map>
#include <span>
#include <utility>

#include "faces.h"
#include "world_impl.h"

namespace platon::physics {

// --- WorldImpl: lookups and checks ---

void WorldImpl::throwNoPart(MapPartId id) { throw Error("map part " + std::to_string(id) + " does not exist"); }

const Entity& WorldImpl::entity(EntityId id) const {
  if (id.index >= slots.size() || !slots[id.index].entity || slots[id.index].generation != id.generation)
    throw Error("entity " + std::to_string(id.index) + ":" + std::to_string(id.generation) +
                " does not exist (destroyed or never created)");
  return *slots[id.index].entity;
}

Entity& WorldImpl::entity(EntityId id) { return const_cast<Entity&>(std::as_const(*this).entity(id)); }

void WorldImpl::checkUnlocked(const char* what) const {
  if (locked) throw Error(std::string(what) + " is not allowed inside a contact callback (during solve)");
}

// Warp targets are checked once a part is initialized and the world is next used, so a level may
// create and initialize its parts in any order.
void WorldImpl::checkWarpTargets() {
  for (size_t k = 0; k < uncheckedWarps.size();) {
    const MapPart& p = *uncheckedWarps[k];
    if (!p.initialized()) {
      ++k;
      continue;
    }
    for (LineIndex i = 0; i < p.lines().size(); ++i) {
      if (p.lines()[i].kind != LineKind::Warp) continue;
      const MapPartId target = p.warps()[p.lines()[i].warp].target;
      if (!findPart(target))
        throw Error("map part " + std::to_string(p.id()) + " warp " + std::to_string(i) + ": target map part " +
                    std::to_string(target) + " does not exist");
    }
    uncheckedWarps.erase(uncheckedWarps.begin() + static_cast<long>(k));
  }
}

// --- World ---

World::World() : impl_(std::make_unique<WorldImpl>()) {}
World::~World() = default;

MapPart& World::createMapPart(MapPartId id) {
  impl_->checkUnlocked("createMapPart");
  auto& index = impl_->partIndex;
  auto it = std::lower_bound(index.begin(), index.end(), id, [](const MapPart* p, MapPartId v) { return p->id() < v; });
  if (it != index.end() && (*it)->id() == id) throw Error("map part " + std::to_string(id) + " already exists");
  impl_->parts.push_back(MapPart(id));
  MapPart* created = &impl_->parts.back();
  index.insert(it, created);
  if (id < WorldImpl::kPartsById) {
    if (impl_->partById.size() <= id) impl_->partById.resize(id + 1, nullptr);
    impl_->partById[id] = created;
  }
  impl_->uncheckedWarps.push_back(created);
  return *created;
}

const MapPart* World::findMapPart(MapPartId id) const { return impl_->findPart(id); }
const MapPart& World::mapPart(MapPartId id) const { return impl_->part(id); }
MapPart& World::mapPart(MapPartId id) { return const_cast<MapPart&>(impl_->part(id)); }

EntityId World::createEntity(const Convex& shape) {
  impl_->checkUnlocked("createEntity");
  auto& slots = impl_->slots;
  uint32_t index;
  if (!impl_->freeSlots.empty()) {
    index = impl_->freeSlots.back();
    impl_->freeSlots.pop_back();
  } else {
    index = static_cast<uint32_t>(slots.size());
    slots.push_back({});
  }
  const EntityId id{index, slots[index].generation};
  slots[index].entity = std::make_unique<Entity>(id, shape);
  ++impl_->liveEntities;
  return id;
}

bool World::valid(EntityId id) const {
  const auto& slots = impl_->slots;
  return id.index < slots.size() && slots[id.index].entity && slots[id.index].generation == id.generation;
}

EntityView World::entity(EntityId id) const { return EntityView(impl_->entity(id)); }

void World::destroyEntity(EntityId id) {
  impl_->checkUnlocked("destroyEntity");
  Entity& e = impl_->entity(id);  // validates
  {
    CallbackScope scope(*impl_);
    for (const Instance& inst : e.instances) impl_->endEntityOverlaps(e, inst.part);
    scope.finish();
  }
  if (impl_->restingCount > 0) impl_->wakeAround(e);  // what rested on it
  impl_->wake(e);
  impl_->entityIndex.remove(e);
  WorldImpl::Slot& slot = impl_->slots[id.index];
  slot.entity.reset();
  ++slot.generation;
  impl_->freeSlots.push_back(id.index);
  --impl_->liveEntities;
}

size_t World::entityCount() const { return impl_->liveEntities; }
EntityRange World::entities() const { return EntityRange(*impl_); }

void World::setVelocity(EntityId id, Vec2w v) {
  const int64_t limit = int64_t{kMaxMove} << 16;
  if (v.x < -limit || v.x > limit || v.y < -limit || v.y > limit)
    throw Error("velocity (" + std::to_string(v.x) + ", " + std::to_string(v.y) +
                ") / 65536 exceeds the largest move per frame, 2^30 units");
  Entity& e = impl_->entity(id);
  e.velocityQ16 = v;
  impl_->wake(e);
}
void World::setSubunit(EntityId id, Vec2w s) {
  constexpr int64_t kUnitQ17 = 131072;
  if (s.x <= -kUnitQ17 || s.x >= kUnitQ17 || s.y <= -kUnitQ17 || s.y >= kUnitQ17)
    throw Error("subunit (" + std::to_string(s.x) + ", " + std::to_string(s.y) + ") / 131072 is a unit or more");
  Entity& e = impl_->entity(id);
  e.subunitQ17 = s;
  impl_->wake(e);
}
void World::setAngularVelocity(EntityId id, int32_t a) {
  Entity& e = impl_->entity(id);
  e.angularVelocity = a;
  impl_->wake(e);
}
void World::setGravityEnabled(EntityId id, bool on) {
  Entity& e = impl_->entity(id);
  e.gravity = on;
  impl_->wake(e);
}
void World::setUserData(EntityId id, uint64_t value) { impl_->entity(id).userData = value; }

void World::setFilter(EntityId id, const EntityFilter& filter) {
  WorldImpl& w = *impl_;
  w.checkUnlocked("setFilter");
  Entity& e = w.entity(id);
  const EntityFilter was = e.filter;
  e.filter = filter;
  for (Instance& inst : e.instances)
    if (const std::optional<EntityId> other = w.entityOverlap(e, inst, worldVertices(inst))) {
      e.filter = was;
      throw Error("setFilter: entity " + std::to_string(id.index) + " would overlap entity " +
                  std::to_string(other->index) + ", which it would be solid to, in map part " +
                  std::to_string(inst.part));
    }
  CallbackScope scope(w);
  for (const Instance& inst : e.instances)
    w.endEntityOverlaps(e, inst.part);  // begin again below if they still overlap
  w.reindex(e);
  w.updatePierceState(e, {});
  scope.finish();
}

void World::setRules(Rules* rules) {
  impl_->checkUnlocked("setRules");
  impl_->rules = rules ? rules : &impl_->defaultRules;
  impl_->wakeAll();  // new rules may answer otherwise
  // Pierceability is cached per region line; ask the new rules afresh.
  for (WorldImpl::Slot& s : impl_->slots)
    if (s.entity)
      for (Instance& inst : s.entity->instances)
        std::fill(inst.region.flags().begin(), inst.region.flags().end(), uint8_t{0});
}

void World::refreshPierce(uint32_t tag) {
  impl_->checkUnlocked("refreshPierce");
  impl_->wakeAll();  // a line it rests on may have opened
  for (WorldImpl::Slot& slot : impl_->slots) {
    if (!slot.entity) continue;
    for (Instance& inst : slot.entity->instances) {
      const MapPart& part = impl_->part(inst.part);
      const auto lines = inst.region.lines();
      for (size_t k = 0; k < lines.size(); ++k)
        if (part.lines()[lines[k]].tag == tag) inst.region.flags()[k] = 0;
    }
  }
}

namespace {

// On a face (a part whose warp edges close into a loop) a body's middle is on the face, or over an
// edge by no more than the body's reach and the rounding two copies of it differ by (as while it
// crosses one). Farther out it would be taken for a body gone through a vertex and put back by a
// corner on its first step, hundreds of units from where it was put: refused instead.
void checkOnFace(const MapPart& part, MapPartId partId, const Instance& inst, Vec2 origin) {
  if (part.faceLoop().empty()) return;
  const Vec2 middle = centreOf(inst);
  if (insideFace(part, middle)) return;
  int64_t reach2 = 0;
  for (const Vec2 v : inst.shape) {
    const Vec2w d{int64_t{v.x} - inst.centre.x, int64_t{v.y} - inst.centre.y};
    reach2 = std::max(reach2, d.x * d.x + d.y * d.y);
  }
  const auto reach = static_cast<int64_t>(isqrt(static_cast<u128>(reach2))) + 1;
  constexpr int64_t kRounding = 6;  // insideFace's 4 units, and 2 for the middle's own rounding
  const int64_t out = unitsOutside(part, middle);
  if (out <= reach + kRounding) return;
  throw Error("insert: the entity at " + toString(origin) + " in map part " + std::to_string(partId) +
              " has its middle " + toString(middle) + " " + std::to_string(out) +
              " units off the face, farther than its size (" + std::to_string(reach) +
              "): a body's middle goes on its face, or over an edge by at most its size");
}

}  // namespace

void World::insert(EntityId id, MapPartId partId, Vec2 origin, Angle angle) {
  WorldImpl& w = *impl_;
  w.checkUnlocked("insert");
  Entity& e = w.entity(id);
  const MapPart& part = w.part(partId);
  if (!part.initialized()) throw Error("insert: map part " + std::to_string(partId) + " is not initialized");
  w.checkWarpTargets();
  if (e.instanceIn(partId)) throw Error("insert: entity already has an instance in map part " + std::to_string(partId));
  if (!inRange(origin)) throw Error("insert: origin " + toString(origin) + " is outside the coordinate range");
  const bool first = e.instances.empty();
  const Angle frame = first ? 0 : static_cast<Angle>(angle - e.angle);
  const Angle angleBefore = e.angle;
  if (first) e.angle = angle;
  Instance inst;
  try {
    inst = w.makeInstance(e, partId, origin, frame);
    w.coverMotion(inst, {});
    const std::vector<Vec2> verts = worldVertices(inst);
    if (const std::optional<LineIndex> line = w.solidOverlap(e, inst, verts)) {
      const Segment s = w.segmentOf(part, *line);
      throw Error("insert: the entity at " + toString(origin) + " in map part " + std::to_string(partId) +
                  " would overlap solid line " + std::to_string(*line) + " " + toString(s.a) + "-" + toString(s.b));
    }
    if (const std::optional<EntityId> other = w.entityOverlap(e, inst, verts))
      throw Error("insert: the entity at " + toString(origin) + " in map part " + std::to_string(partId) +
                  " would overlap entity " + std::to_string(other->index) + ", which it is solid to");
    checkOnFace(part, partId, inst, origin);
  } catch (...) {
    e.angle = angleBefore;
    throw;
  }
  e.instances.push_back(std::move(inst));
  w.reindex(e);
  CallbackScope scope(w);
  w.updatePierceState(e, {});
  w.createOverlappedWarps(e);
  w.reindex(e);
  scope.finish();
}

void World::erase(EntityId id, MapPartId partId) {
  WorldImpl& w = *impl_;
  w.checkUnlocked("erase");
  Entity& e = w.entity(id);
  for (size_t i = 0; i < e.instances.size(); ++i)
    if (e.instances[i].part == partId) {
      CallbackScope scope(w);
      std::vector<Vec2w> noNormals;
      Move move{e, {}, noNormals, {}, {}};
      w.eraseInstance(move, i);
      w.reindex(e);
      scope.finish();
      return;
    }
  throw Error("erase: entity has no instance in map part " + std::to_string(partId));
}

bool World::rotate(EntityId id, Angle angle) {
  WorldImpl& w = *impl_;
  w.checkUnlocked("rotate");
  Entity& e = w.entity(id);
  const int64_t delta = static_cast<int32_t>(static_cast<Angle>(angle - e.angle));
  for (const Instance& inst : e.instances)  // refuse shapes that cannot turn, before moving anything
    (void)e.shape.rotated(static_cast<Angle>(angle + inst.frame));
  CallbackScope scope(w);
  const bool done = w.rotateBy(e, delta);
  scope.finish();
  return done;
}

// A body's step before any test (gravity, its contacts, whether it rests) costs about as much as
// this many tests (measured on 10,000 bodies at rest): EntityView::work counts it too.
constexpr uint32_t kBodyStepWork = 16;

void World::setRestMode(RestMode mode) {
  impl_->restCache = mode != RestMode::Tested;
  impl_->restCheck = mode == RestMode::Checked;
  if (!impl_->restCache) impl_->wakeAll();
}

void WorldImpl::stepInFrame(Entity& e) {
  e.steppedFrame = frame;
  e.contacts.clear();
  e.contactsAreRest = false;
  e.work = 0;
  if (e.instances.empty()) return;
  e.work = kBodyStepWork;
  stepEntity(e);
}

SolveReport World::solve() {
  WorldImpl& w = *impl_;
  w.checkUnlocked("solve");
  w.checkWarpTargets();
  CallbackScope scope(w);
  w.report = {};
  w.report.frame = ++w.frame;
  w.steppingEntities = false;
  w.movePlatforms();
  w.steppingEntities = true;
  for (WorldImpl::Slot& slot : w.slots) {
    Entity* e = slot.entity.get();
    if (e && e->steppedFrame != w.frame) w.stepInFrame(*e);
  }
  w.steppingEntities = false;
  w.fireOverContacts();
  scope.finish();
  return w.report;
}

uint64_t World::frame() const { return impl_->frame; }

// --- EntityRange ---

EntityId EntityRange::iterator::operator*() const { return world_->slots[slot_].entity->id; }

EntityRange::iterator& EntityRange::iterator::operator++() {
  const auto& slots = world_->slots;
  do ++slot_;
  while (slot_ < slots.size() && !slots[slot_].entity);
  return *this;
}

EntityRange::iterator EntityRange::begin() const {
  iterator it(world_, 0);
  if (!world_->slots.empty() && !world_->slots[0].entity) ++it;
  return it;
}

EntityRange::iterator EntityRange::end() const { return iterator(world_, static_cast<uint32_t>(world_->slots.size())); }

}  // namespace platon::physics
