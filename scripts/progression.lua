-- Progression (trusted): spawns the player at the level's start, counts deaths and restarts at
-- the last checkpoint, marks the level won when the goal is reached, applies switch toggles
-- between frames (the world's structure cannot change inside a contact callback).
local game = ...
-- Private copies: nothing a script does to a table can swap what this file calls.
local world = platon.world
local position, destroyEntity, valid, refreshPierce = world.position, world.destroyEntity, world.valid, world.refreshPierce
local pcall, tostring, error = pcall, tostring, error
local DOOR = 1000

local progression = {}

local function levelStartPoint()
  local s = game.level.start or { face = 0, x = 0, y = 0 }
  return s.face, s.x, s.y
end

local function spawnPoint()
  local c = game.checkpoint
  if c then return c.face, c.x, c.y end
  return levelStartPoint()
end

progression.spawnPoint = spawnPoint

-- A new player at the checkpoint, or at the level's start when the checkpoint's place is taken
-- (or gone); the old one is destroyed only once the new one is in the world. Without any place,
-- the old player stays.
function progression.respawn()
  local old = game.player
  local ok, player = pcall(game.Player.spawn, game, spawnPoint())
  if not ok and game.checkpoint then
    game.checkpoint = nil
    game.message = "the checkpoint's place is taken: back to the level's start"
    ok, player = pcall(game.Player.spawn, game, levelStartPoint())
  end
  if not ok then error("the player cannot respawn: " .. tostring(player), 0) end
  game.player = player
  if old and valid(old.entity) then destroyEntity(old.entity) end
end

function progression.start()
  game.player = game.Player.spawn(game, spawnPoint())
end

-- The switches that are on, in increasing order (what the renderer's open doors follow).
local function listOpen()
  local on = {}
  for id = 0, 999 do
    if game.switches[id] then on[#on + 1] = id end
  end
  game.openSwitches = on
end

-- After a hot reload restored the switches: the new world's doors follow them (in id order).
function progression.onReload()
  for id = 0, 999 do
    if game.switches[id] ~= nil then refreshPierce(DOOR + id) end
  end
  listOpen()
end

function progression.afterStep()
  local toggles = game.pendingToggles
  if #toggles > 0 then
    for i = 1, #toggles do
      local id = toggles[i]
      game.switches[id] = not game.switches[id]
      refreshPierce(DOOR + id)
      toggles[i] = nil
    end
    listOpen()
  end
  if game.touchedCheckpoint then
    game.touchedCheckpoint = false
    local face, x, y = position(game.player.entity)
    game.checkpoint = { face = face, x = x, y = y }
  end
  if game.reachedGoal and not game.won then
    game.won, game.wonFrame = true, game.time  -- frames played: a hot reload starts a new world at frame 0
    game.message = "goal reached"
  end
  if game.killed or (game.input.pressed.restart and not game.won) then
    game.killed = false
    game.deaths = game.deaths + 1
    progression.respawn()
  end
end

return progression
