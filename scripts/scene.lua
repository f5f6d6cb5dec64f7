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
  frame = function() return world.frame() end,
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
  local frame = world.frame() + 1
  if game.level.tick then game.level.tick(levelApi, frame) end
  for i = 1, #game.mods do
    if game.mods[i].tick then game.mods[i].tick(levelApi, frame) end
  end
end

function scene.afterStep()
  if game.progression.afterStep then game.progression.afterStep(game) end
end

function scene.draw()
  if game.player and game.Player and game.Player.draw then game.Player.draw(game.player, platon.draw) end
  if game.level.draw then game.level.draw(levelApi, platon.draw) end
end

local status = {}
function scene.status()
  status.won, status.wonFrame, status.deaths, status.message = game.won, game.wonFrame, game.deaths, game.message
  if game.player and world.valid(game.player.entity) then
    status.face, status.x, status.y = world.position(game.player.entity)
  end
  return status
end

function scene.game() return game end

return scene
