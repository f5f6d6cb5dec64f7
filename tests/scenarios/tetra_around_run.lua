-- Tetrahedron, around: walk right over two edges (down turns at each), jumping the hazard pit on
-- face 1, to the goal on face 2.
return {
  scene = "levels/tetra_around/scene.lua",
  frames = 1200,
  input = {
    { hold = "right", from = 1, to = 1200 },
    { press = "jump", at = 495, frames = 30 },  -- over the pit on face 1 (x 1700..2150)
  },
  expect = {
    goal_by = 1200, deaths = 0,
    face = { [200] = 0, [450] = 1, [900] = 2 },
  },
}
