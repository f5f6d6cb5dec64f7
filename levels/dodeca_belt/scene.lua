-- Dodecahedron, belt: walk right round the pentagons.
return {
  name = "Dodecahedron: belt",
  systems = { "scripting", "rendering", "audio" },
  music = "orbit",
  stage = { level = "dodeca_belt.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
