-- Icosahedron, drop: the lines, start and goal are in icosa_drop.level; this script talks.
local level = {}

function level.tick(game, frame)
  if frame == 1 then game.message("the wall is shut: look down") end
end

return level
