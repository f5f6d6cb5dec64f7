-- Walk right from the start on the cube's first level until the goal.
return {
  scene = "levels/cube_intro/scene.lua",
  frames = 3000,
  input = { { hold = "right", from = 1, to = 3000 } },
  expect = { goal_by = 3000, deaths = 0 },
}
