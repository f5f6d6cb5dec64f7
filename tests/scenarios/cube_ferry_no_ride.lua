-- Cube, ferry: the pit is too wide to cross without the ferry. Walk right over the waiting ferry
-- and off its far end (a jump pressed there comes too late): down into the pit, whose bottom is
-- deadly; the player starts again at the start.
return {
  scene = "levels/cube_ferry/scene.lua",
  frames = 300,
  input = {
    { hold = "right", from = 1, to = 300 },
    { press = "jump", at = 205, frames = 30 },
  },
  expect = {
    deaths = 1,
    face = { [300] = 0 },
    inside = {
      { frame = 240, face = 0, box = { 2200, 600, 3000, 1200 } },  -- falling in the pit
      { frame = 300, face = 0, box = { 200, 1290, 1600, 1300 } },  -- back on the floor before it
    },
  },
}
