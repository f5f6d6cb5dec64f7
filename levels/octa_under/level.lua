-- Octahedron, underneath: the lines, start and goal are in octa_under.level; this script talks.
local level = {}

function level.build(game)  -- said once, as the level starts: no per-frame tick to pay for
  game.message("the goal is below this floor: look for a gap")
end

return level
