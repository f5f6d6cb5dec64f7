-- Cube, first steps: walk right over the cube's edges; the goal waits on a later face.
return {
  name = "Cube: first steps",
  systems = { "scripting", "rendering" },
  stage = { level = "cube_intro.level" },
  gravity = 0.35,
  scripts = {
    rules = "scripts/rules/game.lua",
    player = "scripts/player.lua",
    progression = "scripts/progression.lua",
    level = "level.lua",
  },
}
