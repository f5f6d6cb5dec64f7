-- Dodecahedron, trapdoor: open the trapdoor with the switch and fall onto the bottom face.
return {
  name = "Dodecahedron: trapdoor",
  systems = { "scripting", "rendering" },
  stage = { level = "dodeca_trapdoor.level" },
  gravity = 0.35,
  scripts = {
    rules = "scripts/rules/game.lua",
    player = "scripts/player.lua",
    progression = "scripts/progression.lua",
    level = "level.lua",
  },
}
