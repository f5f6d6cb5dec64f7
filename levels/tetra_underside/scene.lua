-- Tetrahedron, underside: drop through a gap onto the bottom face, where gravity is turned round.
return {
  name = "Tetrahedron: underside",
  systems = { "scripting", "rendering" },
  stage = { level = "tetra_underside.level" },
  gravity = 0.35,
  scripts = {
    rules = "scripts/rules/game.lua",
    player = "scripts/player.lua",
    progression = "scripts/progression.lua",
    level = "level.lua",
  },
}
