-- Icosahedron, strip: three triangles in a row, each leaning its own way.
return {
  name = "Icosahedron: strip",
  systems = { "scripting", "rendering" },
  stage = { level = "icosa_strip.level" },
  gravity = 0.35,
  scripts = {
    rules = "scripts/rules/game.lua",
    player = "scripts/player.lua",
    progression = "scripts/progression.lua",
    level = "level.lua",
  },
}
