-- Icosahedron, drop: fall through a floor out of the next face's side.
return {
  name = "Icosahedron: drop",
  systems = { "scripting", "rendering" },
  stage = { level = "icosa_drop.level" },
  gravity = 0.35,
  scripts = {
    rules = "scripts/rules/game.lua",
    player = "scripts/player.lua",
    progression = "scripts/progression.lua",
    level = "level.lua",
  },
}
