-- Cube, switches: the timer. Hit the switch (door 1 opens), then wait three seconds before
-- running on: level.tick shuts the door again 7 s after it opened, before the player gets there,
-- so the player ends up stopped against the closed door on face 1 (its side at x 1500 - 96).
return {
  scene = "levels/cube_switches/scene.lua",
  frames = 900,
  input = {
    { hold = "right", from = 1, to = 300 },
    { press = "jump", at = 158, frames = 30 },  -- over the pit
    { press = "jump", at = 258, frames = 30 },  -- into the switch at about frame 290
    { hold = "right", from = 500, to = 900 },   -- the door shuts at about frame 710
  },
  expect = {
    deaths = 0,
    inside = {
      { frame = 450, face = 0, box = { 3200, 1250, 3500, 1350 } },  -- waiting past the switch
      { frame = 900, face = 1, box = { 1350, 1250, 1410, 1350 } },  -- held by the shut door
    },
  },
}
