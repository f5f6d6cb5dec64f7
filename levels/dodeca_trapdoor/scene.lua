-- Dodecahedron, trapdoor: open the trapdoor with the switch and fall onto the bottom face.
return {
  name = "Dodecahedron: trapdoor",
  systems = { "scripting", "rendering", "audio" },
  music = "orbit",
  stage = { level = "dodeca_trapdoor.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
