-- Icosahedron, drop: fall through a floor out of the next face's side.
return {
  name = "Icosahedron: drop",
  systems = { "scripting", "rendering", "audio" },
  music = "crystal",
  stage = { level = "icosa_drop.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
