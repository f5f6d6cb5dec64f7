// The physics world: map parts, entities, rules, and the frame step. An ordinary object: several
// worlds may live side by side (parallel headless runs), and nothing is shared between them.
#pragma once
#include <memory>
#include <vector>

#include "platon/physics/entity_view.h"
#include "platon/physics/map_part.h"
#include "platon/physics/rules.h"

namespace platon::physics {

struct WorldImpl;  // the solver's state (physics/src/world_impl.h)

// Sub-moves per entity per frame: each hit consumes one (the motion is then projected along the
// line); a warp crossing consumes one. Motion left after the last one is dropped for this frame.
inline constexpr int kMaxSubMoves = 8;

// What one solve() did, for tests, benchmarks and profiling.
struct SolveReport {
  uint64_t frame = 0;
  uint32_t subMoves = 0;
  uint32_t hits = 0;
  uint32_t pierceEvents = 0;     // begin + end
  uint32_t roundingRetries = 0;  // a rounded position failed its exact check and was pulled back
  uint32_t warpsCreated = 0;
  uint32_t instancesErased = 0;
  uint32_t copiesReplaced = 0;  // copies moved within two units to free them from a rounding snag
  uint32_t cornerReturns = 0;   // entities gone on over the faces round a vertex they went through
  uint32_t vertexHolds = 0;     // entities a walled vertex held on a face, as a wall would
  uint32_t warpsHeld = 0;       // warp edges no whole-unit step could reach: held like a wall for the frame
  uint32_t restsKept = 0;       // bodies at rest that nothing disturbed: their answer kept, no test
  uint32_t restMismatches = 0;  // RestMode::Checked: kept answers the test contradicted (always 0)
  // The frame's work: every line, platform line and body a move was tested against. A frame's time
  // grows with it (EntityView::work has each entity's share), so a caller can bound what it costs.
  uint64_t tested = 0;
};

// A line of a moving platform: solid, or one-way (solid from its left side).
struct PlatformLine {
  Segment segment;
  uint32_t tag = 0;
  LineKind kind = LineKind::Solid;
};

// A platform's lines on a face beside its own, where they reach over one of its part's warp edges:
// the same lines through the warp, in that part's coordinates (World::createPlatform).
struct PlatformCopyView {
  MapPartId part = 0;
  std::span<const PlatformLine> lines;
};

// A moving platform as callers see it: its lines where they are now.
struct PlatformView {
  MapPartId part = 0;
  Vec2 offset;  // how far it has moved since it was created, or since it last crossed a warp edge
  Vec2 motion;  // whole units per frame
  std::span<const PlatformLine> lines;
  Vec2 pivot;        // the point it turns about, where it is now
  Angle angle = 0;   // how far it has turned about the pivot (since the pivot was last changed)
  int32_t spin = 0;  // binary-angle units per frame, counter-clockwise
  // The latest solve()'s work for it: its lines placed and checked and the bodies they were checked
  // against (as EntityView::work counts an entity's), so a caller can bound what it costs.
  uint64_t work = 0;
  std::vector<PlatformCopyView> copies;  // on the faces beside it its lines reach (a renderer draws them)
};

// The largest turn a platform makes in a frame (1/16 of a turn), and the most a frame's turn may
// cost: sub-steps (which grow with the turn and the square root of the farthest end's distance
// from the pivot), and sub-steps times lines. A 4096-unit face's width turns at the largest spin
// in 130 sub-steps.
inline constexpr int32_t kMaxPlatformSpin = int32_t{1} << 28;
inline constexpr int64_t kMaxPlatformTurnSubSteps = 1024;
inline constexpr int64_t kMaxPlatformTurnLineSteps = int64_t{1} << 18;

// The live entities, in handle order: for (EntityId id : world.entities()). No allocation.
class EntityRange {
 public:
  class iterator {
   public:
    using value_type = EntityId;
    using difference_type = std::ptrdiff_t;
    iterator() = default;
    iterator(const WorldImpl* world, uint32_t slot) : world_(world), slot_(slot) {}
    EntityId operator*() const;
    iterator& operator++();
    iterator operator++(int) {
      iterator was = *this;
      ++*this;
      return was;
    }
    friend bool operator==(const iterator& a, const iterator& b) { return a.slot_ == b.slot_; }

   private:
    const WorldImpl* world_ = nullptr;
    uint32_t slot_ = 0;
  };
  explicit EntityRange(const WorldImpl& world) : world_(&world) {}
  iterator begin() const;
  iterator end() const;

 private:
  const WorldImpl* world_;
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
  EntityView entity(EntityId id) const;  // throws Error for a stale or unknown handle
  EntityRange entities() const;
  size_t entityCount() const;

  void setVelocity(EntityId id, Vec2w velocityQ16);
  // The motion below one unit an entity carries to its next frame (EntityView::subunit), for a copy
  // of a world that goes on exactly as the original (a hot reload); each part under one unit.
  void setSubunit(EntityId id, Vec2w subunitQ17);
  void setAngularVelocity(EntityId id, int32_t anglePerFrame);
  void setGravityEnabled(EntityId id, bool enabled);
  void setUserData(EntityId id, uint64_t value);
  // Which entities it collides with or reports overlaps with (see EntityFilter). Refused (Error) if
  // the entity would then overlap one it is solid to.
  void setFilter(EntityId id, const EntityFilter& filter);

