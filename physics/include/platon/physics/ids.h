// Stable handles: plain integers that Lua, the renderer and save files can hold.
#pragma once
#include <cstdint>

namespace platon::physics {

using MapPartId = uint32_t;  // chosen by the caller (the level file's face index, say)
using LineIndex = uint32_t;  // position of a line in its map part, in the order lines were added

// An entity handle: a slot and the slot's generation, so a stale handle is detected, never reused.
struct EntityId {
  uint32_t index = UINT32_MAX;
  uint32_t generation = 0;
  constexpr bool isSet() const { return index != UINT32_MAX; }  // false for a default handle
  friend constexpr bool operator==(EntityId, EntityId) = default;
};

// A moving platform's handle, checked like an entity's.
struct PlatformId {
  uint32_t index = UINT32_MAX;
  uint32_t generation = 0;
  constexpr bool isSet() const { return index != UINT32_MAX; }
  friend constexpr bool operator==(PlatformId, PlatformId) = default;
};

// Which entities meet which, by category bits (like a collision filter). Two entities are solid to
// each other (they stop, rest on or push each other) when each one's category is in the other's
// solidWith; they report overlaps through Rules (begin, over, end, with Contact::other) when they
// are not solid to each other and either one's category is in the other's overlapWith. The default
// meets nothing and costs nothing.
struct EntityFilter {
  uint32_t category = 0;     // what this entity is: player, crate, enemy, pickup... one bit each
  uint32_t solidWith = 0;    // categories it collides with
  uint32_t overlapWith = 0;  // categories it reports overlaps with
  bool pushable = false;     // a solid entity moving into it pushes it along (a crate); else it holds
  friend constexpr bool operator==(const EntityFilter&, const EntityFilter&) = default;
};

constexpr bool solidPair(const EntityFilter& a, const EntityFilter& b) {
  return (a.category & b.solidWith) != 0 && (b.category & a.solidWith) != 0;
}
constexpr bool overlapPair(const EntityFilter& a, const EntityFilter& b) {
  return !solidPair(a, b) && ((a.overlapWith & b.category) != 0 || (b.overlapWith & a.category) != 0);
}

}  // namespace platon::physics
