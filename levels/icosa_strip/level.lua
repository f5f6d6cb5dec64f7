-- Icosahedron, strip: the lines, start and goal are in icosa_strip.level; this script talks.
local level = {}

function level.tick(game, frame)
  if frame == 1 then game.message("small faces, quick turns: mind the red floors") end
end

return level
