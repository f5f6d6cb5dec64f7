-- Octahedron, underneath: jump the hazard pit, drop through the gap in face 0's floor, come out of
-- face 4's right-hand side and fall along face 4's own down onto its floor, by the goal.
return {
  scene = "levels/octa_under/scene.lua",
  frames = 400,
  input = {
    { hold = "right", from = 1, to = 400 },
    { press = "jump", at = 52, frames = 30 },  -- over the pit (x 1400..1800)
  },
  expect = {
    goal_by = 400, deaths = 0,
    face = { [150] = 0, [200] = 4 },
  },
}
