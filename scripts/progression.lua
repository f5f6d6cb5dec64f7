-- Progression (trusted): spawns the player at the level's start, counts deaths and restarts at
-- the last checkpoint, marks the level won when the goal is reached, applies switch toggles
-- between frames (the world's structure cannot change inside a contact callback).
local game = ...
local world = platon.world
local DOOR = 1000

local progression = {}

local function spawnPoint()
  local c = game.checkpoint or game.level.start or { face = 0, x = 0, y = 0 }
  return c.face, c.x, c.y
end

progression.spawnPoint = spawnPoint

function progression.start()
  game.player = game.Player.spawn(game, spawnPoint())
end

-- After a hot reload restored the switches: the new world's doors follow them.
function progression.onReload()
  for id in pairs(game.switches) do world.refreshPierce(DOOR + id) end
end

function progression.afterStep()
  for i = 1, #game.pendingToggles do
    local id = game.pendingToggles[i]
    game.switches[id] = not game.switches[id]
    world.refreshPierce(DOOR + id)
    game.pendingToggles[i] = nil
  end
  if game.touchedCheckpoint then
    game.touchedCheckpoint = false
    local face, x, y = world.position(game.player.entity)
    game.checkpoint = { face = face, x = x, y = y }
  end
  if game.reachedGoal and not game.won then
    game.won, game.wonFrame = true, world.frame()
    game.message = "goal reached"
  end
  if game.killed or (game.input.pressed.restart and not game.won) then
    game.killed = false
    game.deaths = game.deaths + 1
    world.destroyEntity(game.player.entity)
    game.player = game.Player.spawn(game, spawnPoint())
  end
end

return progression
