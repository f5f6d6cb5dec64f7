// The physics world: map parts, entities, rules, and the frame step. An ordinary object: several
// worlds may live side by side (parallel headless runs), and nothing is shared between them.
#pragma once
#include <deque>
#include <exception>
#include <memory>
#include <vector>

#include "platon/physics/entity.h"
#include "platon/physics/map_part.h"
#include "platon/physics/rules.h"

namespace platon::physics {

// Sub-moves per entity per frame: each hit consumes one (the motion is then projected along the
// line); a warp crossing consumes one. Motion left after the last one is dropped for this frame.
inline constexpr int kMaxSubMoves = 8;

struct SolveReport {
  uint64_t frame = 0;
  uint32_t subMoves = 0;
  uint32_t hits = 0;
  uint32_t pierceEvents = 0;   // begin + end
  uint32_t roundingRetries = 0;  // a rounded position failed its exact check and was pulled back
  uint32_t warpsCreated = 0;
  uint32_t instancesErased = 0;
  uint32_t copiesReplaced = 0;  // copies moved within two units to free them from a rounding snag
};

class World {
 public:
  World();
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Map parts. Ids are the caller's; a repeated id throws.
  MapPart& createMapPart(MapPartId id);
  MapPart& mapPart(MapPartId id);
  const MapPart& mapPart(MapPartId id) const;
  const MapPart* findMapPart(MapPartId id) const;

  // Entities exist outside any map part until inserted.
  EntityId createEntity(const Convex& shape);
  void destroyEntity(EntityId id);
  bool valid(EntityId id) const;
  const Entity& entity(EntityId id) const;
  std::vector<EntityId> entities() const;

  void setVelocity(EntityId id, Vec2w velocityQ16);
  void setAngularVelocity(EntityId id, int32_t anglePerFrame);
  void setGravityEnabled(EntityId id, bool enabled);
  void setUserData(EntityId id, uint64_t value);

  // Places an instance of the entity in a part (the seed's MapPart::insert). The first instance
  // sets the entity's position and angle; later ones follow it. Throws if the part is not
  // initialized, already holds the entity, or a solid line would overlap the instance.
  void insert(EntityId id, MapPartId part, Vec2 origin, Angle angle);
  void erase(EntityId id, MapPartId part);
  // Turns the entity towards `angle` (the short way round) until a solid line stops it; returns
  // whether it got there. A stop calls Rules::touchContact.
  bool rotate(EntityId id, Angle angle);

  // nullptr restores the default rules. The rules object must outlive its use by solve().
  void setRules(Rules* rules);

  // Advances one frame. Deterministic: the same calls give bit-identical states.
  SolveReport solve();
  uint64_t frame() const { return frame_; }
  uint64_t stateHash() const;

  // Number of (instance, solid line) pairs that overlap; the invariant says always 0. For tests.
  size_t countOverlaps() const;

 private:
  struct Slot {
    std::unique_ptr<Entity> entity;
    uint32_t generation = 0;
  };
  struct Move;  // one sub-move in progress (world_slide.cpp)

  Entity& mutableEntity(EntityId id);
  void checkUnlocked(const char* what) const;

  // world.cpp
  Instance makeInstance(const Entity& e, MapPartId part, Vec2 position, Angle frame) const;
  bool isPierceable(EntityId id, Instance& inst, size_t regionIndex);
  // Makes the instance's region hold every line near its shape moved by anything from 0 to `motion`,
  // and within `slack` more units around that.
  void coverMotion(Instance& inst, Vec2w motion, int64_t slack = 0);
  void rebase(Entity& e, size_t newAnchor, Vec2w* motion);
  // world_slide.cpp
  void stepEntity(EntityId id, Entity& e);
  void slide(EntityId id, Entity& e, Vec2w motion);
  Fraction firstBlock(EntityId id, Instance& inst, const std::vector<Vec2>& verts, Vec2w step);
  bool liftCopy(EntityId id, Instance& copy, Vec2w floorNormal, Vec2w move);
  bool rotateBy(EntityId id, Entity& e, int64_t delta);
  // world_contacts.cpp
  bool createWarpInstance(EntityId id, Entity& e, size_t from, LineIndex warpLine, Vec2w fromQ30, Vec2w motion);
  void createOverlappedWarps(EntityId id, Entity& e);
  // Moves `inst` to the free whole-unit position within two units of `targetQ30` (touching
  // `mustTouch` if given) that lets it travel furthest along `probe`, nearest first among equals.
  bool placeNear(EntityId id, Instance& inst, Vec2w targetQ30, const Segment* mustTouch, Vec2w probe);
  void updatePierceState(EntityId id, Entity& e, const std::vector<std::vector<Vec2>>* startVerts,
                         const std::vector<Vec2w>* steps, const std::vector<uint8_t>* pierceNear = nullptr);
  void updateLinks(EntityId id, Entity& e, Vec2w* motion, std::vector<Vec2w>* normals);
  void eraseInstance(EntityId id, Entity& e, size_t index, Vec2w* motion = nullptr,
                     std::vector<Vec2w>* normals = nullptr);
  void fireOverContacts();
  // Runs a rules callback; an exception is kept for solve() to rethrow once the frame is whole.
  template <class F>
  void callRules(F&& f) {
    try {
      f(*rules_);
    } catch (...) {
      if (!pendingError_) pendingError_ = std::current_exception();
    }
  }
  Contact makeContact(EntityId id, const Instance& inst, LineIndex line, Fraction t, Vec2w normal,
                      ContactPoints points) const;

  std::deque<MapPart> parts_;  // stable addresses
  std::vector<MapPart*> partIndex_;  // sorted by id
  std::vector<Slot> slots_;
  std::vector<uint32_t> freeSlots_;
  Rules defaultRules_;
  Rules* rules_ = &defaultRules_;
  uint64_t frame_ = 0;
  bool locked_ = false;
  std::exception_ptr pendingError_;
  SolveReport report_;
  // Per-frame buffers, kept to avoid allocating on every step (solve is not reentrant).
  struct Scratch {
    std::vector<std::vector<Vec2>> verts;
    std::vector<Vec2w> moves, steps, normals;
    std::vector<uint8_t> pierceNear;
    std::vector<Vec2> now;
  } scratch_;
};

}  // namespace platon::physics
