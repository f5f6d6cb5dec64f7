-- The Lua language server's definitions (---@meta) of one set of the scripting API, written from
-- the live binding tables (trusted: the engine's `platon`; sandboxed: the `platon` a sandbox sees
-- and the `game` level scripts and mods are handed) with each function's entry in
-- api_signatures.lua. Returns the text and the problems: a binding with no entry, an entry with
-- no binding. Run by `platon defs` (ScriptSystem::definitions).
local api, levelApi, signatures, sandboxed, data, actionDocs = ...
local out, problems, seen = {}, {}, {}
local function emit(line) out[#out + 1] = line end

local function sortedKeys(t)
  local keys = {}
  for k in pairs(t) do keys[#keys + 1] = k end
  table.sort(keys, function(a, b) return tostring(a) < tostring(b) end)
  return keys
end

-- "a: T, b?: {x: U, y: V}" -> { "a: T", "b?: {x: U, y: V}" }: commas inside braces stay.
local function split(text)
  local parts, depth, start = {}, 0, 1
  for i = 1, #text do
    local c = text:sub(i, i)
    if c == "{" or c == "(" or c == "[" then depth = depth + 1
    elseif c == "}" or c == ")" or c == "]" then depth = depth - 1
    elseif c == "," and depth == 0 then
      parts[#parts + 1] = text:sub(start, i - 1):match("^%s*(.-)%s*$")
      start = i + 1
    end
  end
  local last = text:sub(start):match("^%s*(.-)%s*$")
  if last ~= "" then parts[#parts + 1] = last end
  return parts
end

-- One function's definition: `params` "a: T, b?: U", `returns` "T1 name, T2" (each its own line).
local function emitFunction(owner, name, params, returns, doc)
  emit("")
  if doc then emit("--- " .. doc) end
  local names = {}
  for _, p in ipairs(split(params)) do
    local n, optional, t = p:match("^([%w_]+)(%??):%s*(.+)$")
    if n then
      emit("---@param " .. n .. optional .. " " .. t)
      names[#names + 1] = n
    end
  end
  for _, r in ipairs(split(returns)) do emit("---@return " .. r) end
  emit("function " .. owner .. "." .. name .. "(" .. table.concat(names, ", ") .. ") end")
end

local function functionOf(path, owner, name)
  local s = signatures[path]
  if not s then
    problems[#problems + 1] = path .. ": a binding with no definition (engine/script/lua/api_signatures.lua)"
    return
  end
  seen[path] = true
  emitFunction(owner, name, s[1], s[2], s[3])
end

emit("---@meta")
emit("-- The Lua language server's definitions of Platon's scripting API for "
     .. (sandboxed and "level scripts, mods and a level's own rules and player (sandboxed)"
         or "the engine's own scripts (trusted)") .. ".")
emit("-- Written by `platon defs` from the engine's binding tables: do not edit (docs/scripting.md, "
     .. "\"Editors\").")
emit("")
emit("---@class platon")
emit("platon = {}")
for _, key in ipairs(sortedKeys(api)) do
  local v = api[key]
  if key == "tags" then
    emit("")
    emit("--- Each line tag's number by its word (the game's and the mods'): platon.tags.hazard.")
    emit("---@type table<string, integer>")
    emit("platon.tags = {}")
  elseif key == "tagKinds" then
    emit("")
    emit("---@class platon.TagKind")
    emit("---@field word string")
    emit("---@field number integer the tag, or a numbered kind's base")
    emit("---@field count integer 0, or 999 for a word that takes a number")
    emit("---@field passable \"wall\"|\"through\"|\"door\"")
    emit("---@field color string \"#rrggbb\"")
    emit("---@field glow boolean")
    emit("---@field spikes boolean")
    emit("---@field owner string \"the game\", or a mod's file")
    emit("")
    emit("--- The line tags' kinds, in the table's order.")
    emit("---@type platon.TagKind[]")
    emit("platon.tagKinds = {}")
  elseif type(v) == "table" then
    emit("")
    emit("---@class platon." .. key)
    emit("platon." .. key .. " = {}")
    for _, name in ipairs(sortedKeys(v)) do
      if type(v[name]) == "function" then functionOf("platon." .. key .. "." .. name, "platon." .. key, name) end
    end
  elseif type(v) == "function" then
    functionOf("platon." .. key, "platon", key)
  end
end

if sandboxed then
  emit("")
  emit("--- What level scripts, mods and a level's own rules are handed as `game` (their hooks' first")
  emit("--- argument): annotate it with ---@param game platon.Game.")
  emit("---@class platon.Game")
  emit("---@field world platon.world the world, read-only as a table")
  emit("local Game = {}")
  for _, name in ipairs(sortedKeys(levelApi)) do
    if type(levelApi[name]) == "function" then functionOf("game." .. name, "Game", name) end
  end
end

-- The `input` table a player's tick is handed: the scene's actions (core/actions.h), by name.
emit("")
emit("--- The actions held this frame (a player's tick's `input`), the engine's and the scene's mods':")
emit("--- `input.jump`; `input.pressed.jump` went down on this frame.")
emit("---@class platon.Input")
for i, name in ipairs(data.actions) do emit("---@field " .. name .. " boolean " .. (actionDocs[i] or "")) end
emit("---@field pressed platon.Input the actions that went down on this frame")
emit("")
emit("--- A mod's action (its table's `actions`): keys and pad buttons by SDL's names.")
emit("---@class platon.ActionDeclaration")
emit("---@field keys? string[] default keys (\"Left Shift\", \"X\"), at most 8")
emit("---@field pad? string[] default pad buttons (\"x\", \"rightshoulder\"), at most 8")
emit("---@field label? string the settings screen's name for it (default: its name)")
emit("---@field does? string one line: what it does")

-- What a level script or mod returns (docs/scripting.md, "The level script", "Tags", "Actions").
emit("")
emit("--- A tag a mod declares (its table's `tags`): its look, its passage and its handlers.")
emit("---@class platon.TagDeclaration")
emit("---@field color? string \"#rrggbb\"")
emit("---@field glow? boolean drawn unlit and bright")
emit("---@field spikes? boolean a row of spikes along its top")
emit("---@field numbered? boolean the word takes a number 1..999")
emit("---@field passable? boolean|fun(game: platon.Game, entity: integer, tag: integer, kind: integer): boolean")
for _, name in ipairs(data.tagHandlers) do
  emit("---@field " .. name .. "? fun(game: platon.Game, entity: integer, tag: integer, kind: integer, ...): table?")
end
emit("")
emit("--- What a level script or a mod returns.")
emit("---@class platon.Module")
for _, name in ipairs(data.hooks) do
  emit("---@field " .. name .. "? fun(game: platon.Game, ...): any the " .. name .. " hook")
end
emit("---@field start? {face: integer, x: number, y: number} where the player starts")
emit("---@field tags? table<string, platon.TagDeclaration> a mod's line tags")
emit("---@field actions? table<string, platon.ActionDeclaration> a mod's actions")

-- The game's player, which a level's own player is handed to extend (docs/scripting.md, "The player").
emit("")
emit("--- The game's player (scripts/player.lua): a level's own player is handed a copy to extend.")
emit("---@class platon.Player")
emit("---@field entity integer its body")
emit("---@field grounded boolean it stands on something")
emit("---@field wall integer the way off a wall it touches: 1 right, -1 left, 0 none")
emit("---@field facing integer the way it last walked: 1 right, -1 left")
emit("---@field downX number the face's down this frame (a unit vector)")
emit("---@field downY number")
emit("---@field rightX number the face's right this frame (down turned a quarter)")
emit("---@field rightY number")
emit("---@field jumping boolean rising from its own jump (the jump cut applies)")
emit("---@field coyote integer frames a jump still works after leaving a ledge")
emit("---@field buffer integer frames a pressed jump waits for the ground")
emit("---@field fall number the fall speed last frame (+ down)")
emit("local Player = {}")
for _, name in ipairs(sortedKeys(data.player)) do
  local v = data.player[name]
  if type(v) == "number" then
    emit("Player." .. name .. " = " .. tostring(v))
  end
end
local PLAYER_FUNCTIONS = {
  spawn = { "game: platon.Game, face: integer, x: number, y: number, degrees?: number", "platon.Player" },
  tick = { "self: platon.Player, input: platon.Input", "" },
  canJump = { "self: platon.Player", "boolean" },
  jump = { "self: platon.Player, along: number", "number along, number fall" },
  move = { "self: platon.Player, input: platon.Input, along: number, fall: number", "number along, number fall" },
  draw = { "self: platon.Player, draw: platon.draw", "" },
}
-- Hooks the game's player has none of, which a level's own may define (scene.lua asks for them).
local OPTIONAL = {
  save = { "self: platon.Player", "table", "what a hot reload carries to the new version (default: its plain fields)" },
  onReload = { "self: platon.Player, state: table", "", "the new version's player given what save returned" },
}
for _, name in ipairs(sortedKeys(OPTIONAL)) do
  local f = OPTIONAL[name]
  if data.player[name] == nil then emitFunction("Player", name, f[1], f[2], "Optional: " .. f[3] .. ".") end
end
for _, name in ipairs(sortedKeys(data.player)) do
  if type(data.player[name]) == "function" then
    local f = PLAYER_FUNCTIONS[name]
    if not f then
      problems[#problems + 1] = "Player." .. name .. ": a player function with no definition (definitions.lua)"
    else
      emitFunction("Player", name, f[1], f[2])
    end
  end
end

for _, path in ipairs(sortedKeys(signatures)) do
  local covered = path:sub(1, 7) == "platon." or (sandboxed and path:sub(1, 5) == "game.")
  if covered and not seen[path] then
    problems[#problems + 1] = path .. ": a definition with no binding (engine/script/lua/api_signatures.lua)"
  end
end
emit("")
return table.concat(out, "\n"), problems
