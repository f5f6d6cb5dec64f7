-- Tetrahedron, around: walk right round three faces; the goal waits on the third.
return {
  name = "Tetrahedron: around",
  systems = { "scripting", "rendering" },
  stage = { level = "tetra_around.level" },
  gravity = 0.35,
  scripts = {
    rules = "scripts/rules/game.lua",
    player = "scripts/player.lua",
    progression = "scripts/progression.lua",
    level = "level.lua",
  },
}
