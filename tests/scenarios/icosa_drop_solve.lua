-- Icosahedron, drop: fall through the gap in face 0's floor out of face 8's side, hop the low wall
-- on face 8, walk over onto face 9, jump up through the one-way shelf onto it and from it into
-- the goal.
return {
  scene = "levels/icosa_drop/scene.lua",
  frames = 800,
  input = {
    { hold = "right", from = 1, to = 800 },
    { press = "jump", at = 266, frames = 30 },  -- the low wall on face 8 (x 2600)
    { press = "jump", at = 630, frames = 30 },  -- up through the shelf on face 9
    { press = "jump", at = 690, frames = 30 },  -- from the shelf into the goal
  },
  expect = {
    goal_by = 800, deaths = 0,
    face = { [100] = 0, [250] = 8, [550] = 9 },
    inside = { { frame = 685, face = 9, box = { 2000, 600, 2900, 700 } } },  -- standing on the shelf
  },
}
