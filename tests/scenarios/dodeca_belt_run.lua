-- Dodecahedron, belt: walk right over two edges, jumping the hazard pit on face 1 and hopping the
-- low wall on face 2, to the goal.
return {
  scene = "levels/dodeca_belt/scene.lua",
  frames = 1400,
  input = {
    { hold = "right", from = 1, to = 1400 },
    { press = "jump", at = 570, frames = 30 },   -- over the pit on face 1 (x 1500..1950)
    { press = "jump", at = 1108, frames = 30 },  -- over the wall on face 2 (x 2000)
  },
  expect = {
    goal_by = 1400, deaths = 0,
    face = { [300] = 0, [600] = 1, [1000] = 2 },
  },
}
