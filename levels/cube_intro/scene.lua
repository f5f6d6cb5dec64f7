-- Cube, first steps: walk right over the cube's edges; the goal waits on a later face.
return {
  name = "Cube: first steps",
  systems = { "scripting", "rendering", "audio" },
  music = "first_steps",
  stage = { level = "cube_intro.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
