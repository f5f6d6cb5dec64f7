-- Cube, lift: ride a lift up to a ledge too high to jump to, then walk over an
-- edge onto the next face to the goal.
return {
  name = "Cube: lift",
  systems = { "scripting", "rendering" },
  stage = { level = "cube_lift.level" },
  gravity = 0.35,
  scripts = {
    rules = "scripts/rules/game.lua",
    player = "scripts/player.lua",
    progression = "scripts/progression.lua",
    level = "level.lua",
  },
}
