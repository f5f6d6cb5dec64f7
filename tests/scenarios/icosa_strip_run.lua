-- Icosahedron, strip: from face 7 walk right over two edges (7 -> 0 -> 1), jumping the pit and the
-- low wall on face 0 and the pit on face 1, to the goal.
return {
  scene = "levels/icosa_strip/scene.lua",
  frames = 1100,
  input = {
    { hold = "right", from = 1, to = 1100 },
    { press = "jump", at = 436, frames = 30 },  -- the pit on face 0 (x 1300..1750)
    { press = "jump", at = 582, frames = 30 },  -- the low wall on face 0 (x 2700)
    { press = "jump", at = 868, frames = 30 },  -- the pit on face 1 (x 1400..1850)
  },
  expect = {
    goal_by = 1100, deaths = 0,
    face = { [300] = 7, [500] = 0, [850] = 1 },
  },
}
