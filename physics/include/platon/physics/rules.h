// Rules: what happens on contact. The world asks them; it never asks a global.
//
// Callbacks run inside World::solve at a consistent state. They may read the world and change an
// entity's velocity; structural changes (create, destroy, insert, erase, rules) throw Error there.
// A callback may throw (a Lua binding turns a script error into a C++ exception): the world
// finishes the frame with default responses, stays consistent, and rethrows the first error from
// solve().
#pragma once
#include "platon/physics/fraction.h"
#include "platon/physics/ids.h"
#include "platon/physics/map_part.h"
#include "platon/physics/sweep.h"

namespace platon::physics {

inline constexpr LineIndex kWorldBoundLine = UINT32_MAX;  // the edge of the coordinate range
inline constexpr LineIndex kNoLine = UINT32_MAX - 1;      // a contact with another entity

struct LineRef {
  MapPartId part = 0;
  LineIndex index = 0;  // kWorldBoundLine for the world's edge; for a platform's line, see below
  uint32_t tag = 0;
  LineKind kind = LineKind::Solid;
  PlatformId platform;  // set for a moving platform's line: then `index` is its index in the platform
};

struct Contact {
  EntityId entity;
  MapPartId part = 0;    // the map part of the instance that touched
  LineRef line;          // line.index == kNoLine for a contact with another entity
  EntityId other;        // the other entity, for a contact between entities; invalid otherwise
  Fraction fraction;     // of the sub-move (for solid lines) when the contact began or ended
  Vec2w normal;          // from the line towards the entity, in the part's frame, not normalized
  ContactPoints points;  // in the part's coordinates
};

// What a solid contact does to the motion. Defaults: slide along the line and lose the velocity
// component that points into it.
//
// A restitution above zero bounces instead: the body leaves the line with that fraction of the
// normal speed it met it with ({1, 1}: elastic), and the rest of the frame follows the bounce, so
// with constant gravity a bounce is exact (the apex of an elastic drop is where it started, on
// time). A body that would leave slower than one frame of gravity brings back lands instead (the
// defaults apply), so bouncing bodies come to rest. The velocity is the world's to set then: the
// two fields above do not apply.
struct ContactResponse {
  bool slide = true;                 // false: the rest of this frame's motion is dropped
  bool removeNormalVelocity = true;  // false: keep the velocity as the callback left it
  Fraction restitution = Fraction::zero();
};

class Rules {
 public:
  virtual ~Rules() = default;
  // Whether `entity` passes through `line`. Asked once when the line comes near an instance, and
  // again after setRules(); the answer must not change while they overlap. Default: warps pierce.
  // (Not asked about moving platforms' lines: those are solid, or one-way.)
  virtual bool pierce(EntityId entity, const LineRef& line) {
    (void)entity;
    return line.kind == LineKind::Warp;
  }
  // Pierceable lines, and entities that report overlaps with each other (EntityFilter): the interior
  // of an instance starts, keeps (once per frame), stops overlapping. For two entities,
  // Contact::other is set: the mover is `entity` for begin and end, the lower handle for over.
  virtual void beginContact(const Contact&) {}
  virtual void overContact(const Contact&) {}
  virtual void endContact(const Contact&) {}
  // Solid lines, and entities solid to each other: a moving instance reached the line or the other.
  virtual void contact(const Contact&, ContactResponse&) {}
  // Solid lines and entities: a rotation was stopped by one.
  virtual void touchContact(const Contact&) {}
  // A moving platform could not push this entity out of its way (it is caught between the platform
  // and something else) and stopped for this frame, short of its motion (any frame a platform ends
  // short of its motion calls this once, with the entity that stopped it). Contact::line is the
  // platform's line (line 0 when the platform was stopped short of meeting one). What it
  // means (a squashed player, a jammed door) is the rules' business: the world keeps everything
  // where it is, so nothing overlaps.
  virtual void crushed(const Contact&) {}
};

}  // namespace platon::physics
