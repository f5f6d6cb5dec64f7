// Entities and their instances as the solver keeps them. Callers see them through EntityView and
// InstanceView (platon/physics/entity_view.h); everything here is the solver's bookkeeping.
#pragma once
#include <algorithm>
#include <vector>

#include "platon/physics/angle.h"
#include "platon/physics/convex.h"
#include "platon/physics/ids.h"
#include "platon/physics/rules.h"
#include "region.h"

namespace platon::physics {

// One copy of an entity in one map part. While an entity straddles a warp edge it has an instance
// on each side; instance 0 (the anchor) defines the entity's frame.
struct Instance {
  MapPartId part = 0;
  Vec2 position;      // the entity origin in the part's coordinates
  Angle frame = 0;    // rotation from the entity frame into this part (0 for the anchor)
  Rotation rotation;  // rotationOf(frame)
  // Where a non-anchor instance should be, in Q30 (2^30 per unit): the anchor's position mapped
  // through the warps. Each sub-move aims at it, so rounding never accumulates into drift.
  Vec2w idealQ30;
  std::vector<Vec2> shape;  // vertices relative to position: the entity shape turned by angle + frame
  Vec2 low, high;           // the shape's bounding box, relative to position (setShape keeps it)
  // A point inside the shape, relative to position: the mean of the created shape's vertices,
  // turned with it (turnedCentre). Which face an instance is on is decided by this point, not by
  // the origin, which a shape need not contain.
  Vec2 centre;
  std::vector<LineIndex> overlapping;   // pierceable lines whose interior this instance overlaps
  std::vector<LineIndex> blockedWarps;  // warps that could not be crossed this frame (act solid)
  Region region;
};

// A point inside the entity's shape turned by `turn`: the mean of the created (unturned) shape's
// vertices, turned and rounded. Turning the mean, not taking the mean of the turned vertices,
// keeps it the same point of the body in every copy: a turned shape is a new convex hull of
// rounded points, which can lose a vertex that rounding put in line with its neighbours (a copy's
// mean then moved by a tenth of the body's size from its anchor's, and the two could both sit
// off their faces while straddling one edge).
inline Vec2 turnedCentre(const Convex& shape, Angle turn) {
  const auto vertices = shape.vertices();
  const auto n = static_cast<i128>(vertices.size());
  i128 sx = 0, sy = 0;
  for (const Vec2 v : vertices) sx += v.x, sy += v.y;
  const Vec2w meanQ16{static_cast<int64_t>(roundDiv(sx << 16, n)), static_cast<int64_t>(roundDiv(sy << 16, n))};
  const Vec2w turned = turn == 0 ? meanQ16 : rotateWide(rotationOf(turn), meanQ16);
  return {static_cast<int32_t>(roundDiv(turned.x, i128{1} << 16)),
          static_cast<int32_t>(roundDiv(turned.y, i128{1} << 16))};
}

// Sets an instance's shape (the entity's turned by `turn`, its angle and the instance's frame)
// and its bounding box and centre.
inline void setShape(Instance& inst, std::vector<Vec2> shape, const Convex& created, Angle turn) {
  inst.shape = std::move(shape);
  inst.low = inst.high = inst.shape.front();
  for (const Vec2 v : inst.shape) {
    inst.low = {std::min(inst.low.x, v.x), std::min(inst.low.y, v.y)};
    inst.high = {std::max(inst.high.x, v.x), std::max(inst.high.y, v.y)};
  }
  inst.centre = turnedCentre(created, turn);
}

// The instance's centre in its part's coordinates (see Instance::centre).
inline Vec2 centreOf(const Instance& inst) {
  return {inst.position.x + inst.centre.x, inst.position.y + inst.centre.y};
}

// The box swept by the instance moving by m: sweptBox of its vertices, from the box it keeps.
inline Box sweptBox(const Instance& inst, Vec2w m) {
  return {int64_t{inst.position.x} + inst.low.x + std::min<int64_t>(m.x, 0),
          int64_t{inst.position.y} + inst.low.y + std::min<int64_t>(m.y, 0),
          int64_t{inst.position.x} + inst.high.x + std::max<int64_t>(m.x, 0),
          int64_t{inst.position.y} + inst.high.y + std::max<int64_t>(m.y, 0)};
}

// Whether the instance's bounding box meets the closed box [x0, x1] x [y0, y1].
template <class B>
inline bool boxMeets(const Instance& inst, const B& box) {
  return int64_t{inst.position.x} + inst.low.x <= box.x1 && int64_t{inst.position.x} + inst.high.x >= box.x0 &&
         int64_t{inst.position.y} + inst.low.y <= box.y1 && int64_t{inst.position.y} + inst.high.y >= box.y0;
}

// Two instances joined through a warp edge; the pair lives while the entity straddles the edge.
struct WarpLink {
  MapPartId fromPart = 0;
  LineIndex warpLine = 0;  // in fromPart
  MapPartId toPart = 0;
  // Each side's contact with its edge: 0 apart, 1 touching, 2 overlapping.
  uint8_t fromState = 0;
  uint8_t toState = 0;
};

// The instance's vertices in its part's coordinates.
inline void worldVertices(const Instance& inst, std::vector<Vec2>& out) {
  const size_t n = inst.shape.size();
  out.resize(n);
  const Vec2* shape = inst.shape.data();  // read once: `out` could alias them as far as the compiler knows
  Vec2* to = out.data();
  const Vec2 at = inst.position;
  for (size_t i = 0; i < n; ++i) to[i] = {at.x + shape[i].x, at.y + shape[i].y};
}
inline std::vector<Vec2> worldVertices(const Instance& inst) {
  std::vector<Vec2> out;
  worldVertices(inst, out);
  return out;
}

struct Entity {
  Entity(EntityId handle, Convex s) : id(handle), shape(std::move(s)) {}

