-- Icosahedron, drop: the lines, start and goal are in icosa_drop.level; this script talks.
local level = {}

function level.build(game)  -- said once, as the level starts: no per-frame tick to pay for
  game.message("the wall is shut: look down")
end

return level
