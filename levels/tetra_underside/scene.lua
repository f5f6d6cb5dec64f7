-- Tetrahedron, underside: drop through a gap onto the bottom face, where gravity is turned round.
return {
  name = "Tetrahedron: underside",
  systems = { "scripting", "rendering", "audio" },
  music = "first_steps",
  stage = { level = "tetra_underside.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
