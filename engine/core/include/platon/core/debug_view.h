// The debug overlay (F2 in the game and `platon play`, `platon shot --debug`): what the physics
// sees, drawn over the picture. Every line by its kind and tag (solid white, one-way sky blue with
// ticks on its solid side, warp edges grey, tagged lines in their tag's colour with the tag's word,
// lines the player passes dashed), each moving platform with its motion, each entity's instances
// (the anchor yellow, its copies across edges orange), its velocity and its contacts with their
// normals.
#pragma once
#include "platon/core/draw_list.h"
#include "platon/core/scene.h"

namespace platon::core {

// Adds the overlay's shapes to `out` (Place::overlay: drawn over the walls, unlit).
void drawDebug(const Scene& scene, DrawList& out);

}  // namespace platon::core
