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

local function trusted(path) return path:sub(1, 8) == "scripts/" end

local function load(path, ...)
  if path == nil or path == "" then return nil end
  return engine.load(path, trusted(path), ...)
end

-- Level scripts and mods are sandboxed: their functions run with the JIT off (so the time budget's
-- hook can stop any loop). Trusted code calls them through engine.call, a C function: LuaJIT
-- stitches the trusted code's traces around it instead of giving up on them. Their tables are read
-- raw, once, so no metamethod of theirs ever runs outside a sandboxed call.
local call = engine.call
local HOOKS = { "build", "tick", "draw", "save", "onReload" }

local function sandboxedModule(t, path)
  if t == nil then return {} end
  if type(t) ~= "table" then error(path .. ": a level script or mod returns a table", 0) end
  local m = {}
  for _, name in ipairs(HOOKS) do
    local f = rawget(t, name)
    if type(f) == "function" then m[name] = f end
  end
  local start = rawget(t, "start")
  if type(start) == "table" then
    m.start = { face = tonumber(rawget(start, "face")), x = tonumber(rawget(start, "x")), y = tonumber(rawget(start, "y")) }
  end
  return m
end

-- The buttons, by their InputFrame bits (core/input.h): left 1, right 2, up 4, down 8, jump 16,
-- restart 32, pause 64, reload 128. Written out with constant keys, which the JIT turns into
-- direct slots (a loop over names costs a hash lookup each).
local function decode(t, bits)
  t.left, t.right, t.up, t.down = band(bits, 1) ~= 0, band(bits, 2) ~= 0, band(bits, 4) ~= 0, band(bits, 8) ~= 0
  t.jump, t.restart, t.pause, t.reload = band(bits, 16) ~= 0, band(bits, 32) ~= 0, band(bits, 64) ~= 0, band(bits, 128) ~= 0
end

local game = {
  name = setup.name,
  won = false, wonFrame = 0, deaths = 0, message = "",
  time = 0,            -- frames played on this level (kept across hot reloads, unlike world.frame())
  switches = {},       -- switch id -> true when on
  pendingToggles = {}, -- switch ids toggled during the frame, applied after it
  killed = false,
  input = { pressed = { left = false, right = false, up = false, down = false, jump = false, restart = false,
                        pause = false, reload = false },
            left = false, right = false, up = false, down = false, jump = false, restart = false, pause = false,
            reload = false },
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
  game.level = sandboxedModule(load(setup.level, levelApi), setup.level)
  game.Player = load(setup.player, game)
  game.progression = load(setup.progression, game) or {}
  game.mods = {}
  for i, path in ipairs(setup.mods) do game.mods[i] = sandboxedModule(load(path, levelApi), path) end
  if not game.level.start then  -- the level file's start, when the manifest names a level file
    local face, x, y = world.levelStart()
    if face then game.level.start = { face = face, x = x, y = y } end
  end
  if game.level.build then call(game.level.build, levelApi) end
end

function scene.start()
  local rules = load(setup.rules, game)
  if rules then engine.setRules(rules, not trusted(setup.rules)) end
  if game.progression.start then game.progression.start(game) end
end

function scene.beforeStep(held, pressed)
  local input = game.input
  decode(input, held)
  decode(input.pressed, pressed)
  if game.player and game.Player then game.Player.tick(game.player, input) end
  local frame = game.time + 1
  if game.level.tick then call(game.level.tick, levelApi, frame) end
  for i = 1, #game.mods do
    if game.mods[i].tick then call(game.mods[i].tick, levelApi, frame) end
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
  if game.level.save then saved.level = call(game.level.save, levelApi) end
  for i = 1, #game.mods do
    if game.mods[i].save then saved.mods[i] = call(game.mods[i].save, levelApi) end
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
  if game.level.onReload then call(game.level.onReload, levelApi, saved.level) end
  for i = 1, #game.mods do
    if game.mods[i].onReload then call(game.mods[i].onReload, levelApi, saved.mods[i]) end
  end
end

function scene.draw()
  if game.player and game.Player and game.Player.draw then game.Player.draw(game.player, platon.draw) end
  if game.level.draw then call(game.level.draw, levelApi, platon.draw) end
end

local status = {}
function scene.status()
  status.won, status.wonFrame, status.deaths, status.message = game.won, game.wonFrame, game.deaths, game.message
  status.time = game.time
  if game.player and world.valid(game.player.entity) then
    status.face, status.x, status.y = world.position(game.player.entity)
  end
  -- The doors the switches hold open (tag 1000 + n), for the renderer.
  local open = status.openTags or {}
  for i = #open, 1, -1 do open[i] = nil end
  for id, on in pairs(game.switches) do
    if on then open[#open + 1] = 1000 + id end
  end
  status.openTags = open
  return status
end

function scene.game() return game end

return scene
