-- Dodecahedron, belt: walk right round the pentagons.
return {
  name = "Dodecahedron: belt",
  systems = { "scripting", "rendering" },
  stage = { level = "dodeca_belt.level" },
  gravity = 0.35,
  scripts = {
    rules = "scripts/rules/game.lua",
    player = "scripts/player.lua",
    progression = "scripts/progression.lua",
    level = "level.lua",
  },
}
