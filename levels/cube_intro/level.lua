-- The same run on every face: a floor with a gap, a ramp up to the edge, a platform above.
local level = {}

level.start = { face = 0, x = 600, y = 700 }

function level.build(game)
  local world = game.world
  for i = 1, world.faceCount() do
    local face = world.face(i)
    world.line(face, 256, 512, 2600, 512)
    world.line(face, 3000, 512, 3800, 900)
    world.line(face, 1200, 1800, 2400, 1800)
  end
  -- The goal: a trigger line across face 3, the face the run falls onto over the first edge.
  world.line(3, 3600, 200, 3600, 3900, 2)
end

function level.tick(game, frame)
  if frame == 1 then game.message("walk right: every edge turns the cube") end
end

return level
