-- Dodecahedron, trapdoor: the lines, start and goal are in dodeca_trapdoor.level; this script talks.
local level = {}

function level.tick(game, frame)
  if frame == 1 then game.message("the yellow switch opens the orange trapdoor") end
  if game.switchOn(1) and not level.said then
    level.said = true
    game.message("the trapdoor is open: drop through")
  end
end

return level
