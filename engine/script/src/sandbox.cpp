#include "sandbox.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "lua_host.h"

namespace platon::script {

namespace {

// How many keys 1, 2, ... the table at index 1 holds in a row (at most kMaxOrderedKeys): the
// array part the fixed order walks first.
size_t arrayLength(lua_State* L) {
  size_t n = 0;
  for (;; ++n) {
    lua_rawgeti(L, 1, static_cast<int>(n + 1));
    const bool present = !lua_isnil(L, -1);
    lua_pop(L, 1);
    if (!present || n >= kMaxOrderedKeys) return n;
  }
}

// A key of the fixed order outside the array part: a number, a string or a boolean.
struct Key {
  int kind;
  double number = 0;
  const char* text = nullptr;  // the table's own string: alive while the table is unchanged
  size_t length = 0;
  bool boolean = false;
};

bool bytesBefore(const Key& a, const Key& b) {
  const int c = std::memcmp(a.text, b.text, std::min(a.length, b.length));
  return c != 0 ? c < 0 : a.length < b.length;
}

// Calls visit(key) for every key of the table at index 1 outside its array part 1..n; returns why
// the keys have no fixed order ("" when they have one).
template <class Visit>
std::string visitKeys(lua_State* L, size_t n, Visit&& visit) {
  size_t others = 0;
  lua_pushnil(L);
  while (lua_next(L, 1)) {
    lua_pop(L, 1);
    if (++others > kMaxOrderedKeys) {
      lua_pop(L, 1);
      return "pairs over more than 1000000 keys in a sandbox (it would take too long to order them)";
    }
    Key key{lua_type(L, -1)};
    if (key.kind == LUA_TNUMBER) {
      key.number = lua_tonumber(L, -1);
      if (key.number >= 1 && key.number <= static_cast<double>(n) && key.number == std::floor(key.number)) {
        --others;  // in the array part
        continue;
      }
    } else if (key.kind == LUA_TSTRING) {
      key.text = lua_tolstring(L, -1, &key.length);
    } else if (key.kind == LUA_TBOOLEAN) {
      key.boolean = lua_toboolean(L, -1);
    } else {
      std::string why = std::string("pairs over ") + lua_typename(L, key.kind) +
                        " keys has no fixed order in a replayable game (key the table by numbers, strings or booleans)";
      lua_pop(L, 1);
      return why;
    }
    visit(key);
  }
  return "";
}

void pushKey(lua_State* L, const Key& key) {
  if (key.kind == LUA_TNUMBER)
    lua_pushnumber(L, key.number);
  else if (key.kind == LUA_TSTRING)
    lua_pushlstring(L, key.text, key.length);
  else
    lua_pushboolean(L, key.boolean);
}

int refuse(lua_State* L, const std::string& why) {
  lua_pushnil(L);
  lua_pushlstring(L, why.data(), why.size());
  return 2;
}

// The first key of the fixed order and the array part's length, in one pass that builds nothing:
// next(t) (what "is it empty?" asks) costs a walk over the keys, not a sort. Every key is still
// visited, so a table whose keys have no fixed order is refused by next(t) as by pairs(t).
int firstKey(lua_State* L, int64_t& cost) {
  const size_t n = arrayLength(L);
  cost += static_cast<int64_t>(n);
  bool any = false;
  Key first{LUA_TNIL};
  auto rank = [](const Key& k) { return k.kind == LUA_TNUMBER ? 0 : k.kind == LUA_TSTRING ? 1 : k.boolean ? 3 : 2; };
  const std::string why = visitKeys(L, n, [&](const Key& key) {
    const bool before =
        !any || rank(key) < rank(first) ||
        (rank(key) == rank(first) &&
         (key.kind == LUA_TNUMBER ? key.number < first.number : key.kind == LUA_TSTRING && bytesBefore(key, first)));
    if (before) first = key;
    any = true;
    ++cost;
  });
  if (!why.empty()) return refuse(L, why);
  if (n > 0)
    lua_pushnumber(L, 1);
  else if (any)
    pushKey(L, first);
  else
    lua_pushnil(L);
  lua_pushnumber(L, static_cast<double>(n));
  return 2;
}

// What sorting m keys costs in steps: about m log2 m comparisons.
int64_t sortCost(size_t m) {
  int64_t log = 1;
  while ((size_t{1} << log) < m) ++log;
  return static_cast<int64_t>(m) * log;
}

int allKeys(lua_State* L, int64_t& cost) {
  // The array part the walk began with, when a walk's first key came from firstKey: its keys keep
  // their place even if one of them was removed since (the rest would sort among the numbers).
  const size_t n = lua_isnumber(L, 2)
                       ? static_cast<size_t>(std::clamp(lua_tonumber(L, 2), 0.0, double(kMaxOrderedKeys)))
                       : arrayLength(L);
  std::vector<double> numbers;
  std::vector<Key> strings;
  bool hasFalse = false, hasTrue = false;
  const std::string why = visitKeys(L, n, [&](const Key& key) {
    if (key.kind == LUA_TNUMBER)
      numbers.push_back(key.number);
    else if (key.kind == LUA_TSTRING)
      strings.push_back(key);
    else
      (key.boolean ? hasTrue : hasFalse) = true;
  });
  if (!why.empty()) return refuse(L, why);
  cost += 2 * static_cast<int64_t>(n) + sortCost(numbers.size()) + sortCost(strings.size()) +
          static_cast<int64_t>(numbers.size() + strings.size());
  std::sort(numbers.begin(), numbers.end());
  std::sort(strings.begin(), strings.end(), bytesBefore);
  lua_createtable(L, static_cast<int>(n + numbers.size() + strings.size() + 2), 0);
  int k = 0;
  for (size_t i = 1; i <= n; ++i) {
    lua_rawgeti(L, 1, static_cast<int>(i));
    const bool present = !lua_isnil(L, -1);
    lua_pop(L, 1);
    if (!present) continue;
    lua_pushnumber(L, static_cast<double>(i));
    lua_rawseti(L, -2, ++k);
  }
  for (const double d : numbers) {
    lua_pushnumber(L, d);
    lua_rawseti(L, -2, ++k);
  }
  for (const Key& key : strings) {
    pushKey(L, key);
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

}  // namespace

namespace {

int countedLess(lua_State* L) {
  chargeSteps(L, 1);
  const CallbackDepth nested(L);  // the comparator, or an __lt metamethod, may sort again
  if (lua_isnil(L, lua_upvalueindex(1))) {
    lua_pushboolean(L, lua_lessthan(L, 1, 2));
    return 1;
  }
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_pushvalue(L, 1);
  lua_pushvalue(L, 2);
  lua_call(L, 2, 1);
  return 1;
}

}  // namespace

int countedComparator(lua_State* L) {
  lua_settop(L, 1);
  lua_pushcclosure(L, countedLess, 1);
  return 1;
}

// The keys are walked, and sorted, in C, where no hook counts: their work is charged here, once
// the vectors are gone (the charge may stop the sandbox).
int orderedKeys(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  int64_t cost = 0;
  const int results = lua_isboolean(L, 2) && lua_toboolean(L, 2) ? firstKey(L, cost) : allKeys(L, cost);
  chargeSteps(L, cost);
  return results;
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
// is a deterministic generator per sandbox, os.time/clock/date read the game clock, pairs, next
// and table.foreach walk keys in a fixed order, tostring names tables and functions by a counter,
// not an address.
// The pattern functions count their steps (lua_pattern.cpp); table.sort charges each comparison
// and refuses huge tables (it
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
local function safeTostring(...)
  if select("#", ...) == 0 then error("bad argument #1 to 'tostring' (value expected)", 2) end
  local v = ...
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

-- string.format's %s of a table or function would print its address, and %p prints one.
local function safeFormat(f, ...)
  if type(f) == "string" and f:gsub("%%%%", ""):find("%%[-+ #0-9.]*p") then
    error("bad argument #1 to 'format' (%p shows an address, which differs from one run to the next: "
          .. "use tostring)", 2)
  end
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
-- is the view itself. The view is an empty table whose metatable reads `entries`; pairs, next and
-- ipairs walk those entries (views[view].entries) without ever handing the table out, so a view
-- lists what it shows and stays read-only. Messages name keys by the sandbox's tostring: an
-- address in an error would differ between runs and break replays.
local views = setmetatable({}, { __mode = "k" })  -- view -> { entries = what it shows, name = its name }
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
  views[view] = { entries = entries, name = name }
  return view
end

-- What pairs, next and ipairs walk: a view's entries, any other table itself.
local function shownBy(t)
  local view = views[t]
  return view and view.entries or t
end

-- pairs and next in a fixed order (sandbox.cpp, orderedKeys): LuaJIT's order depends on the
-- string hash's random seed and on addresses. pairs orders the keys once per traversal.
local function safePairs(t)
  if type(t) ~= "table" then error("bad argument #1 to 'pairs' (table expected, got " .. type(t) .. ")", 2) end
  local shown = shownBy(t)
  local keys, why = orderedKeys(shown)
  if not keys then error(why, 2) end
  local i = 0
  return function()
    while true do
      i = i + 1
      local k = keys[i]
      if k == nil then return nil end
      local v = rawget(shown, k)
      if v ~= nil then return k, v end
    end
  end, t, nil
end

-- The keys of t in the fixed order, and the position of each (arrayLength: see orderedKeys).
local function orderOf(t, arrayLength)
  local keys, why = orderedKeys(t, arrayLength)
  if not keys then return nil, why end
  local at = {}
  for i = 1, #keys do at[keys[i]] = i end
  return { keys = keys, at = at }
end

-- next in the same order. next(t) finds the first key in one pass that builds nothing (the "is it
-- empty?" idiom must not sort); the walk it starts orders the keys at its second call and keeps
-- them (walks[t]), so next(t, k) with the key the last call returned costs O(1) amortized, and the
-- walk is dropped at its end. Any other k orders the keys again (a new traversal sees the keys
-- added since), unless k was removed after this walk returned it (as Lua allows). Keys added
-- during a traversal are not seen by it; keys whose value became nil are skipped.
local walks = setmetatable({}, { __mode = "k" })  -- t -> { keys, at, last = index of lastKey, lastKey }
local function safeNext(t, k)
  if type(t) ~= "table" then error("bad argument #1 to 'next' (table expected, got " .. type(t) .. ")", 2) end
  t = shownBy(t)
  if k == nil then
    local first, arrayLength = orderedKeys(t, true)
    if type(arrayLength) == "string" then error(arrayLength, 2) end
    if first == nil then
      walks[t] = nil
      return nil
    end
    walks[t] = { lastKey = first, arrayLength = arrayLength }  -- ordered at the next call, if any
    return first, rawget(t, first)
  end
  local walk, i = walks[t], nil
  if walk and rawequal(walk.lastKey, k) then
    if not walk.keys then
      local ordered, why = orderOf(t, walk.arrayLength)
      if not ordered then error(why, 2) end
      walk.keys, walk.at = ordered.keys, ordered.at
      walk.last = walk.at[k] or 0  -- k was the first key: if it was removed, every key comes after it
    end
    i = walk.last
  elseif rawget(t, k) ~= nil then
    local why
    walk, why = orderOf(t)
    if not walk then error(why, 2) end
    walks[t] = walk
    i = walk.at[k]
  elseif walk and walk.at and walk.at[k] then
    i = walk.at[k]
  else
    error("invalid key to 'next'", 2)
  end
  local keys = walk.keys
  while true do
    i = i + 1
    local key = keys[i]
    if key == nil then
      walks[t] = nil
      return nil
    end
    local v = rawget(t, key)
    if v ~= nil then
      walk.last, walk.lastKey = i, key
      return key, v
    end
  end
end

-- ipairs over a view walks its entries; over any other table it is LuaJIT's.
local function safeIpairs(t)
  if not views[t] then return ipairs(t) end
  local shown = views[t].entries
  return function(_, i)
    i = i + 1
    local v = rawget(shown, i)
    if v ~= nil then return i, v end
  end, t, 0
end

-- table's functions read and write raw: on a view, insert would write past its read-only
-- metatable into the table every sandbox is shown (a mod's note in the level's `game`), and
-- foreach would walk LuaJIT's order, which differs between processes.
local function refuseView(t, what)
  local view = views[t]
  if view then error(view.name .. " is read-only (tried to " .. what .. " in it)", 3) end
end
local insert, remove = table.insert, table.remove
local function safeInsert(t, ...)
  refuseView(t, "insert")
  return insert(t, ...)
end
local function safeRemove(t, ...)
  refuseView(t, "remove")
  return remove(t, ...)
end
local function safeForeach(t, f)
  if type(t) ~= "table" then error("bad argument #1 to 'foreach' (table expected, got " .. type(t) .. ")", 2) end
  if type(f) ~= "function" then error("bad argument #2 to 'foreach' (function expected, got " .. type(f) .. ")", 2) end
  local shown = shownBy(t)
  local keys, why = orderedKeys(shown)
  if not keys then error(why, 2) end
  for i = 1, #keys do
    local v = rawget(shown, keys[i])
    if v ~= nil then
      local r = f(keys[i], v)
      if r ~= nil then return r end
    end
  end
end

-- table.sort runs in C, where no hook counts: each comparison is charged a step (LuaJIT's quicksort
-- takes n^2 of them on some orders), and one call sorts at most MAX_SORT items.
local MAX_SORT = 1000000
local countedComparator = C.countedComparator
local function safeSort(t, less)
  refuseView(t, "sort")
  if type(t) == "table" and #t > MAX_SORT then
    error("table.sort: at most " .. MAX_SORT .. " items in a sandbox (this table has " .. #t .. ")", 2)
  end
  if less ~= nil and type(less) ~= "function" then
    error("bad argument #2 to 'sort' (function expected, got " .. type(less) .. ")", 2)
  end
  return sort(t, countedComparator(less))
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
    -- The bounds as LuaJIT reads them: numbers (or numeric strings), not checked for order, so
    -- random(0) is 1 and random(3, 1) is 2, as in stock LuaJIT.
    if low == nil then return r end
    local lo = tonumber(low)
    if type(low) ~= "number" and (type(low) ~= "string" or lo == nil) then
      error("bad argument #1 to 'random' (number expected, got " .. type(low) .. ")", 2)
    end
    if high == nil then return floor(r * lo) + 1 end
    local hi = tonumber(high)
    if type(high) ~= "number" and (type(high) ~= "string" or hi == nil) then
      error("bad argument #2 to 'random' (number expected, got " .. type(high) .. ")", 2)
    end
    return floor(r * (hi - lo + 1)) + lo
  end
  m.randomseed = function(seed)
    if type(seed) ~= "number" then error("bad argument to 'randomseed' (number expected)", 2) end
    state = bit.tobit(floor(seed))
    if state == 0 then state = 0x2545F491 end
  end
end

local SAFE = { "assert", "error", "pcall", "select", "tonumber", "type", "unpack", "rawequal",
               "rawget", "getmetatable", "setmetatable" }

-- LuaJIT runs an xpcall handler where the error was raised, before unwinding; for the error the
-- time budget raises, that is inside the hook, where no hook fires, so an endless handler would
-- never be stopped. The sandbox's xpcall runs the handler after unwinding instead.
local pcall, unpack = pcall, unpack
local function packed(ok, ...) return ok, select("#", ...), { ... } end
local function safeXpcall(f, handler, ...)
  local ok, n, results = packed(pcall(f, ...))
  if ok then return true, unpack(results, 1, n) end
  local handled, message = pcall(handler, results[1])
  if not handled then return false, "error in error handling" end  -- as stock LuaJIT says it
  return false, message
end

local function newSandbox(name, api)
  local env = {}
  for _, k in ipairs(SAFE) do env[k] = _G[k] end
  env.pairs, env.next, env.ipairs, env.tostring, env.xpcall = safePairs, safeNext, safeIpairs, safeTostring, safeXpcall
  env._G = env
  env._VERSION = _VERSION
  env.string = copy(methods)
  env.table = copy(table)
  env.table.sort, env.table.insert, env.table.remove, env.table.foreach = safeSort, safeInsert, safeRemove, safeForeach
  env.math = copy(math)
  deterministicRandom(env.math)
  env.bit = copy(bit)
  env.coroutine = copy(coroutine)
  env.os = { time = safeTime, date = safeDate, clock = safeClock }
  env.collectgarbage = function(option)
    if option == "count" then
      error("collectgarbage(\"count\") is not for sandboxes: the Lua state's memory differs from one run to "
            .. "the next (JIT traces, the engine's own scripts), and what a sandbox sees must not (the engine "
            .. "stops a sandbox that uses too much: docs/scripting.md, Limits)", 2)
    end
    error("collectgarbage: a sandbox may not drive the garbage collector", 2)
  end
  env.print = function(...)
    local parts = {}
    for i = 1, select("#", ...) do parts[i] = safeTostring((select(i, ...))) end
    printSink(name, concat(parts, "\t"))
  end
  env.platon = readonly(api, "platon")
  return env
end

return newSandbox, readonly, safeTostring
)lua";
}

}  // namespace platon::script
