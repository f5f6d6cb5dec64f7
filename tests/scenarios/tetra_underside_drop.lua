-- Tetrahedron, underside: walk right from face 1 over two edges, jump the low wall on face 2, drop
-- through the gap in face 0's floor into the bottom face (gravity turned round) and land under the
-- ledge by the goal.
return {
  scene = "levels/tetra_underside/scene.lua",
  frames = 1300,
  input = {
    { hold = "right", from = 1, to = 1300 },
    { press = "jump", at = 490, frames = 30 },  -- over the low wall on face 2 (x 1800)
  },
  expect = {
    goal_by = 1300, deaths = 0,
    face = { [300] = 1, [600] = 2, [900] = 0, [1020] = 3 },
  },
}
