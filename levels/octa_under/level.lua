-- Octahedron, underneath: the lines, start and goal are in octa_under.level; this script talks.
local level = {}

function level.tick(game, frame)
  if frame == 1 then game.message("the goal is below this floor: look for a gap") end
end

return level
