-- Tetrahedron, around: the lines, start and goal are in tetra_around.level; this script talks.
local level = {}

function level.build(game)  -- said once, as the level starts: no per-frame tick to pay for
  game.message("walk right: each edge tips you onto the next face")
end

return level
