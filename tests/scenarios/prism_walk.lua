-- Walk right from the start of the prism level until the goal, on the next face.
return {
  scene = "levels/prism/scene.lua",
  frames = 1500,
  input = { { hold = "right", from = 1, to = 1500 } },
  expect = { goal_by = 1500, deaths = 0 },
}
