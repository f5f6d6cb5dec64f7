#include "sandbox.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace platon::script {

int orderedKeys(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  const char* problem = nullptr;
  std::string why;
  {
    size_t n = 0;  // the array part: 1, 2, ... while present
    for (;; ++n) {
      lua_rawgeti(L, 1, static_cast<int>(n + 1));
      const bool present = !lua_isnil(L, -1);
      lua_pop(L, 1);
      if (!present || n >= kMaxOrderedKeys) break;
    }
    std::vector<double> numbers;
    std::vector<std::pair<const char*, size_t>> strings;  // the table's own keys: alive while it is unchanged
    bool hasFalse = false, hasTrue = false;
    size_t total = n;
    lua_pushnil(L);
    while (lua_next(L, 1)) {
      lua_pop(L, 1);
      if (++total > kMaxOrderedKeys + n) {
        lua_pop(L, 1);
        problem = "pairs over more than 1000000 keys in a sandbox (it would take too long to order them)";
        break;
      }
      const int kind = lua_type(L, -1);
      if (kind == LUA_TNUMBER) {
        const double d = lua_tonumber(L, -1);
        if (d >= 1 && d <= static_cast<double>(n) && d == std::floor(d)) --total;  // in the array part
        else numbers.push_back(d);
      } else if (kind == LUA_TSTRING) {
        size_t length = 0;
        const char* text = lua_tolstring(L, -1, &length);
        strings.emplace_back(text, length);
      } else if (kind == LUA_TBOOLEAN) {
        (lua_toboolean(L, -1) ? hasTrue : hasFalse) = true;
      } else {
        why = std::string("pairs over ") + lua_typename(L, kind) +
              " keys has no fixed order in a replayable game (key the table by numbers, strings or booleans)";
        lua_pop(L, 1);
        break;
      }
    }
    if (!problem && why.empty()) {
      std::sort(numbers.begin(), numbers.end());
      std::sort(strings.begin(), strings.end(), [](const auto& a, const auto& b) {
        const int c = std::memcmp(a.first, b.first, std::min(a.second, b.second));
        return c != 0 ? c < 0 : a.second < b.second;
      });
      lua_createtable(L, static_cast<int>(total), 0);
      int k = 0;
      for (size_t i = 1; i <= n; ++i) {
        lua_pushnumber(L, static_cast<double>(i));
        lua_rawseti(L, -2, ++k);
      }
      for (const double d : numbers) {
        lua_pushnumber(L, d);
        lua_rawseti(L, -2, ++k);
      }
      for (const auto& [text, length] : strings) {
        lua_pushlstring(L, text, length);
        lua_rawseti(L, -2, ++k);
      }
      if (hasFalse) {
        lua_pushboolean(L, 0);
        lua_rawseti(L, -2, ++k);
      }
      if (hasTrue) {
        lua_pushboolean(L, 1);
        lua_rawseti(L, -2, ++k);
      }
      return 1;
    }
  }
  lua_pushnil(L);
  if (problem) lua_pushstring(L, problem);
  else lua_pushlstring(L, why.data(), why.size());
  return 2;
}

