-- Octahedron, ring: the lines, start and goal are in octa_ring.level; this script talks.
local level = {}

function level.tick(game, frame)
  if frame == 1 then game.message("round the top: jump the pit, hop the wall") end
end

return level
