-- Octahedron, ring: the lines, start and goal are in octa_ring.level; this script talks.
local level = {}

function level.build(game)  -- said once, as the level starts: no per-frame tick to pay for
  game.message("round the top: jump the pit, hop the wall")
end

return level
