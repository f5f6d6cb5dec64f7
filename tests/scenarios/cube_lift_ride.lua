-- Cube, lift: ride the lift. Walk right, jump onto the lift while it waits at the bottom, stand
-- still while it rises 750 units to the ledge's height (no jump gets there), then walk right onto
-- the ledge, over face 0's right edge onto face 1, to the goal.
return {
  scene = "levels/cube_lift/scene.lua",
  frames = 720,
  input = {
    { hold = "right", from = 1, to = 200 },
    { press = "jump", at = 170, frames = 30 },  -- lands on the lift at about frame 230
    { hold = "right", from = 400, to = 720 },   -- the lift waits at the top from frame 391
  },
  expect = {
    goal_by = 720, deaths = 0,
    face = { [240] = 0, [560] = 0, [600] = 1 },
    inside = {
      { frame = 235, face = 0, box = { 2350, 1340, 2850, 1350 } },  -- standing on the lift, down
      { frame = 320, face = 0, box = { 2350, 1650, 2850, 1750 } },  -- on the way up
      { frame = 395, face = 0, box = { 2350, 2090, 2850, 2100 } },  -- up at the ledge's height
      { frame = 500, face = 0, box = { 2900, 2090, 4096, 2100 } },  -- walking along the ledge
    },
  },
}
