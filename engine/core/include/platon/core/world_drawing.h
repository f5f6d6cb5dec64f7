// The world as the renderer draws it, each frame: every entity (by its look) and every moving
// platform's lines, added to the frame's draw list before what the systems draw. Nothing in the
// world is drawn by a script's code unless the script wants a look of its own.
#pragma once
#include "platon/core/draw_list.h"
#include "platon/core/look.h"
#include "platon/physics/world.h"

namespace platon::core {

// Adds `world`'s entities and platforms to `out` (nothing when `out` is disabled). Each instance
// of an entity is one shape tagged with the entity (DrawShape::body), so the renderer draws the
// entity once however many faces it spans.
void drawWorld(const physics::World& world, const Looks& looks, const stage::TagTable& tags, DrawList& out);

}  // namespace platon::core
