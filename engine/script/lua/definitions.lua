-- The Lua language server's definitions (---@meta) of one set of the scripting API, written from
-- the live binding tables (trusted: the engine's `platon`; sandboxed: the `platon` a sandbox sees
-- and the `game` level scripts and mods are handed) with each function's entry in
-- api_signatures.lua. Returns the text and the problems: a binding with no entry, an entry with
-- no binding. Run by `platon defs` (ScriptSystem::definitions).
local api, levelApi, signatures, sandboxed = ...
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

local function functionOf(path, owner, name)
  local s = signatures[path]
  if not s then
    problems[#problems + 1] = path .. ": a binding with no definition (engine/script/lua/api_signatures.lua)"
    return
  end
  seen[path] = true
  emit("")
  emit("--- " .. s[3])
  local names = {}
  for _, p in ipairs(split(s[1])) do
    local n, optional, t = p:match("^([%w_]+)(%??):%s*(.+)$")
    if n then
      emit("---@param " .. n .. optional .. " " .. t)
      names[#names + 1] = n
    end
  end
  for _, r in ipairs(split(s[2])) do emit("---@return " .. r) end
  emit("function " .. owner .. "." .. name .. "(" .. table.concat(names, ", ") .. ") end")
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

for _, path in ipairs(sortedKeys(signatures)) do
  local covered = path:sub(1, 7) == "platon." or (sandboxed and path:sub(1, 5) == "game.")
  if covered and not seen[path] then
    problems[#problems + 1] = path .. ": a definition with no binding (engine/script/lua/api_signatures.lua)"
  end
end
emit("")
return table.concat(out, "\n"), problems
