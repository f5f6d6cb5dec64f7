-- Cube, lift: without the lift the ledge is out of reach. Walk right past the lift (at the floor
-- the one-way lift lets the player through) to the wall under the ledge and jump three times: every
-- jump tops out ~170 units up, far below the ledge (y 2000), and the player never leaves face 0.
return {
  scene = "levels/cube_lift/scene.lua",
  frames = 700,
  input = {
    { hold = "right", from = 1, to = 700 },
    { press = "jump", at = 380, frames = 30 },
    { press = "jump", at = 460, frames = 30 },
    { press = "jump", at = 540, frames = 30 },
  },
  expect = {
    deaths = 0,
    face = { [700] = 0 },
    inside = {
      { frame = 410, face = 0, box = { 3600, 1250, 3800, 1500 } },  -- each jump's top
      { frame = 490, face = 0, box = { 3600, 1250, 3800, 1500 } },
      { frame = 570, face = 0, box = { 3600, 1250, 3800, 1500 } },
      { frame = 700, face = 0, box = { 3600, 1250, 3800, 1350 } },  -- back on the floor, below
    },
  },
}
