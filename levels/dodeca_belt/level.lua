-- Dodecahedron, belt: the lines, start and goal are in dodeca_belt.level; this script talks.
local level = {}

function level.build(game)  -- said once, as the level starts: no per-frame tick to pay for
  game.message("five sides round the bottom: walk right, jump the pit")
end

return level
