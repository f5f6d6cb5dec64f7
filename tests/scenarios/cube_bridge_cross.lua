-- Cube, turning bridge: walk up to the pit, wait there while the bridge turns and stands, then
-- cross it while it lies flat again, and walk on over face 0's right edge onto face 1 to the goal.
return {
  scene = "levels/cube_bridge/scene.lua",
  frames = 780,
  input = {
    { hold = "right", from = 1, to = 90 },     -- up to the pit's edge
    { hold = "right", from = 392, to = 780 },  -- the bridge lies flat again from frame 391
  },
  expect = {
    goal_by = 780, deaths = 0,
    face = { [300] = 0, [700] = 0, [760] = 1 },
    inside = {
      { frame = 300, face = 0, box = { 1300, 1290, 1400, 1300 } },  -- waiting at the pit's edge
      { frame = 470, face = 0, box = { 1900, 1290, 2300, 1300 } },  -- on the bridge, over the pit
    },
  },
}
