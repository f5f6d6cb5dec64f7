-- Octahedron, ring: walk right round the four upper faces.
return {
  name = "Octahedron: ring",
  systems = { "scripting", "rendering" },
  stage = { level = "octa_ring.level" },
  gravity = 0.35,
  scripts = {
    rules = "scripts/rules/game.lua",
    player = "scripts/player.lua",
    progression = "scripts/progression.lua",
    level = "level.lua",
  },
}
