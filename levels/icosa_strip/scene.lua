-- Icosahedron, strip: three triangles in a row, each leaning its own way.
return {
  name = "Icosahedron: strip",
  systems = { "scripting", "rendering", "audio" },
  music = "crystal",
  stage = { level = "icosa_strip.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
