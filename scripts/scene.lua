-- Drives a scene's scripts (trusted). The engine calls build, start, beforeStep, afterStep, draw
-- and status; this file loads the manifest's scripts and passes them the shared `game` state.
--   rules        returns a table of contact callbacks (docs/scripting.md, "Rules")
--   player       returns the Player module: spawn(game, face, x, y), tick(self, input), draw(self, draw)
--   progression  returns {start(game), afterStep(game), respawn(game)}: spawning, goal, deaths, checkpoints
--   level        returns {build(level), start = {face, x, y}, tick(level, frame), ...} (sandboxed)
--   mods         sandboxed scripts that return what a level script does: {build, tick, draw, save, onReload}
-- Which of them are trusted the manifest decided (setup.trusted), from what it wrote: only
-- "scripts/..." names an engine script.
local engine, setup = ...
-- Private copies: nothing a script does to a table can swap what this file calls.
local world, drawApi = platon.world, platon.draw
local valid, position, velocity, angle = world.valid, world.position, world.velocity, world.angle
local setVelocity = world.setVelocity
local subunit, setSubunit = world.subunit, world.setSubunit
local destroyEntity, levelStart, faceCount, faceOf = world.destroyEntity, world.levelStart, world.faceCount, world.face
local band, floor, type, tostring, error, pairs, ipairs, rawget, pcall, setmetatable, getmetatable =
      bit.band, math.floor, type, tostring, error, pairs, ipairs, rawget, pcall, setmetatable, getmetatable
local call, invoke, readonly = engine.call, engine.invoke, engine.readonly
local disabled, protect = engine.disabled, engine.protect

-- Level scripts and mods are sandboxed: their functions run with the JIT off (so the hooks can
-- stop any loop), each call through engine.call, a C function with its own error boundary and the
-- frame's time budget (LuaJIT stitches the trusted code's traces around it). Their tables are
-- read raw, once, so no metamethod of theirs ever runs outside a sandboxed call.
local HOOKS = { "build", "tick", "draw", "save", "onReload" }

