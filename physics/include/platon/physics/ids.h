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
  friend constexpr bool operator==(EntityId, EntityId) = default;
};

}  // namespace platon::physics
