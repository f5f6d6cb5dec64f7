-- A football: the level is drawn on a mesh (a truncated icosahedron), read by the meshes plugin.
return {
  name = "Football: first steps",
  systems = { "scripting", "rendering", "meshes" },
  stage = { level = "soccer_ball.level" },
  gravity = 0.35,
  scripts = {
    rules = "scripts/rules/game.lua",
    player = "scripts/player.lua",
    progression = "scripts/progression.lua",
  },
}
