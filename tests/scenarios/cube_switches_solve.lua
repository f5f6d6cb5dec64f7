-- Cube, switches: the whole route. Jump the deadly pit, jump into the switch hanging above the
-- floor (it opens door 1 for 7 s), run over face 0's right edge onto face 1, through the open door
-- and on to the goal, with no death.
return {
  scene = "levels/cube_switches/scene.lua",
  frames = 720,
  input = {
    { hold = "right", from = 1, to = 720 },
    { press = "jump", at = 158, frames = 30 },  -- over the pit (x 1900..2200)
    { press = "jump", at = 258, frames = 30 },  -- up into the switch (x 3000)
  },
  expect = {
    goal_by = 720, deaths = 0,
    -- What a player hears: the jumps, the switch's click with the door moving, the edge, the goal.
    sounds = { [158] = "jump", [258] = "jump", [279] = { "switch", "door" }, [423] = "cross", [673] = "goal" },
    face = { [150] = 0, [410] = 0, [440] = 1, [680] = 1 },
    -- The checkpoint is touched on the way (frame 79), the switch at the jump's top (frame 279).
    checkpoint = { [60] = false, [100] = { 0, 1113, 1296 }, [680] = { 0, 1113, 1296 } },
    switches = { [270] = {}, [300] = { 1 } },
    inside = {
      { frame = 190, face = 0, box = { 1950, 1400, 2250, 1550 } },  -- in the air over the pit
      { frame = 290, face = 0, box = { 2900, 1400, 3100, 1550 } },  -- at the jump's top, in the switch
      { frame = 600, face = 1, box = { 1500, 1250, 2000, 1350 } },  -- past the door on face 1
    },
  },
}
