-- Octahedron, underneath: fall through a floor and come out of the next face's side.
return {
  name = "Octahedron: underneath",
  systems = { "scripting", "rendering" },
  stage = { level = "octa_under.level" },
  gravity = 0.35,
  scripts = {
    rules = "scripts/rules/game.lua",
    player = "scripts/player.lua",
    progression = "scripts/progression.lua",
    level = "level.lua",
  },
}
