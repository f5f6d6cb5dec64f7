-- A football: the level is drawn on a mesh (a truncated icosahedron), read by the meshes plugin.
return {
  name = "Football: first steps",
  systems = { "scripting", "rendering", "meshes", "audio" },
  music = "lattice",
  stage = { level = "soccer_ball.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
  },
}
