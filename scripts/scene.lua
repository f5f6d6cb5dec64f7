-- Drives a scene's scripts (trusted). The engine calls build, start, beforeStep, afterStep, draw
-- and status; this file loads the manifest's scripts and passes them the shared `game` state.
--   rules        returns a table of contact callbacks (docs/scripting.md, "Rules")
--   player       returns the Player module: spawn(game, face, x, y), tick(self, input), draw(self, draw)
--   progression  returns {start(game), afterStep(game)}: spawning, goal, deaths, checkpoints
--   level        returns {build(level), start = {face, x, y}, tick(level, frame), ...} (sandboxed)
--   mods         sandboxed scripts that may return {tick(level, frame)}
local engine, setup = ...
local world = platon.world
local band = bit.band

local function load(path, ...)
  if path == nil or path == "" then return nil end
  local trusted = path:sub(1, 8) == "scripts/"
  return engine.load(path, trusted, ...)
end

local BUTTONS = { "left", "right", "up", "down", "jump", "restart", "pause", "reload" }

local game = {
  name = setup.name,
  won = false, wonFrame = 0, deaths = 0, message = "",
  time = 0,            -- frames played on this level (kept across hot reloads, unlike world.frame())
  switches = {},       -- switch id -> true when on
  pendingToggles = {}, -- switch ids toggled during the frame, applied after it
  killed = false,
  input = { pressed = {} },
}

-- What level scripts and mods see (a read-only view inside their sandbox).
local levelApi = {
  world = world,
  message = function(text) game.message = tostring(text) end,
  switchOn = function(id) return game.switches[id] == true end,
  toggle = function(id) game.pendingToggles[#game.pendingToggles + 1] = id end,
  kill = function() game.killed = true end,
  checkpoint = function(face, x, y) game.checkpoint = { face = face, x = x, y = y } end,
  frame = function() return game.time end,  -- frames played: kept across hot reloads
  player = function() return game.player and game.player.entity end,
  won = function() return game.won end,
}
game.levelApi = levelApi

local scene = {}

function scene.build()
  game.level = load(setup.level, levelApi) or {}
  if type(game.level) ~= "table" then error(setup.level .. ": a level script returns a table", 0) end
  game.Player = load(setup.player, game)
  game.progression = load(setup.progression, game) or {}
  game.mods = {}
  for i, path in ipairs(setup.mods) do game.mods[i] = load(path, levelApi) or {} end
  if game.level.build then game.level.build(levelApi) end
end

function scene.start()
  local rules = load(setup.rules, game)
  if rules then engine.setRules(rules) end
  if game.progression.start then game.progression.start(game) end
end

function scene.beforeStep(held, pressed)
  local input = game.input
  for i = 1, #BUTTONS do
    local name, b = BUTTONS[i], 2 ^ (i - 1)
    input[name] = band(held, b) ~= 0
    input.pressed[name] = band(pressed, b) ~= 0
  end
  if game.player and game.Player then game.Player.tick(game.player, input) end
  local frame = game.time + 1
  if game.level.tick then game.level.tick(levelApi, frame) end
  for i = 1, #game.mods do
    if game.mods[i].tick then game.mods[i].tick(levelApi, frame) end
  end
end

function scene.afterStep()
  game.time = game.time + 1
  if game.progression.afterStep then game.progression.afterStep(game) end
end

-- Hot reload: the old version's save() is copied as plain data into the new version's restore().
local KEPT = { "won", "wonFrame", "deaths", "message", "time", "checkpoint", "switches" }

local function plainFields(t)
  local out = {}
  for k, v in pairs(t) do
    local kind = type(v)
    if kind == "number" or kind == "string" or kind == "boolean" then out[k] = v end
  end
  return out
end

function scene.save()
  local saved = { game = {}, mods = {} }
  for _, key in ipairs(KEPT) do saved.game[key] = game[key] end
  local p = game.player
  if p and world.valid(p.entity) then
    local face, x, y = world.position(p.entity)
    local vx, vy = world.velocity(p.entity)
    saved.player = { face = face, x = x, y = y, vx = vx, vy = vy, angle = world.angle(p.entity),
                     state = game.Player.save and game.Player.save(p) or plainFields(p) }
  end
  if game.level.save then saved.level = game.level.save(levelApi) end
  for i = 1, #game.mods do
    if game.mods[i].save then saved.mods[i] = game.mods[i].save(levelApi) end
  end
  return saved
end

-- Puts the player back where it was; where the new level has a wall there (or the face is gone),
-- it stays at the level start where progression.start() put it.
local function restorePlayer(saved)
  if not saved or not game.player then return false end
  local old = game.player
  world.destroyEntity(old.entity)
  local ok, player = pcall(game.Player.spawn, game, saved.face, saved.x, saved.y)
  if not ok then
    local start = game.level.start or { face = 0, x = 0, y = 0 }
    if game.progression.spawnPoint then game.player = game.Player.spawn(game, game.progression.spawnPoint())
    else game.player = game.Player.spawn(game, start.face, start.x, start.y) end
    return false
  end
  game.player = player
  world.setVelocity(player.entity, saved.vx, saved.vy)
  if game.Player.onReload then game.Player.onReload(player, saved.state)
  else
    for k, v in pairs(saved.state or {}) do if k ~= "entity" and type(player[k]) == type(v) then player[k] = v end end
  end
  return true
end

function scene.restore(saved)
  for _, key in ipairs(KEPT) do
    if saved.game[key] ~= nil then game[key] = saved.game[key] end
  end
  if game.progression.onReload then game.progression.onReload(game) end
  game.restoredPlayer = restorePlayer(saved.player)
  if not game.restoredPlayer and saved.player then game.message = "reloaded: the player's place is gone, back to the start" end
  if game.level.onReload then game.level.onReload(levelApi, saved.level) end
  for i = 1, #game.mods do
    if game.mods[i].onReload then game.mods[i].onReload(levelApi, saved.mods[i]) end
  end
end

function scene.draw()
  if game.player and game.Player and game.Player.draw then game.Player.draw(game.player, platon.draw) end
  if game.level.draw then game.level.draw(levelApi, platon.draw) end
end

local status = {}
function scene.status()
  status.won, status.wonFrame, status.deaths, status.message = game.won, game.wonFrame, game.deaths, game.message
  status.time = game.time
  if game.player and world.valid(game.player.entity) then
    status.face, status.x, status.y = world.position(game.player.entity)
  end
  return status
end

function scene.game() return game end

return scene
