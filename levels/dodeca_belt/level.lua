-- Dodecahedron, belt: the lines, start and goal are in dodeca_belt.level; this script talks.
local level = {}

function level.tick(game, frame)
  if frame == 1 then game.message("five sides round the bottom: walk right, jump the pit") end
end

return level
