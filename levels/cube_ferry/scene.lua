-- Cube, ferry: ride a moving platform over a pit and over the cube's edge onto the next face.
return {
  name = "Cube: ferry",
  systems = { "scripting", "rendering", "audio" },
  music = "first_steps",
  stage = { level = "cube_ferry.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
