-- Cube, first steps: the lines, start and goal are in cube_intro.level; this script only talks.
local level = {}

function level.build(game)  -- said once, as the level starts: no per-frame tick to pay for
  game.message("walk right: every edge turns the cube")
end

return level
