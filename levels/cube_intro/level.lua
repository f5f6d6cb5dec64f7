-- Cube, first steps: the lines, start and goal are in cube_intro.level; this script only talks.
local level = {}

function level.tick(game, frame)
  if frame == 1 then game.message("walk right: every edge turns the cube") end
end

return level
