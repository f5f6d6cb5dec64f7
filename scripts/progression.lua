-- Progression (trusted): spawns the player at the level's start, counts deaths and restarts at
-- the last checkpoint, marks the level won when the goal is reached, applies switch toggles
-- between frames (the world's structure cannot change inside a contact callback).
local game = ...
-- Private copies: nothing a script does to a table can swap what this file calls.
local world = platon.world
local play = platon.sound.play
local position, destroyEntity = world.position, world.destroyEntity
local valid, refreshPierce = world.valid, world.refreshPierce
local pcall, tostring, error, rawget, type = pcall, tostring, error, rawget, type
local DOOR = platon.tags.door  -- door n is DOOR + n
-- Taken once, now: a level's own (sandboxed) player script shares `game` and may write to it, so
-- nothing here calls a function found in `game` later, and what it reads there it reads raw.
local Player = game.Player
local start = game.level.start

local progression = {}

local function entityOf(p) return type(p) == "table" and rawget(p, "entity") or nil end
local function switches() return rawget(game, "switches") end

local function levelStartPoint()
  if not start then return 0, 0, 0 end
  return start.face, start.x, start.y
end

local function spawnPoint()
  local c = rawget(game, "checkpoint")
  if type(c) == "table" then
    local face, x, y = rawget(c, "face"), rawget(c, "x"), rawget(c, "y")
    if type(face) == "number" and type(x) == "number" and type(y) == "number" then return face, x, y end
  end
  return levelStartPoint()
end

progression.spawnPoint = spawnPoint

-- A new player at the checkpoint, or at the level's start when the checkpoint's place is taken
-- (or gone); the old one is destroyed only once the new one is in the world. Without any place,
-- the old player stays.
function progression.respawn()
  local old = entityOf(rawget(game, "player"))
  local ok, player = pcall(Player.spawn, game, spawnPoint())
  if not ok and game.checkpoint then
    game.checkpoint = nil
    game.message = "the checkpoint's place is taken: back to the level's start"
    ok, player = pcall(Player.spawn, game, levelStartPoint())
  end
  if not ok then error("the player cannot respawn: " .. tostring(player), 0) end
  game.player = player
  if old and valid(old) then destroyEntity(old) end
end

function progression.start()
  game.player = Player.spawn(game, spawnPoint())
end

-- The switches that are on, in increasing order (what the renderer's open doors follow).
local function listOpen()
  local on = {}
  for id = 0, 999 do
    if rawget(switches(), id) then on[#on + 1] = id end
  end
  game.openSwitches = on
end

-- After a hot reload restored the switches: the new world's doors follow them (in id order).
function progression.onReload()
  for id = 0, 999 do
    if rawget(switches(), id) ~= nil then refreshPierce(DOOR + id) end
  end
  listOpen()
end

function progression.afterStep()
  local toggles = rawget(game, "pendingToggles")
  if rawget(toggles, 1) ~= nil then
    local on = switches()
    local i = 1
    while true do
      local id = rawget(toggles, i)
      if id == nil then break end
      if type(id) == "number" then  -- levelApi.toggle checked it; a level's own player may write here too
        on[id] = not rawget(on, id)  -- no __newindex on game's tables: a plain write is raw (a base has no rawset)
        refreshPierce(DOOR + id)
      end
      toggles[i] = nil
      i = i + 1
    end
    listOpen()
    play("door")  -- a door moves (the switch's own click is the rules', on contact)
  end
  if game.touchedCheckpoint then
    game.touchedCheckpoint = false
    local face, x, y = position(entityOf(rawget(game, "player")))
    game.checkpoint = { face = face, x = x, y = y }
    play("checkpoint")
  end
  if game.reachedGoal and not game.won then
    game.won, game.wonFrame = true, game.time  -- frames played: a hot reload starts a new world at frame 0
    game.message = "goal reached"
    play("goal")
  end
  if game.killed or (game.input.pressed.restart and not game.won) then
    play(game.killed and "death" or "respawn")
    game.killed = false
    game.deaths = game.deaths + 1
    progression.respawn()
  end
end

return progression
