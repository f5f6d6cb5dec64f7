-- Octahedron, ring: walk right round the four upper faces, jumping the hazard pit on face 1 and
-- hopping the low wall on face 2, to the goal on face 3.
return {
  scene = "levels/octa_ring/scene.lua",
  frames = 1500,
  input = {
    { hold = "right", from = 1, to = 1500 },
    { press = "jump", at = 478, frames = 30 },  -- over the pit on face 1 (x 1500..2000)
    { press = "jump", at = 972, frames = 30 },  -- over the wall on face 2 (x 2000)
  },
  expect = {
    goal_by = 1500, deaths = 0,
    face = { [300] = 0, [600] = 1, [1000] = 2, [1400] = 3 },
  },
}
