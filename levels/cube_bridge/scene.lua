-- Cube, turning bridge: cross a deadly pit on a bridge that turns a quarter turn at a time, while
-- it lies flat, then walk over an edge onto the next face to the goal.
return {
  name = "Cube: turning bridge",
  systems = { "scripting", "rendering", "audio" },
  music = "first_steps",
  stage = { level = "cube_bridge.level" },
  gravity = 0.35,
  scripts = {
    preset = "game",  -- the game's rules, player and progression (docs/scripting.md)
    level = "level.lua",
  },
}