// What a sandbox holds, and why each thing it lacks is missing (docs/scripting.md, "Sandbox"):
//   io, os (but time, date, clock: the game's clock), debug, ffi, jit, package, require, module:
//     reach the machine or the engine's internals;
//   load, loadstring, loadfile, dofile: bytecode is unverified in LuaJIT and can break memory
//     safety; text could be loaded, but nothing needs it;
//   getfenv, setfenv: would hand out the trusted globals;
//   rawset: would write past the engine's read-only tables;
//   newproxy, gcinfo, collectgarbage (but "count"): GC control;
//   string.dump: produces bytecode.
// xpcall runs its handler after the stack unwound (see safeXpcall below).
// Replays must be exact, so what would differ between runs or machines is the game's: math.random
// is a deterministic generator per sandbox, os.time/clock/date read the game clock, pairs and next
// walk keys in a fixed order, tostring names tables and functions by a counter, not an address.
// The pattern functions count their steps (lua_pattern.cpp); table.sort refuses huge tables (it
// sorts in C, where no hook runs).
// For every script: the shared string metatable is locked (getmetatable("") returns "locked"), and
// its methods (s:find(...)) are the counted pattern functions, without dump.
std::string_view sandboxPrelude() {
  return R"lua(
local C = ...
local printSink, gameFrames, orderedKeys = C.print, C.frames, C.orderedKeys
local pairs, next, type, setmetatable, getmetatable, error, select, tostring, rawget, rawequal, ipairs =
      pairs, next, type, setmetatable, getmetatable, error, select, tostring, rawget, rawequal, ipairs
local string, table, math, bit, coroutine, os, collectgarbage, jit, debug =
      string, table, math, bit, coroutine, os, collectgarbage, jit, debug
local floor, concat, sort, format, rawmeta = math.floor, table.concat, table.sort, string.format, debug.getmetatable

local function copy(t)
  local c = {}
  for k, v in pairs(t) do c[k] = v end
  return c
end

-- tostring with no address in it: a table, function or coroutine without __tostring is named by
-- the order in which tostring first saw it.
local ids, lastId = setmetatable({}, { __mode = "k" }), 0
local function safeTostring(v)
  local kind = type(v)
  if kind == "table" or kind == "function" or kind == "thread" or kind == "userdata" then
    local mt = rawmeta(v)
    if mt and rawget(mt, "__tostring") ~= nil then return tostring(v) end
    local id = ids[v]
    if not id then
      lastId = lastId + 1
      id = lastId
      ids[v] = id
    end
    return kind .. ": #" .. id
  end
  return tostring(v)
end

-- string.format's %s of a table or function would print its address.
local function safeFormat(f, ...)
  local n = select("#", ...)
  if n == 0 then return format(f) end
  local args = { ... }
  for i = 1, n do
    local kind = type(args[i])
    if kind ~= "string" and kind ~= "number" then args[i] = safeTostring(args[i]) end
  end
  return format(f, unpack(args, 1, n))
end

-- The methods of every string: LuaJIT's, but the pattern functions count their steps and there
-- is no dump. Trusted code keeps LuaJIT's own in its global `string`.
local methods = copy(string)
methods.dump = nil
methods.find, methods.match, methods.gmatch, methods.gsub = C.find, C.match, C.gmatch, C.gsub
methods.format = safeFormat
local stringMeta = getmetatable("")
stringMeta.__index = methods
stringMeta.__metatable = "locked"

-- A read-only view of an engine table, built once; nested tables are views too. A view of a view
-- is the view itself. Messages name keys by the sandbox's tostring: an address in an error would
-- differ between runs and break replays.
local views = setmetatable({}, { __mode = "k" })
local function readonly(t, name)
  if views[t] then return t end
  local entries = {}
  for k, v in pairs(t) do
    entries[k] = type(v) == "table" and readonly(v, name .. "." .. safeTostring(k)) or v
  end
  local view = setmetatable({}, {
    __index = entries,
    __newindex = function(_, k)
      error(name .. " is read-only (tried to set " .. safeTostring(k) .. ")", 2)
    end,
    __metatable = "locked",
  })
  views[view] = true
  return view
end

-- pairs and next in a fixed order (sandbox.cpp, orderedKeys): LuaJIT's order depends on the
-- string hash's random seed and on addresses.
local function safePairs(t)
  if type(t) ~= "table" then error("bad argument #1 to 'pairs' (table expected, got " .. type(t) .. ")", 2) end
  local keys, why = orderedKeys(t)
  if not keys then error(why, 2) end
  local i = 0
  return function()
    while true do
      i = i + 1
      local k = keys[i]
      if k == nil then return nil end
      local v = rawget(t, k)
      if v ~= nil then return k, v end
    end
  end, t, nil
end

local walks = setmetatable({}, { __mode = "k" })  -- t -> { keys, position of each key }
local function safeNext(t, k)
  if type(t) ~= "table" then error("bad argument #1 to 'next' (table expected, got " .. type(t) .. ")", 2) end
  local walk = walks[t]
  if k == nil or not walk or not walk.at[k] then
    if k ~= nil and rawget(t, k) == nil then error("invalid key to 'next'", 2) end
    local keys, why = orderedKeys(t)
    if not keys then error(why, 2) end
    local at = {}
    for i = 1, #keys do at[keys[i]] = i end
    walk = { keys = keys, at = at }
    walks[t] = walk
  end
  local i = k == nil and 0 or walk.at[k]
  while true do
    i = i + 1
    local key = walk.keys[i]
    if key == nil then return nil end
    local v = rawget(t, key)
    if v ~= nil then return key, v end
  end
end

-- table.sort runs in C, where no hook stops it: a bound on what one call may sort.
local MAX_SORT = 1000000
local function safeSort(t, less)
  if type(t) == "table" and #t > MAX_SORT then
    error("table.sort: at most " .. MAX_SORT .. " items in a sandbox (this table has " .. #t .. ")", 2)
  end
  return sort(t, less)
end

-- The game's clock: frames / 60 seconds since an epoch of 0 (os.time, os.clock), dates in UTC.
local function gameSeconds() return floor(gameFrames() / 60) end
local function daysFromCivil(y, m, d)  -- days since 1970-01-01 of a proleptic Gregorian date
  y = m <= 2 and y - 1 or y
  local era = floor(y / 400)
  local yoe = y - era * 400
  local doy = floor((153 * (m + (m > 2 and -3 or 9)) + 2) / 5) + d - 1
  local doe = yoe * 365 + floor(yoe / 4) - floor(yoe / 100) + doy
  return era * 146097 + doe - 719468
end
local function field(t, key, default)
  local v = rawget(t, key)
  if v == nil then
    if default == nil then error("field '" .. key .. "' missing in date table", 3) end
    return default
  end
  if type(v) ~= "number" or v ~= v or v == math.huge or v == -math.huge then
    error("field '" .. key .. "' is not a number", 3)
  end
  return floor(v)
end
local function safeTime(t)
  if t == nil then return gameSeconds() end
  if type(t) ~= "table" then error("bad argument #1 to 'time' (table expected, got " .. type(t) .. ")", 2) end
  local year, month = field(t, "year"), field(t, "month")
  local day, hour, min, sec = field(t, "day"), field(t, "hour", 12), field(t, "min", 0), field(t, "sec", 0)
  year = year + floor((month - 1) / 12)
  month = (month - 1) % 12 + 1
  return (daysFromCivil(year, month, 1) + day - 1) * 86400 + hour * 3600 + min * 60 + sec
end
local realDate = os.date
local function safeDate(f, time)
  f = f == nil and "%c" or f
  if type(f) ~= "string" and type(f) ~= "number" then
    error("bad argument #1 to 'date' (string expected, got " .. type(f) .. ")", 2)
  end
  f = tostring(f)
  if f:sub(1, 1) == "!" then f = f:sub(2) end
  if time ~= nil and type(time) ~= "number" then
    error("bad argument #2 to 'date' (number expected, got " .. type(time) .. ")", 2)
  end
  return realDate("!" .. f, time or gameSeconds())
end
local function safeClock() return gameFrames() / 60 end

-- xorshift32: the same sequence on every machine and build.
local function deterministicRandom(m)
  local state = 0x2545F491
  m.random = function(low, high)
    state = bit.bxor(state, bit.lshift(state, 13))
    state = bit.bxor(state, bit.rshift(state, 17))
    state = bit.bxor(state, bit.lshift(state, 5))
    local r = (state % 4294967296) / 4294967296
    if low == nil then return r end
    if high == nil then low, high = 1, low end
    if type(low) ~= "number" or type(high) ~= "number" or low > high then
      error("bad argument to 'random' (interval is empty)", 2)
    end
    return low + floor(r * (high - low + 1))
  end
  m.randomseed = function(seed)
    if type(seed) ~= "number" then error("bad argument to 'randomseed' (number expected)", 2) end
    state = bit.tobit(floor(seed))
    if state == 0 then state = 0x2545F491 end
  end
end

local SAFE = { "assert", "error", "ipairs", "pcall", "select", "tonumber", "type", "unpack", "rawequal",
               "rawget", "getmetatable", "setmetatable" }

-- LuaJIT runs an xpcall handler where the error was raised, before unwinding; for the error the
-- time budget raises, that is inside the hook, where no hook fires, so an endless handler would
-- never be stopped. The sandbox's xpcall runs the handler after unwinding instead.
local pcall, unpack = pcall, unpack
local function packed(ok, ...) return ok, select("#", ...), { ... } end
local function safeXpcall(f, handler, ...)
  local ok, n, results = packed(pcall(f, ...))
  if ok then return true, unpack(results, 1, n) end
  return false, handler(results[1])
end

-- What a sandbox calls with its loops in them runs interpreted, so the hooks see them.
for _, f in ipairs { safeTostring, safeFormat, safePairs, safeNext, safeSort, safeTime, safeDate, safeXpcall } do
  jit.off(f, true)
end

local function newSandbox(name, api)
  local env = {}
  for _, k in ipairs(SAFE) do env[k] = _G[k] end
  env.pairs, env.next, env.tostring, env.xpcall = safePairs, safeNext, safeTostring, safeXpcall
  env._G = env
  env._VERSION = _VERSION
  env.string = copy(methods)
  env.table = copy(table)
  env.table.sort = safeSort
  env.math = copy(math)
  deterministicRandom(env.math)
  env.bit = copy(bit)
  env.coroutine = copy(coroutine)
  env.os = { time = safeTime, date = safeDate, clock = safeClock }
  env.collectgarbage = function(option)
    if option == "count" then return collectgarbage("count") end
    error("collectgarbage: a sandbox may only ask for \"count\"", 2)
  end
  env.print = function(...)
    local parts = {}
    for i = 1, select("#", ...) do parts[i] = safeTostring((select(i, ...))) end
    printSink(name, concat(parts, "\t"))
  end
  env.platon = readonly(api, "platon")
  return env
end

return newSandbox, readonly
)lua";
}

}  // namespace platon::script
