-- Tetrahedron, around: walk right round three faces; the goal waits on the third.
return {
  name = "Tetrahedron: around",
  systems = { "scripting", "rendering", "audio" },
  music = "first_steps",
  stage = { level = "tetra_around.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