  // Places an instance of the entity in a part (the seed's MapPart::insert). The first instance
  // sets the entity's position and angle; later ones follow it. Throws if the part is not
  // initialized, already holds the entity, a solid line or a body it is solid to would overlap the
  // instance, or (on a face: a part whose warps close into a loop) its middle lies off the face by
  // more than its size.
  void insert(EntityId id, MapPartId part, Vec2 origin, Angle angle);
  void erase(EntityId id, MapPartId part);
  // Turns the entity towards `angle` (the short way round) until a solid line stops it; returns
  // whether it got there. A stop calls Rules::touchContact.
  bool rotate(EntityId id, Angle angle);

  // Moving platforms: lines of one map part that move together by whole units, once a frame before
  // the entities step. A platform pushes every entity in its way (as a slide of the entity's own,
  // so walls stop it), carries the entities standing on it and those snug in a pocket of its own
  // lines, and stops where a push is impossible (Rules::crushed). It passes through the part's fixed lines and other
  // platforms. On a face of a solid (a part whose warp lines close into a loop: MapPart::faceLoop), a platform crosses
  // the face's edges: where its lines come within reach of a warp edge they are also on the face beyond (a copy,
  // PlatformView::copies, placed through the warp and moved with it, a whole unit at a time after its exact place, and
  // turned with it about its pivot placed there; one copy at most, across the edge its lines come furthest over). It
  // meets each body in the first of its parts the body is in (its own, then its copy's), and pushes, carries and is
  // stopped by it there as on one face; once every line is beyond one edge, the platform belongs to the face beyond
  // (its part, lines, pivot and motion turned into that part's frame, exactly; its offset counted from there; its copy
  // over another edge of that face made in the same frame where it meets no body, else the next frame). A copy
  // made over a body there (the lines came over that edge with no copy: beside a vertex, where it has one copy, or the
  // frame it crossed) treats that body as one left in a copy's line (cleared off it, or passed through); a platform is
  // stopped only by a body it meets (Rules::crushed). On a part that is not a face of a solid a platform stays in its
  // part. docs/physics.md, "Platforms across edges", says more. Up to 65,536 lines a platform and 16,384 platforms;
  // lines must be Solid or OneWay.
  PlatformId createPlatform(MapPartId part, std::span<const PlatformLine> lines);
  void destroyPlatform(PlatformId id);
  void setPlatformMotion(PlatformId id, Vec2 perFrame);
  // Turns the platform about `pivot` (the part's coordinates; the pivot moves with the platform) by
  // `anglePerFrame` binary-angle units a frame (up to kMaxPlatformSpin), after its motion: gears,
  // seesaws, turning bridges. Its lines at angle a are its lines as created turned by a about the
  // pivot, each end rounded to the nearest unit (the CORDIC rotation entities use): angles add
  // exactly, so a full turn comes back exactly and quarter turns are exact. Each frame's turn goes
  // in sub-steps in which no point strays half a unit from its chord; what a sub-step's lines sweep
  // over is pushed along (a slide of the entity's own), riders are carried as if fixed to it, and
  // where room cannot be made it stops for the frame and calls Rules::crushed. A new pivot for a
  // turned platform takes its lines where they are as its lines as created (nothing jumps). A turn
  // that would cost a frame more than kMaxPlatformTurnSubSteps sub-steps or kMaxPlatformTurnLineSteps
  // sub-steps times lines is refused (Error): turn it slower, or about a nearer point.
  void setPlatformSpin(PlatformId id, Vec2 pivot, int32_t anglePerFrame);
  PlatformView platform(PlatformId id) const;
  // The live platforms, oldest slot first (what a renderer draws each frame).
  std::vector<PlatformId> platforms() const;

  // nullptr restores the default rules. The rules object must outlive its use by solve().
  void setRules(Rules* rules);
  // Asks Rules::pierce again, for every entity, about the lines tagged `tag` in every part: call it
  // when a switch changes what pierce answers (a door opens, a bridge appears). The answers are
  // otherwise kept while a line stays near an instance. A line that becomes solid while an
  // instance overlaps it stays passable for that instance until it is clear of it (its begin/end
  // pair completes, and nothing is ever inside a solid line); then it holds.
  void refreshPierce(uint32_t tag);

  // Rest that costs nothing. A body at rest (its velocity and its fraction of a unit zero, pressed
  // into what holds it) that nothing disturbs keeps its answer without testing again: it is looked
  // at again once something that could move it changes (an entity moving, pushed, inserted or
  // erased near it; its velocity, spin, gravity switch or filter set; its part's gravity; a
  // platform of its part moving; the rules replaced or refreshPierce), so a switch, a platform or
  // a script acts on it in the same frame as before, and states are bit for bit those of a world
  // that tests every body every frame. Kept is the default; Tested tests every body every frame;
  // Checked keeps and tests, and counts in SolveReport::restMismatches every kept answer the test
  // contradicts (the proof, in tests).
  enum class RestMode : uint8_t { Kept, Tested, Checked };
  void setRestMode(RestMode mode);

  // Advances one frame. Deterministic: the same calls give bit-identical states.
  SolveReport solve();
  uint64_t frame() const;
  uint64_t stateHash() const;

  // Number of (instance, line) pairs where the instance overlaps the interior of a line that is
  // solid for it; the invariant says always 0. One-way lines, and lines kept passable until an
  // instance is clear of them (refreshPierce), do not count; a platform's lines count in the part
  // where the platform meets the body (createPlatform). For tests; what it costs is what the
  // bodies meet (never the map's size): `work`, if given, is set to the pairs and index nodes it
  // looked at, for a caller that charges it.
  size_t countOverlaps(size_t* work = nullptr) const;

 private:
  std::unique_ptr<WorldImpl> impl_;
};

}  // namespace platon::physics