-- A mod's line tags (docs/scripting.md, "Tags"): tags = { word = { look, passage, handlers } }.
-- Read raw, in word order (a table's own order differs between runs); checked here, so that a
-- wrong field is the mod's error by name. The look and passage go to the engine's tag table
-- (ScriptSystem::declareTags), the handlers stay here (composedRules).
local TAG_HANDLERS = { "contact", "beginContact", "overContact", "endContact", "touchContact" }
local MAX_TAGS = 64  -- a mod's own words

-- A mod's table of declarations (`tags`, `actions`), read raw: its keys, strings, in sorted order
-- (a table's own order differs between runs), at most `max`; nil when it has none.
local function declaredNames(t, path, section, keys, max, many)
  if t == nil then return nil end
  local at = path .. ": " .. section .. ": "
  if type(t) ~= "table" then error(at .. "expected a table of " .. keys .. ", got a " .. type(t), 0) end
  local names = {}
  for name in next, t do
    if type(name) ~= "string" then error(at .. "the keys are " .. keys .. ", got a " .. type(name), 0) end
    names[#names + 1] = name
    if #names > max then error(at .. "more than " .. max .. " " .. many, 0) end
  end
  table.sort(names)
  return names
end

-- The error of a declaration's field: "mod.lua: tags.spring.color: expected ..., got ...".
local function badField(path, section, name)
  return function(field, expected, v)
    local got = type(v) == "string" and string.format("%q", v:sub(1, 40)) or "a " .. type(v)
    error(path .. ": " .. section .. "." .. name .. (field and "." .. field or "") .. ": expected " .. expected
          .. ", got " .. got, 0)
  end
end

local function tagsOf(m, tags, path)
  local words = declaredNames(tags, path, "tags", "tag words", MAX_TAGS, "words")
  if not words then return end
  m.declared, m.handlers = {}, {}
  for _, word in ipairs(words) do
    local t = rawget(tags, word)
    local bad = badField(path, "tags", word)
    if type(t) ~= "table" then bad(nil, "a table { color =, passable =, contact = ... }", t) end
    local d = { owner = path, word = word, look = false, passage = "wall", r = 204, g = 121, b = 167 }
    local h = {}
    for field, v in next, t do
      if field == "color" then
        local r, g, b
        if type(v) == "string" then r, g, b = v:match("^#(%x%x)(%x%x)(%x%x)$") end
        if not r then bad(field, 'a colour "#rrggbb"', v) end
        d.r, d.g, d.b, d.look = tonumber(r, 16), tonumber(g, 16), tonumber(b, 16), true
      elseif field == "glow" or field == "spikes" or field == "numbered" then
        if type(v) ~= "boolean" then bad(field, "true or false", v) end
        d[field], d.look = v, true
      elseif field == "passable" then
        if type(v) == "boolean" then d.passage = v and "through" or "wall"
        elseif type(v) == "function" then d.passage, h.pierce = "door", v
        else bad(field, "true, false or a function(game, entity, tag, kind) deciding each contact", v) end
        d.look = true
      else
        local known = false
        for _, name in ipairs(TAG_HANDLERS) do known = known or name == field end
        if not known then
          bad(field, "one of color, glow, spikes, numbered, passable, " .. table.concat(TAG_HANDLERS, ", "),
              field)
        end
        if type(v) ~= "function" then bad(field, "a function", v) end
        h[field] = v
      end
    end
    m.declared[#m.declared + 1] = d
    m.handlers[word] = h
  end
end

-- A mod's actions (docs/scripting.md, "Actions"): actions = { dash = { keys =, pad =, label =,
-- does = } }, read raw in name order and checked here; the engine's action table takes the names
-- (ScriptSystem::declareTags refuses one taken), and the `input` table has them from then on.
local MAX_ACTIONS = 8

local function namesOf(v, bad, field)
  if type(v) ~= "table" then bad(field, "a list of names", v) end
  local out = {}
  for i = 1, 9 do
    local name = rawget(v, i)
    if name == nil then break end
    if type(name) ~= "string" or #name > 40 then
      bad(field .. "[" .. i .. "]", "a name (\"Left Shift\", \"x\")", name)
    end
    if i == 9 then bad(field, "at most 8 names", v) end
    out[i] = name
  end
  return out
end

local function actionsOf(m, actions, path)
  local names = declaredNames(actions, path, "actions", "action names", MAX_ACTIONS, "actions")
  if not names then return end
  m.actions = {}
  for _, name in ipairs(names) do
    local t = rawget(actions, name)
    local bad = badField(path, "actions", name)
    if type(t) ~= "table" then bad(nil, "a table { keys =, pad =, label =, does = }", t) end
    local a = { owner = path, name = name, label = name, does = "", keys = {}, pad = {} }
    for field, v in next, t do
      if field == "keys" or field == "pad" then a[field] = namesOf(v, bad, field)
      elseif field == "label" or field == "does" then
        if type(v) ~= "string" or #v > 80 then bad(field, "a string of at most 80 bytes", v) end
        a[field] = v
      else bad(field, "one of keys, pad, label, does", field) end
    end
    m.actions[#m.actions + 1] = a
  end
end

local function sandboxedModule(t, path, id)
  if t == nil then return { id = id, name = path } end
  if type(t) ~= "table" then error(path .. ": a level script or mod returns a table", 0) end
  local m = { id = id, name = path }
  for _, name in ipairs(HOOKS) do
    local f = rawget(t, name)
    if type(f) == "function" then m[name] = f end
  end
  local start = rawget(t, "start")
  if type(start) == "table" then
    m.start = { face = tonumber(rawget(start, "face")), x = tonumber(rawget(start, "x")),
                y = tonumber(rawget(start, "y")) }
  end
  tagsOf(m, rawget(t, "tags"), path)
  actionsOf(m, rawget(t, "actions"), path)
  return m
end

-- A module's hook, behind its own error boundary: a failing module does not stop the others (its
-- error is reported with the frame's), and one a limit stopped is dropped for good.
local function run(m, hook, ...)
  local f = m[hook]
  if f == nil then return nil end
  local ok, result = call(m.id, f, ...)
  if ok then return result end
  if disabled(m.id) then
    for _, name in ipairs(HOOKS) do m[name] = nil end
  end
  return nil
end

-- A level's own player or progression script (sandboxed) is the game's logic, so it gets the game
-- state; its functions run as sandboxed code (engine.invoke: the budget and the memory limit, and
-- their errors raised as if called directly).
-- A function a sandbox can call runs inside its budget, where each interpreted instruction is a
-- step: it runs interpreted too (a trace the JIT compiled would run uncounted, and whether one is
-- compiled differs from one process to the next, which would make a stop differ between runs).
local function interpreted(f)
  jit.off(f, true)
  return f
end

-- A sandboxed module's functions, each called as its code (engine.invoke); `after(f)`, when
-- given, runs after each call returns (the checks of what the call wrote in `game`).
local function sandboxedFunctions(t, id, checks)
  if type(t) ~= "table" then return t end
  local wrapped = {}
  for k, v in pairs(t) do
    if type(v) == "function" then
      local f = v
      if checks then  -- checks.before() ahead of each call, checks.after(f) once it returned
        local function finish(...)
          checks.after(f)
          return ...
        end
        wrapped[k] = interpreted(function(...)
          checks.before()
          return finish(invoke(id, f, ...))
        end)
      else
        wrapped[k] = interpreted(function(...) return invoke(id, f, ...) end)
      end
    else
      wrapped[k] = v
    end
  end
  return wrapped
end

-- What this file dispatches on, kept here and never read back from `game`: a level's own player
-- or progression script (sandboxed) is handed the game state and may write to it, so a function
-- found in `game` later could be its own, called outside its limits.
local Level, Mods, PlayerModule, Progression = { name = "" }, {}, nil, {}

-- A module as other scripts see it in `game` (game.Player, game.progression): its functions, none
-- of it writable, nested tables too (Player.__index is Player itself).
local function sealed(t, name, seen)
  if type(t) ~= "table" then return t end
  seen = seen or {}
  if seen[t] then return seen[t] end
  local entries = {}
  local view = setmetatable({}, {
    __index = entries,
    __newindex = interpreted(function(_, k) error(name .. " is read-only (tried to set " .. tostring(k) .. ")", 2) end),
    __metatable = "locked",
  })
  seen[t] = view
  for k, v in pairs(t) do entries[k] = sealed(v, name .. "." .. tostring(k), seen) end
  return view
end

local function load(path, trusted, ...)
  if path == nil or path == "" then return nil end
  return engine.load(path, trusted, ...)
end

-- The `input` table's names, by their InputFrame bits: the engine's actions (core/actions.h), then
-- those the mods add. The decoder is compiled from the names with constant keys, which the JIT
-- turns into direct slots (a loop over names costs a hash lookup each).
local function decoder(names)
  local lines = { "local band = ... return function(t, bits)" }
  for i, name in ipairs(names) do lines[#lines + 1] = ("t[%q] = band(bits, %d) ~= 0"):format(name, 2 ^ (i - 1)) end
  lines[#lines + 1] = "end"
  return assert(loadstring(table.concat(lines, "\n"), "=input decoder"))(band)
end
local ACTIONS = {}
for i, name in ipairs(setup.actions) do ACTIONS[i] = name end
local decode = decoder(ACTIONS)
local function newInput()
  local input = { pressed = {} }
  for _, name in ipairs(ACTIONS) do input[name], input.pressed[name] = false, false end
  return input
end

local game = {
  name = setup.name,
  won = false, wonFrame = 0, deaths = 0, message = "",
  time = 0,            -- frames played on this level (kept across hot reloads, unlike world.frame())
  switches = {},       -- switch id -> true when on
  openSwitches = {},   -- the ids of the switches on, increasing (progression keeps it)
  pendingToggles = {}, -- switch ids toggled during the frame, applied after it
  killed = false,
  input = newInput(),
}

-- With a level's own player or progression script (sandboxed, handed `game`), the game state's
-- own tables keep their metatables (none), so it cannot make reading them run its code. Only
-- then: a metatable, even one with no metamethods, slows every access the JIT compiles (the
-- engine's own scripts alone: 1.45 times the C++ game's frame; locked: 1.59).
local LOCKED = { __metatable = "locked" }
local function lock(t) if type(t) == "table" and getmetatable(t) == nil then setmetatable(t, LOCKED) end return t end
local anyGameLogicSandboxed = not (setup.trusted.player and setup.trusted.progression)
local function lockGameTables()
  if not anyGameLogicSandboxed then return end
  lock(game)
  lock(game.input)
  lock(game.input.pressed)
  lock(game.switches)
  lock(game.pendingToggles)
end
lockGameTables()

-- What the engine reads in `game` after a level's own player or progression script (sandboxed,
-- handed `game`) ran: checked raw after each of its calls. The engine reads these fields with
-- arithmetic, comparisons and indexing, so a value of another kind (a table whose __add loops, a
-- table with an __index) would run that script's code outside its limits: it is the script's
-- error, at its function's line, and the field is set back to what it was.
local function wholeNumber(v) return type(v) == "number" and v == floor(v) and v >= 0 and v < 2 ^ 53 end
local function isBoolean(v) return type(v) == "boolean" end
local function isString(v) return type(v) == "string" end
local function orNil(check) return function(v) return v == nil or check(v) end end
local rawmeta = debug.getmetatable
local function plainTable(v) return type(v) == "table" and (rawmeta(v) == nil or rawmeta(v) == LOCKED) end
local function isTable(v) return type(v) == "table" end
local function listOfWholes(v)  -- switch ids: at most 1000 of them
  if not plainTable(v) then return false end
  local n = 0
  for k, x in next, v do
    n = n + 1
    if n > 1000 or type(k) ~= "number" or not wholeNumber(x) then return false end
  end
  return true
end
local function checkpointPlace(v)
  return v == nil or (plainTable(v) and type(rawget(v, "face")) == "number" and type(rawget(v, "x")) == "number"
                      and type(rawget(v, "y")) == "number")
end
local GAME_FIELDS = {
  time = { wholeNumber, "a whole number" }, deaths = { wholeNumber, "a whole number" },
  wonFrame = { wholeNumber, "a whole number" }, won = { isBoolean, "a boolean" },
  killed = { isBoolean, "a boolean" }, message = { isString, "a string" },
  reachedGoal = { orNil(isBoolean), "a boolean" }, touchedCheckpoint = { orNil(isBoolean), "a boolean" },
  restoredPlayer = { orNil(isBoolean), "a boolean" }, switches = { plainTable, "a table with no metatable" },
  openSwitches = { listOfWholes, "a list of switch ids" }, pendingToggles = { listOfWholes, "a list of switch ids" },
  checkpoint = { checkpointPlace, "nil or a table { face =, x =, y = } of numbers" },
  player = { orNil(isTable), "nil or a table" },  -- the player module's object: the engine reads it raw
}
local gameGood = {}  -- the values before the call, to set a wrong one back to
local engineTables = {}  -- the engine's own tables in `game`, which must stay themselves
local function gameRemembered()
  for key, rule in pairs(GAME_FIELDS) do
    local v = rawget(game, key)
    if rule[1](v) then gameGood[key] = v end
  end
end
interpreted(gameRemembered)
local function gameChecked(f)
  local problem
  for key, rule in pairs(GAME_FIELDS) do
    local v = rawget(game, key)
    if rule[1](v) then
      gameGood[key] = v
    else
      problem = problem or ("game." .. key .. " was left " .. (type(v) == "table" and "a table of another kind"
                or ("a " .. type(v))) .. ", where the engine reads " .. rule[2] .. "; it is set back")
      rawset(game, key, gameGood[key])
    end
  end
  for key, t in pairs(engineTables) do
    if rawget(game, key) ~= t then
      problem = problem or ("game." .. key .. " is the engine's: it was replaced; it is set back")
      rawset(game, key, t)
    end
  end
  if problem then
    local info = debug.getinfo(f, "S")
    error(info.short_src .. ":" .. info.linedefined .. ": " .. problem, 0)
  end
end
interpreted(gameChecked)
local GAME_CHECKS = { before = gameRemembered, after = gameChecked }

-- The player's entity, read raw (the player table may be a sandboxed script's).
local function playerEntity()
  local p = rawget(game, "player")
  return type(p) == "table" and rawget(p, "entity") or nil
end

-- What level scripts and mods may do to the game, checked here: a bad value is an error at the
-- script's own line, never a broken game later.
local MESSAGE_BYTES = 200
local COORDINATE = 2 ^ 30 - 1

local function shown(v)
  if type(v) == "number" then return tostring(v) end
  if type(v) == "string" then return string.format("%q", v:sub(1, 40)) end
  return "a " .. type(v)
end

local function checkSwitch(what, id)
  if type(id) ~= "number" or id ~= floor(id) or id < 1 or id > 999 then
    error(what .. ": expected a switch id, an integer 1..999, got " .. shown(id), 3)
  end
end

local faces  -- the stage's face ids, as a set (read once, when a checkpoint is first set)
local function checkCoordinate(what, name, v)
  if type(v) ~= "number" or v ~= floor(v) or v < -COORDINATE or v > COORDINATE then
    error(what .. ": " .. name .. ": expected an integer within +-(2^30 - 1), got " .. shown(v), 3)
  end
end

local showValue = engine.tostring  -- the sandboxes' tostring: no address (it would differ between runs)
local levelApi = {
  message = function(text)
    text = showValue(text)
    if #text > MESSAGE_BYTES then  -- cut at a character boundary (UTF-8)
      local cut = MESSAGE_BYTES
      while cut > 0 and band(text:byte(cut + 1), 0xC0) == 0x80 do cut = cut - 1 end
      text = text:sub(1, cut) .. "..."
    end
    game.message = text
  end,
  switchOn = function(id)
    checkSwitch("switchOn", id)
    return game.switches[id] == true
  end,
  toggle = function(id)
    checkSwitch("toggle", id)
    game.pendingToggles[#game.pendingToggles + 1] = id
  end,
  kill = function() game.killed = true end,
  checkpoint = function(face, x, y)
    if not faces then
      faces = {}
      for i = 1, faceCount() do faces[(faceOf(i))] = true end
    end
    if type(face) ~= "number" or not faces[face] then
      error("checkpoint: face: expected a face of this stage, got " .. shown(face), 2)
    end
    checkCoordinate("checkpoint", "x", x)
    checkCoordinate("checkpoint", "y", y)
    game.checkpoint = { face = face, x = x, y = y }
  end,
  frame = function() return game.time end,  -- frames played: kept across hot reloads
  player = function()  -- playerEntity's body again: that one runs compiled for the engine's own calls
    local p = rawget(game, "player")
    return type(p) == "table" and rawget(p, "entity") or nil
  end,
  won = function() return game.won end,
}
game.levelApi = levelApi

-- Sandboxes call them, and so what they call: every Lua function a sandbox's call can reach runs
-- interpreted (sandbox_fuzz found two runs of one program stopped at different lines: a helper the
-- JIT compiled in one process ran uncounted there). A helper the engine's own per-frame code also
-- calls is not shared (playerEntity): interpreted, it doubled the Lua game's frame (script_frames).
for _, f in pairs(levelApi) do interpreted(f) end
for _, f in ipairs { shown, checkSwitch, checkCoordinate } do interpreted(f) end

-- The sandboxes' views: read-only, the world's too (platon.world as every sandbox sees it).
local worldView = readonly(engine.sandboxApi().world, "game.world")
levelApi.world = worldView
local levelView = readonly(levelApi, "game")
-- A sandboxed rules script: the same, and what the game's own rules do to the game.
local rulesApi = {}
for k, v in pairs(levelApi) do rulesApi[k] = v end
rulesApi.reachGoal = function() game.reachedGoal = true end
rulesApi.touchCheckpoint = function() game.touchedCheckpoint = true end
interpreted(rulesApi.reachGoal)
interpreted(rulesApi.touchCheckpoint)
local rulesView = readonly(rulesApi, "game")
local drawView = readonly(drawApi, "draw")

-- The player's entity is the game's: a sandbox may not destroy or erase it (world_api.cpp).
local protected
local function protectPlayer()
  local e = playerEntity()
  if e ~= protected then
    protect(e)
    protected = e
  end
end

local scene = {}

-- The mods, loaded once, before the level file is read: their tags are words it may write.
local modsLoaded = false
local function loadMods()
  if modsLoaded then return end
  modsLoaded = true
  Mods = {}
  for i, path in ipairs(setup.mods) do
    local mod, id = load(path, false, levelView)
    Mods[i] = sandboxedModule(mod, path, id)
  end
end

-- What the mods declare of their tags and actions, in the manifest's order, for the engine's tag
-- and action tables.
function scene.declare()
  loadMods()
  local out, actions = {}, {}
  for _, m in ipairs(Mods) do
    for _, d in ipairs(m.declared or {}) do out[#out + 1] = d end
    for _, a in ipairs(m.actions or {}) do actions[#actions + 1] = a end
  end
  return out, actions
end

-- The engine took the mods' actions (in declare's order, after its own): `input` has them now.
function scene.setActions(names)
  for i = #setup.actions + 1, #names do
    ACTIONS[i] = names[i]
    game.input[names[i]], game.input.pressed[names[i]] = false, false
  end
  decode = decoder(ACTIONS)
end

-- `frames`: the level's frames played so far, carried over a hot reload (0 on a fresh load), so
-- that the new version's build sees game.frame() where the old one was.
function scene.build(frames)
  game.time = frames or 0
  local level, levelId = load(setup.level, setup.trusted.level, levelView)
  if setup.trusted.level then Level = sandboxedModule(level, setup.level, nil) -- an engine script as the level
  else Level = sandboxedModule(level, setup.level, levelId) end
  if not Level.start then  -- the level file's start, when the manifest names a level file
    local face, x, y = levelStart()
    if face then Level.start = { face = face, x = x, y = y } end
  end
  -- What the player and progression scripts see of the level: its start, as data.
  local start = Level.start
  game.level = { start = start and { face = start.face, x = start.x, y = start.y } }
  -- A level's own player script gets the game's player to build on (its second argument): a copy
  -- of scripts/player.lua run in a sandbox of its own, so that what the level changes in it stays
  -- the level's and its functions run inside the level's limits.
  local base = not setup.trusted.player and setup.player ~= "" and engine.load("scripts/player.lua", "base", game)
  -- With either of them sandboxed, the engine's own other one is within its reach (game.Player,
  -- game.progression): it then runs as a base does, sandboxed. Trusted, the JIT would compile it
  -- after a few calls from the sandbox and run it uncounted (a loop of calls to game.progression's
  -- spawnPoint fit as many in the budget as calls of an empty function), and whether and when
  -- that happens differs between processes.
  local playerTrusted = setup.trusted.player and not anyGameLogicSandboxed
  local progressionTrusted = setup.trusted.progression and not anyGameLogicSandboxed
  local function how(trusted, trustedByManifest) return trusted or (trustedByManifest and "base") end
  local Player, playerId = load(setup.player, how(playerTrusted, setup.trusted.player), game, base or nil)
  PlayerModule = playerTrusted and Player or sandboxedFunctions(Player, playerId, GAME_CHECKS)
  game.Player = sealed(PlayerModule, "game.Player")
  local progression, progressionId = load(setup.progression, how(progressionTrusted, setup.trusted.progression), game)
  Progression = (progressionTrusted and progression or sandboxedFunctions(progression, progressionId,
                                                                          GAME_CHECKS)) or {}
  game.progression = sealed(Progression, "game.progression")
  for _, key in ipairs { "input", "levelApi", "Player", "progression", "level" } do
    engineTables[key] = rawget(game, key)
  end
  for key, rule in pairs(GAME_FIELDS) do
    if rule[1](rawget(game, key)) then gameGood[key] = rawget(game, key) end
  end
  loadMods()
  if Level.id then run(Level, "build", levelView)
  elseif Level.build then Level.build(levelView) end
  for i = 1, #Mods do run(Mods[i], "build", levelView) end  -- after the level's, in the manifest's order
end

-- The rules as the world calls them when mods declare tags or handlers: the rules script's
-- callback first, then each mod's handler for the contact's tag, in the manifest's order; the
-- last answer that is not nil is the contact's. Whether a line is passed is its tag's owner's
-- say: the rules' for the game's tags, a mod's `passable` for its own.
-- Why a contact answer is none the world takes (nil when it is one): nil, a boolean, or a table
-- { slide =, keepVelocity =, restitution = 0..1 }. A handler's bad answer is its own error, by its
-- file's name (the world, given it, could only blame this file).
local function badContactAnswer(a)
  if a == nil or a == true or a == false then return nil end
  if type(a) ~= "table" then
    return "returned a " .. type(a) .. "; return nothing, false, or {slide =, keepVelocity =, restitution =}"
  end
  local r = rawget(a, "restitution")
  if r ~= nil and (type(r) ~= "number" or not (r >= 0 and r <= 1)) then return "returned restitution outside [0, 1]" end
  return nil
end

local function composedRules(rules, rulesId)
  local tags, kinds = platon.tags, platon.tagKinds
  local byTag, passOf, any = {}, {}, false  -- a kind's number -> its handlers; its own passage
  for _, m in ipairs(Mods) do
    for _, d in ipairs(m.declared or {}) do
      any = true
      local h = m.handlers[d.word]
      local n = tags[d.word]
      if d.look then passOf[n] = h.pierce and { m = m, f = h.pierce } or d.passage == "through" end
      local list = byTag[n] or {}
      byTag[n] = list
      list[#list + 1] = { m = m, h = h }
    end
  end
  if not any then return nil end
  local ranges = {}  -- the numbered kinds that have handlers or a passage of a mod's
  for _, k in ipairs(kinds) do
    if k.count > 0 and (byTag[k.number] or passOf[k.number] ~= nil) then
      ranges[#ranges + 1] = { k.number, k.number + k.count }
    end
  end
  -- A tag's kind, looked for once per tag (the physics asks on every contact, and mods may declare
  -- thousands of numbered kinds): then read from a table.
  local kindOfTag, kindOfTagCount = {}, 0
  local function kindOf(tag)
    local known = kindOfTag[tag]
    if known then return known end
    known = tag
    if not (byTag[tag] or passOf[tag] ~= nil) then
      for i = 1, #ranges do
        local r = ranges[i]
        if tag > r[1] and tag <= r[2] then
          known = r[1]
          break
        end
      end
    end
    kindOfTagCount = kindOfTagCount + 1
    if kindOfTagCount > 65536 then  -- tags made by scripts are any numbers: the memo stays bounded
      kindOfTag, kindOfTagCount = {}, 1
    end
    kindOfTag[tag] = known
    return known
  end
  local function ruleOf(name)  -- the rules' callback, raw, called as its script's
    local f = rules and rawget(rules, name)
    if type(f) ~= "function" or not rulesId then return type(f) == "function" and f or nil end
    return function(...)
      local ok, r = call(rulesId, f, ...)
      if ok then return r end
    end
  end
  local out = {}
  local rulesPierce = ruleOf("pierce")
  out.pierce = function(entity, tag, kind, part, line)
    local own = passOf[kindOf(tag)]
    if own == nil then
      if rulesPierce then return rulesPierce(entity, tag, kind, part, line) end
      return kind == "warp"
    end
    if own == true or own == false then return own end
    local ok, r = call(own.m.id, own.f, levelView, entity, tag, kind, part, line)
    return ok and r == true
  end
  for _, name in ipairs(TAG_HANDLERS) do
    local rule = ruleOf(name)
    out[name] = function(entity, tag, ...)
      local answer
      if rule then answer = rule(entity, tag, ...) end
      local list = byTag[kindOf(tag)]
      if list then
        for i = 1, #list do
          local f = list[i].h[name]
          if f then
            local m = list[i].m
            local ok, a = call(m.id, f, levelView, entity, tag, ...)
            local why = ok and name == "contact" and badContactAnswer(a)
            if why then  -- the mod's error, kept as its own (raised in its sandbox), and no answer
              call(m.id, error, "the contact handler of tag " .. tostring(tag) .. " " .. why, 0)
            elseif ok and a ~= nil then
              answer = a
            end
          end
        end
      end
      return answer
    end
  end
  out.crushed = ruleOf("crushed")
  return out
end

function scene.start()
  local rules, id
  if setup.trusted.rules then rules = load(setup.rules, true, game)
  else rules, id = load(setup.rules, false, rulesView) end
  local composed = composedRules(rules, id)
  if composed then engine.setRules(composed, nil, setup.rules)
  elseif rules then engine.setRules(rules, id, setup.rules) end
  if Progression.start then Progression.start(game) end
  protectPlayer()
end

local function tickLevel(m, frame)
  if m.id then return run(m, "tick", levelView, frame) end
  return m.tick(levelView, frame)
end

function scene.beforeStep(held, pressed)
  local input = game.input
  decode(input, held)
  decode(input.pressed, pressed)
  if rawget(game, "player") and not valid(playerEntity()) and Progression.respawn then
    -- Lost (nothing a sandbox may do destroys it): once, back at the last checkpoint.
    game.player = nil
    Progression.respawn(game)
    game.message = rawget(game, "player") and "the player was lost: back at the last checkpoint"
                   or "the player was lost"
    protectPlayer()
  end
  local p = rawget(game, "player")
  if p and PlayerModule then PlayerModule.tick(p, input) end
  local frame = game.time + 1
  if Level.tick then tickLevel(Level, frame) end
  local mods = Mods
  for i = 1, #mods do
    if mods[i].tick then run(mods[i], "tick", levelView, frame) end
  end
end

function scene.afterStep()
  game.time = game.time + 1
  if Progression.afterStep then Progression.afterStep(game) end
  if playerEntity() ~= protected then protectPlayer() end
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

local function moduleHook(m, hook, ...)
  if m.id then return run(m, hook, ...) end
  if m[hook] then return m[hook](...) end
end

function scene.save()
  local saved = { game = {}, mods = {} }
  for _, key in ipairs(KEPT) do saved.game[key] = game[key] end
  local p, e = rawget(game, "player"), playerEntity()
  if e and valid(e) then
    local face, x, y = position(e)
    local vx, vy = velocity(e)
    local sx, sy = subunit(e)
    saved.player = { face = face, x = x, y = y, vx = vx, vy = vy, sx = sx, sy = sy, angle = angle(e),
                     state = PlayerModule.save and PlayerModule.save(p) or plainFields(p) }
  end
  saved.level = moduleHook(Level, "save", levelView)
  for i = 1, #Mods do saved.mods[i] = run(Mods[i], "save", levelView) end
  return saved
end

-- Puts the player back where it was; where the new level has a wall there (or the face is gone),
-- it stays at the level start where progression.start() put it.
local function restorePlayer(saved)
  if not saved or not rawget(game, "player") then return false end
  local old = playerEntity()
  local ok, player = pcall(PlayerModule.spawn, game, saved.face, saved.x, saved.y, saved.angle)
  if not ok or type(player) ~= "table" then return false end
  if old and valid(old) then destroyEntity(old) end  -- only now: the new one is in the world
  game.player = player
  setVelocity(rawget(player, "entity"), saved.vx, saved.vy)
  setSubunit(rawget(player, "entity"), saved.sx or 0, saved.sy or 0)  -- where within its unit: exact
  if PlayerModule.onReload then PlayerModule.onReload(player, saved.state)
  else
    -- Raw: the player object may be a sandboxed script's, with metamethods of its own.
    for k, v in pairs(saved.state or {}) do
      if k ~= "entity" and type(rawget(player, k)) == type(v) then rawset(player, k, v) end
    end
  end
  return true
end

function scene.restore(saved)
  local newMessage = game.message  -- what the new version's build said, if anything, wins
  for _, key in ipairs(KEPT) do
    if saved.game[key] ~= nil then game[key] = saved.game[key] end
  end
  lockGameTables()
  if newMessage ~= "" then game.message = newMessage end
  if Progression.onReload then Progression.onReload(game) end
  game.restoredPlayer = restorePlayer(saved.player)
  if not game.restoredPlayer and saved.player then
    game.message = "reloaded: the player's place is gone, back to the start"
  end
  protectPlayer()
  moduleHook(Level, "onReload", levelView, saved.level)
  for i = 1, #Mods do run(Mods[i], "onReload", levelView, saved.mods[i]) end
end

function scene.draw()
  local p = rawget(game, "player")
  if p and PlayerModule and PlayerModule.draw then
    PlayerModule.draw(p, setup.trusted.player and drawApi or drawView)
  end
  if Level.draw then moduleHook(Level, "draw", levelView, drawView) end
  for i = 1, #Mods do run(Mods[i], "draw", levelView, drawView) end
end

local status = {}
function scene.status()
  status.won, status.wonFrame, status.deaths, status.message = game.won, game.wonFrame, game.deaths, game.message
  status.time = game.time
  local e = playerEntity()
  if e and valid(e) then
    status.face, status.x, status.y = position(e)
    status.vx, status.vy = velocity(e)
  end
  local p = rawget(game, "player")
  status.grounded = type(p) == "table" and rawget(p, "grounded") == true
  -- Raw reads: the tables may have been left by a script, with metamethods of its own.
  local c = rawget(game, "checkpoint")
  local cf, cx, cy
  if type(c) == "table" then cf, cx, cy = rawget(c, "face"), rawget(c, "x"), rawget(c, "y") end
  if type(cf) == "number" and type(cx) == "number" and type(cy) == "number" then
    status.checkpointFace, status.checkpointX, status.checkpointY = cf, cx, cy
  else
    status.checkpointFace = nil
  end
  -- The doors the switches hold open (door n), for the renderer, in increasing order.
  local open = status.openTags or {}
  for i = #open, 1, -1 do open[i] = nil end
  local on, door = game.openSwitches, platon.tags.door
  for i = 1, #on do open[i] = door + on[i] end
  status.openTags = open
  return status
end

function scene.game() return game end
function scene.levelView() return levelView end  -- the game's console hands it to what is typed
function scene.levelSandbox() return Level.id end  -- and runs it in the level script's globals
function scene.frame() return game.time end
-- What `platon defs` writes besides the bindings: the `input` table's names, the hooks a level
-- script or mod may return, a tag's handlers, and the game's player (a fresh copy: its constants
-- and the functions a level's own player replaces).
function scene.definitionsData()
  return { actions = ACTIONS, hooks = HOOKS, tagHandlers = TAG_HANDLERS,
           player = engine.load("scripts/player.lua", true, game) }
end

return scene
