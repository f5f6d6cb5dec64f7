-- Tetrahedron, underside: the lines, start and goal are in tetra_underside.level; this script talks.
local level = {}

function level.build(game)  -- said once, as the level starts: no per-frame tick to pay for
  game.message("the goal is underneath: find a way down through a floor")
end

return level
