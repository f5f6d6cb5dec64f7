-- Dodecahedron, trapdoor: jump into the switch (it opens the trapdoor), walk onto the trapdoor and
-- fall through face 0's floor edge onto the bottom face; slide down the leaning wall, then walk
-- back left, jump the hazard pit and reach the goal.
return {
  scene = "levels/dodeca_trapdoor/scene.lua",
  frames = 700,
  input = {
    { hold = "right", from = 1, to = 300 },
    { press = "jump", at = 60, frames = 30 },   -- up into the switch (x 1300)
    { hold = "left", from = 301, to = 700 },
    { press = "jump", at = 455, frames = 30 },  -- over the pit on face 10 (x 1900..2350)
  },
  expect = {
    goal_by = 700, deaths = 0,
    face = { [150] = 0, [250] = 10, [550] = 10 },
  },
}
