-- A triangular prism: the level is drawn on a mesh, read by the meshes plugin.
return {
  name = "Prism: first steps",
  systems = { "scripting", "rendering", "meshes", "audio" },
  music = "lattice",
  stage = { level = "prism.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
  },
}
