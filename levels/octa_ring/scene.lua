-- Octahedron, ring: walk right round the four upper faces.
return {
  name = "Octahedron: ring",
  systems = { "scripting", "rendering", "audio" },
  music = "orbit",
  stage = { level = "octa_ring.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
