-- Cube, switches: jump to hit a switch that opens a door for a few seconds, over a deadly pit and
-- a checkpoint, then run across an edge onto the next face and through the door to the goal.
return {
  name = "Cube: switches",
  systems = { "scripting", "rendering", "audio" },
  music = "first_steps",
  stage = { level = "cube_switches.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
