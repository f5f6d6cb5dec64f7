-- Tetrahedron, underside: the lines, start and goal are in tetra_underside.level; this script talks.
local level = {}

function level.tick(game, frame)
  if frame == 1 then game.message("the goal is underneath: find a way down through a floor") end
end

return level
