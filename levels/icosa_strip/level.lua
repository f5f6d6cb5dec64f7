-- Icosahedron, strip: the lines, start and goal are in icosa_strip.level; this script talks.
local level = {}

function level.build(game)  -- said once, as the level starts: no per-frame tick to pay for
  game.message("small faces, quick turns: mind the spiked floors")
end

return level
