-- Cube, lift: ride a lift up to a ledge too high to jump to, then walk over an
-- edge onto the next face to the goal.
return {
  name = "Cube: lift",
  systems = { "scripting", "rendering", "audio" },
  music = "first_steps",
  stage = { level = "cube_lift.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
