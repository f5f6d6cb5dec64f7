-- Cube, ferry: ride the ferry. Walk right onto the ferry while it waits at the pit's near side
-- (flush with the floor), stand still while it crosses the pit and face 0's right edge onto face 1,
-- then walk right off it onto face 1's floor, to the goal.
return {
  scene = "levels/cube_ferry/scene.lua",
  frames = 1100,
  input = {
    { hold = "right", from = 1, to = 150 },
    { hold = "right", from = 800, to = 1100 },  -- the ferry is at the far side from frame 791
  },
  expect = {
    goal_by = 1100, deaths = 0,
    face = { [200] = 0, [700] = 1 },
    inside = {
      { frame = 230, face = 0, box = { 1600, 1290, 2200, 1300 } },  -- standing on the ferry, waiting
      { frame = 500, face = 0, box = { 3100, 1290, 3700, 1300 } },  -- riding it over the pit
      { frame = 790, face = 1, box = { 800, 1290, 1400, 1300 } },   -- at the far side
    },
  },
}
