#include "sandbox.h"

namespace platon::script {

// What a sandbox holds, and why each thing it lacks is missing (docs/scripting.md, "Sandbox"):
//   io, os (but time, date, clock), debug, ffi, jit, package, require, module: reach the machine
//     or the engine's internals;
//   load, loadstring, loadfile, dofile: bytecode is unverified in LuaJIT and can break memory
//     safety; text could be loaded, but nothing needs it;
//   getfenv, setfenv: would hand out the trusted globals;
//   rawset: would write past the engine's read-only tables;
//   newproxy, gcinfo, collectgarbage (but "count"): GC control;
//   string.dump: produces bytecode.
// xpcall runs its handler after the stack unwound (see safeXpcall below).
// The shared string metatable is locked (getmetatable("") returns "locked", so nobody can change
// how every string in the state behaves). math.random is a deterministic generator per sandbox,
// so replays stay exact. Pattern functions refuse subjects that are long for the pattern's number
// of repetition items (a pattern's backtracking runs in C, where no hook can stop it).
std::string_view sandboxPrelude() {
  return R"lua(
local printSink = ...
local pairs, type, setmetatable, getmetatable, error, select, tostring, rawget =
      pairs, type, setmetatable, getmetatable, error, select, tostring, rawget
local string, table, math, bit, coroutine, os, collectgarbage =
      string, table, math, bit, coroutine, os, collectgarbage
local floor, concat = math.floor, table.concat

getmetatable("").__metatable = "locked"

local function copy(t)
  local c = {}
  for k, v in pairs(t) do c[k] = v end
  return c
end

-- A read-only view of an engine table, built once per sandbox; nested tables are views too.
local function readonly(t, name)
  local entries = {}
  for k, v in pairs(t) do
    entries[k] = type(v) == "table" and readonly(v, name .. "." .. tostring(k)) or v
  end
  return setmetatable({}, {
    __index = entries,
    __newindex = function(_, k)
      error(name .. " is read-only (tried to set " .. tostring(k) .. ")", 2)
    end,
    __metatable = "locked",
  })
end

local WORK_LIMIT = 1e8
local function guardPattern(fname, s, p)
  if type(p) ~= "string" then return end
  if type(s) == "number" then s = tostring(s) end
  if type(s) ~= "string" then return end
  local items = 0
  for _ in p:gmatch("[%*%+%-%?]") do items = items + 1 end
  if items > 0 and (#s) ^ items > WORK_LIMIT then
    error(fname .. ": pattern too costly for a subject of " .. #s .. " characters (" .. items ..
          " repetition items; a sandbox allows length^items <= 1e8)", 3)
  end
end

local function safeString()
  local s = copy(string)
  s.dump = nil
  local find, match, gmatch, gsub = string.find, string.match, string.gmatch, string.gsub
  s.find = function(subject, pattern, init, plain)
    if not plain then guardPattern("string.find", subject, pattern) end
    return find(subject, pattern, init, plain)
  end
  s.match = function(subject, pattern, init)
    guardPattern("string.match", subject, pattern)
    return match(subject, pattern, init)
  end
  s.gmatch = function(subject, pattern)
    guardPattern("string.gmatch", subject, pattern)
    return gmatch(subject, pattern)
  end
  s.gsub = function(subject, pattern, replacement, n)
    guardPattern("string.gsub", subject, pattern)
    return gsub(subject, pattern, replacement, n)
  end
  return s
end

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

local SAFE = { "assert", "error", "ipairs", "next", "pairs", "pcall", "select", "tonumber",
               "tostring", "type", "unpack", "rawequal", "rawget", "getmetatable", "setmetatable" }

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

return function(name, api)
  local env = {}
  for _, k in ipairs(SAFE) do env[k] = _G[k] end
  env.xpcall = safeXpcall
  env._G = env
  env._VERSION = _VERSION
  env.string = safeString()
  env.table = copy(table)
  env.math = copy(math)
  deterministicRandom(env.math)
  env.bit = copy(bit)
  env.coroutine = copy(coroutine)
  env.os = { time = os.time, date = os.date, clock = os.clock }
  env.collectgarbage = function(option)
    if option == "count" then return collectgarbage("count") end
    error("collectgarbage: a sandbox may only ask for \"count\"", 2)
  end
  env.print = function(...)
    local parts = {}
    for i = 1, select("#", ...) do parts[i] = tostring((select(i, ...))) end
    printSink(name, concat(parts, "\t"))
  end
  env.platon = readonly(api, "platon")
  return env
end
)lua";
}

}  // namespace platon::script
