-- Tetrahedron, around: the lines, start and goal are in tetra_around.level; this script talks.
local level = {}

function level.tick(game, frame)
  if frame == 1 then game.message("walk right: each edge tips you onto the next face") end
end

return level