  EntityId id;
  Convex shape;                 // as created, unrotated
  Angle angle = 0;              // rotation of the shape in the entity (anchor) frame
  Vec2w velocityQ16;            // 1/65536 units per frame, entity frame
  Vec2w subunitQ17;             // motion below one unit (1/131072 units), carried to the next frame
  int32_t angularVelocity = 0;  // binary-angle units per frame
  bool gravity = true;          // the anchor part's gravity applies
  uint64_t userData = 0;
  EntityFilter filter;
  std::vector<Instance> instances;
  std::vector<WarpLink> links;
  std::vector<Contact> contacts;  // solid contacts of the latest solve(), in the order they happened
  // The latest solve() kept its rest: its contacts are restContacts, read there (contactsOf), not
  // copied into `contacts` every frame.
  bool contactsAreRest = false;
  uint32_t work = 0;          // lines and bodies its moves were tested against in the latest solve()
  uint64_t steppedFrame = 0;  // the world frame it last stepped in (or began to)
  // Waiting, before its own move, for the entities that hold it to step first (step.cpp's
  // stepHoldersFirst): to a move that meets it meanwhile it has not stepped yet, and it takes its
  // step then, from the state it had when the frame's step began (kept here).
  struct Awaiting {
    bool now = false;        // waiting for its holders
    bool takenOver = false;  // a move met it meanwhile and it stepped there: its own step is over
    uint64_t frame = 0;      // the frame it last waited in (it waits once a frame)
    Vec2w velocityQ16, subunitQ17;
  } awaiting;
  // At rest and undisturbed (world.h, "rest costs nothing"): its rest test's answer is known until
  // something that could change it happens, so the frame keeps that answer instead of asking again.
  // What it depends on: its own state (the calls that set it clear this), every entity and line
  // near it (an entity moving near it clears this, world.cpp's wake), its anchor part's gravity and
  // the platforms of its parts (compared below), the rules' answers (setRules, refreshPierce).
  bool resting = false;
  Vec2w restGravityQ16;               // the anchor part's gravity when the answer was found
  uint64_t restPlatformEpoch = 0;     // the platforms of its parts had moved this often
  std::vector<Contact> restContacts;  // the contacts that held it
  std::vector<uint32_t> restHolders;  // the slots of the entities among them it is pressed onto

  const std::vector<Contact>& contactsOf() const { return contactsAreRest ? restContacts : contacts; }

  Instance* instanceIn(MapPartId part) {
    for (Instance& i : instances)
      if (i.part == part) return &i;
    return nullptr;
  }
  const Instance* instanceIn(MapPartId part) const { return const_cast<Entity*>(this)->instanceIn(part); }
};

}  // namespace platon::physics
