-- Octahedron, underneath: fall through a floor and come out of the next face's side.
return {
  name = "Octahedron: underneath",
  systems = { "scripting", "rendering", "audio" },
  music = "orbit",
  stage = { level = "octa_under.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
