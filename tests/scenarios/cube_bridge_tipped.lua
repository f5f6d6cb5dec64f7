-- Cube, turning bridge: walk straight on to the bridge. It lies flat until frame 180, too short a
-- while to cross; it turns with the player on it, tips the player into the pit, whose deadly bottom
-- sends it back to the start.
return {
  scene = "levels/cube_bridge/scene.lua",
  frames = 360,
  input = {
    { hold = "right", from = 1, to = 360 },
  },
  expect = {
    deaths = 1,
    inside = {
      { frame = 170, face = 0, box = { 1500, 1290, 2700, 1300 } },  -- on the bridge while it lies flat
    },
  },
}
