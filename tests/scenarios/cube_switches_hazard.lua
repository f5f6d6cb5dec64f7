-- Cube, switches: the hazard and the checkpoint. Walk right without jumping: the player passes
-- the checkpoint (x 1200), drops into the pit and touches its deadly floor, which counts one death
-- and respawns the player where it crossed the checkpoint, not at the start (x 500).
return {
  scene = "levels/cube_switches/scene.lua",
  frames = 300,
  input = { { hold = "right", from = 1, to = 200 } },
  expect = {
    deaths = 1,
    sounds = { [79] = "checkpoint", [212] = "death" },  -- the checkpoint passed, the pit's hazard
    inside = {
      { frame = 205, face = 0, box = { 1900, 900, 2200, 1200 } },   -- falling into the pit
      { frame = 213, face = 0, box = { 1050, 1250, 1200, 1350 } },  -- just respawned at the checkpoint
      { frame = 300, face = 0, box = { 1050, 1250, 1300, 1350 } },  -- and still there
    },
  },
}
