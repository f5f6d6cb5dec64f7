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

-- C work over bytes and values. A library function that makes or reads a long string, or pushes
-- or moves many values, loops in C, where no hook counts (`while true do local r = s:upper() end`
-- over 100 KB spent seconds inside a budget of steps). Each such function is charged before it
-- runs, a step per 16 bytes and a step per value (C.chargeWork), and then tail-called, so an error
-- it raises still names the script's line and the function as the script called it.
local chargeWork = C.chargeWork
local function bytesOf(v)  -- what v is as a string: its bytes (a number's at most 24), or none
  local kind = type(v)
  if kind == "string" then return #v end
  if kind == "number" then return 24 end
  return 0
end
-- The length of string.sub(s, i, j) by string.sub's own rules, for a string of `len` bytes
-- (0 when an index is not a number: the call raises its own error).
local function span(len, i, j)
  i, j = tonumber(i), tonumber(j)
  if not i or not j then return 0 end
  if i < 0 then i = len + i + 1 end
  if j < 0 then j = len + j + 1 end
  if i < 1 then i = 1 end
  if j > len then j = len end
  return j >= i and j - i + 1 or 0
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
  if n == 0 then
    chargeWork(bytesOf(f), 0)
    return format(f)
  end
  local args, bytes = { ... }, bytesOf(f)
  for i = 1, n do
    local kind = type(args[i])
    if kind ~= "string" and kind ~= "number" then args[i] = safeTostring(args[i]) end
    bytes = bytes + bytesOf(args[i])
  end
  chargeWork(bytes, n)
  return format(f, unpack(args, 1, n))
end

-- The methods of every string: LuaJIT's, but the pattern functions count their steps and there
-- is no dump. Trusted code keeps LuaJIT's own in its global `string`.
local methods = copy(string)
methods.dump = nil
methods.find, methods.match, methods.gmatch, methods.gsub = C.find, C.match, C.gmatch, C.gsub
methods.format = safeFormat
local rep, upper, lower, reverse, sub, byte, char = string.rep, string.upper, string.lower, string.reverse,
                                                    string.sub, string.byte, string.char
local MAX_STRING = 0x7fffff00  -- LuaJIT's longest string: past it rep raises its own error
methods.rep = function(...)
  local s, n, sep = ...
  n = tonumber(n)
  if n and n > 0 then
    local bytes = (bytesOf(s) + bytesOf(sep)) * n
    if bytes <= MAX_STRING then chargeWork(bytes, 0) end
  end
  return rep(...)
end
-- Up to SHORT bytes or values, a call's work is less than the wrapper's own instructions, which
-- the hook counts: only longer ones are charged (byte and sub run in parsers' inner loops).
local SHORT = 64
-- f, charged the length of its first argument when that is a long string (it reads it all).
local function chargingLength(f)
  return function(...)
    local s = ...
    if type(s) == "string" and #s > SHORT then chargeWork(#s, 0) end
    return f(...)
  end
end
methods.upper, methods.lower, methods.reverse = chargingLength(upper), chargingLength(lower), chargingLength(reverse)
methods.sub = function(...)
  local s, i, j = ...
  if type(s) == "string" and #s > SHORT then chargeWork(span(#s, i, j == nil and -1 or j), 0) end
  return sub(...)
end
methods.byte = function(...)
  local s, i, j = ...
  if type(s) == "string" and #s > SHORT then
    if i == nil then i = 1 end
    chargeWork(0, span(#s, i, j == nil and i or j))
  end
  return byte(...)
end
methods.char = function(...)
  local n = select("#", ...)
  if n > SHORT then chargeWork(0, n) end
  return char(...)
end
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
local insert, remove, tconcat, maxn = table.insert, table.remove, table.concat, table.maxn
-- insert and remove at a place move every value after it.
local function moved(t, pos)
  pos = tonumber(pos)
  if type(t) ~= "table" or not pos then return 0 end
  local after = #t - pos + 1
  return after > 0 and after or 0
end
local function safeInsert(t, ...)
  refuseView(t, "insert")
  if select("#", ...) >= 2 then chargeWork(0, moved(t, (...))) end
  return insert(t, ...)
end
local function safeRemove(t, ...)
  refuseView(t, "remove")
  if select("#", ...) >= 1 then chargeWork(0, moved(t, (...))) end
  return remove(t, ...)
end
-- concat reads each value up to the first it cannot join: C.chargeConcat walks them first.
local chargeConcat = C.chargeConcat
local function safeConcat(...)
  chargeConcat(...)
  return tconcat(...)
end
-- unpack pushes each value (past about 8,000, LUAI_MAXCSTACK, it raises its own error).
local MAX_VALUES = 8000
local rawUnpack = unpack
local function safeUnpack(...)
  local t, i, j = ...
  if type(t) == "table" then
    i, j = tonumber(i == nil and 1 or i), tonumber(j == nil and #t or j)
    if i and j and j >= i then chargeWork(0, j - i + 1 <= MAX_VALUES and j - i + 1 or 0) end
  end
  return rawUnpack(...)
end
-- maxn walks every key in C: here the walk is interpreted, so the hook counts it (the largest
-- positive numeric key does not depend on the order of the walk).
local function safeMaxn(...)
  local t = ...
  if type(t) ~= "table" then return maxn(...) end  -- stock's own argument error
  local most = 0
  for k in next, t do
    if type(k) == "number" and k > most then most = k end
  end
  return most
end
-- select copies the values after n (for i = 1, select("#", ...) do select(i, ...) end is n^2/2).
local rawSelect = select
local function safeSelect(...)
  local n = rawSelect("#", ...)
  if n > SHORT then chargeWork(0, n) end
  return rawSelect(...)
end
-- tonumber reads the whole string.
local safeTonumber = chargingLength(tonumber)
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
  chargeWork(#f, 0)
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

-- No weak tables. Which entries of a weak table the collector clears, and when, depends on the
-- collector's timing, which depends on everything the Lua state allocates (the engine's own
-- scripts, drawing, the console): six runs of one level gave six hashes. So a sandbox's metatables
-- never have a __mode: setmetatable refuses one that has it, and every table a sandbox makes a
-- metatable is sealed, so that `mt.__mode = "k"` afterwards is refused too. A new key reaches a
-- table raw only where its metatable has no __newindex (a sandbox has no rawset; table.insert
-- writes number keys only), so a sealed table's own metatable always has one, made here and never
-- handed out: SEAL when the sandbox gave it none, or WITH(U), a copy of the metatable U it gave,
-- whose __newindex refuses __mode and otherwise does what U's does (read when the key is written).
-- getmetatable shows nil and U for these, as stock would.
local rawsetmeta, rawset = debug.setmetatable, rawset
local sealed = setmetatable({}, { __mode = "k" })  -- tables a sandbox made metatables (the engine's own)
local madeHere = setmetatable({}, { __mode = "k" })  -- SEAL and every WITH(U), to what getmetatable shows
local NO_WEAK = "weak tables are not for sandboxes: which entries the collector clears, and when, differs from "
                .. "one run to the next (docs/scripting.md, Sandbox)"
local function refuseMode(k)
  if k == "__mode" then error("__mode in a metatable: " .. NO_WEAK, 3) end
end
local SEAL = { __newindex = function(t, k, v)
  refuseMode(k)
  rawset(t, k, v)
end }
madeHere[SEAL] = { shows = nil }
local function with(u)
  local m = {}
  for k, v in next, u do
    if type(k) == "string" and sub(k, 1, 2) == "__" then m[k] = v end
  end
  m.__newindex = function(t, k, v)
    refuseMode(k)
    local h = rawget(u, "__newindex")
    if h == nil then return rawset(t, k, v) end
    if type(h) == "function" then return h(t, k, v) end
    h[k] = v
  end
  local protected = rawget(u, "__metatable")
  if protected ~= nil then m.__metatable = protected else m.__metatable = nil end
  madeHere[m] = { shows = u, protected = protected ~= nil }
  return m
end
-- Seals mt, a table a sandbox is making a metatable.
local function seal(mt)
  local own = rawmeta(mt)
  if own == nil then
    rawsetmeta(mt, SEAL)
  elseif sealed[own] then  -- a metatable the sandbox gave it (setmetatable(Class, { __index = Base }))
    rawsetmeta(mt, with(own))
  elseif rawget(own, "__newindex") == nil then  -- an engine table whose metatable lets keys in raw
    error("bad argument #2 to 'setmetatable' (an engine table cannot be a sandbox's metatable)", 3)
  end
  sealed[mt] = true
end
local stockSetmetatable, stockGetmetatable = setmetatable, getmetatable
local function safeSetmetatable(...)
  local t, mt = ...
  if type(t) ~= "table" or type(mt) ~= "table" and (mt ~= nil or select("#", ...) < 2) then
    return stockSetmetatable(...)  -- stock's own argument errors
  end
  if mt ~= nil then
    if rawget(mt, "__mode") ~= nil then error("bad argument #2 to 'setmetatable' (it has __mode: " .. NO_WEAK .. ")", 2) end
    if not sealed[mt] then seal(mt) end
  end
  if not sealed[t] then return stockSetmetatable(t, mt) end
  -- t is a metatable itself: the metatable it gets keeps it sealed.
  local own = madeHere[rawmeta(t)]
  if not own or own.protected then error("cannot change a protected metatable", 2) end
  rawsetmeta(t, mt == nil and SEAL or with(mt))
  return t
end
local function safeGetmetatable(...)
  local made = madeHere[rawmeta((...))]
  if made and not made.protected then return made.shows end
  return stockGetmetatable(...)
end

local SAFE = { "assert", "error", "pcall", "select", "tonumber", "type", "unpack", "rawequal", "rawget" }

-- A caught error costs far more than the few instructions around it: LuaJIT unwinds the C stack,
-- and an error of the engine's C++ also throws and catches a C++ exception (3 to 12 us, the time
-- of 1,000 to 3,000 steps; `while true do pcall(error) end` ran into the deadline, not the
-- budget). So every error a sandbox catches (pcall, xpcall, coroutine.resume) is charged
-- C.chargeError's steps (kErrorSteps in lua_host.h).
local chargeError, resume, create = C.chargeError, coroutine.resume, coroutine.create
local enterCoroutine, leaveCoroutine = C.enterCoroutine, C.leaveCoroutine
local function charged(ok, ...)
  if not ok then chargeError() end
  return ok, ...
end
local pcall, unpack = pcall, unpack
local function countedPcall(f, ...) return charged(pcall(f, ...)) end
-- A coroutine resumed inside another nests C frames in LuaJIT (deep nesting overflows the C
-- stack): resumes nest at most as deep as C callbacks do (kMaxCallbackDepth), on the same count,
-- which starts again at each call from the engine. wrap is built on the counted resume, so each
-- level a wrapped coroutine's error passes through is charged.
local function leave(ok, ...)
  leaveCoroutine()
  if not ok then chargeError() end
  return ok, ...
end
local function countedResume(co, ...)
  enterCoroutine()
  return leave(resume(co, ...))
end
local function unwrap(ok, ...)
  if ok then return ... end
  error((...), 0)  -- the coroutine's error object as it is, as stock wrap raises it
end
local function countedWrap(f)
  if type(f) ~= "function" then
    error("bad argument #1 to 'wrap' (function expected, got " .. type(f) .. ")", 2)
  end
  local co = create(f)
  return function(...) return unwrap(countedResume(co, ...)) end
end

-- error(m, level) counts the script's frames as stock Lua does: the counted pcall above adds a
-- frame of this prelude between a function and the one that called pcall, which error(m, 3) would
-- otherwise name ("platon/sandbox:NNN:") instead of the script's line.
local getinfo, PRELUDE = debug.getinfo, debug.getinfo(1, "S").source
local function countedError(message, level)
  if level == nil then level = 1 end
  if type(level) ~= "number" then return error(message, level) end  -- stock's own argument error
  if level < 2 then
    error(message, level > 0 and level + 1 or level)  -- not a tail call: level 2 is the caller
  end
  local frame, seen = 2, 1  -- frame 2: the function that called error, its level 1
  while seen < level do
    frame = frame + 1
    local info = getinfo(frame, "S")
    if not info then break end
    if info.source ~= PRELUDE then seen = seen + 1 end
  end
  error(message, frame)  -- not a tail call: this frame is level 1 of the count
end

-- LuaJIT runs an xpcall handler where the error was raised, before unwinding; for the error the
-- time budget raises, that is inside the hook, where no hook fires, so an endless handler would
-- never be stopped. The sandbox's xpcall runs the handler after unwinding instead.
local function packed(ok, ...) return ok, select("#", ...), { ... } end
local function safeXpcall(f, handler, ...)
  local ok, n, results = packed(countedPcall(f, ...))
  if ok then return true, unpack(results, 1, n) end
  local handled, message = countedPcall(handler, results[1])
  if not handled then return false, "error in error handling" end  -- as stock LuaJIT says it
  return false, message
end

local function newSandbox(name, api)
  local env = {}
  for _, k in ipairs(SAFE) do env[k] = _G[k] end
  env.pairs, env.next, env.ipairs, env.tostring, env.xpcall = safePairs, safeNext, safeIpairs, safeTostring, safeXpcall
  env.setmetatable, env.getmetatable = safeSetmetatable, safeGetmetatable
  env._G = env
  env._VERSION = _VERSION
  env.string = copy(methods)
  env.table = copy(table)
  env.table.sort, env.table.insert, env.table.remove, env.table.foreach = safeSort, safeInsert, safeRemove, safeForeach
  env.table.concat, env.table.maxn = safeConcat, safeMaxn
  env.unpack, env.select, env.tonumber = safeUnpack, safeSelect, safeTonumber
  env.math = copy(math)
  deterministicRandom(env.math)
  env.bit = copy(bit)
  env.coroutine = copy(coroutine)
  env.coroutine.resume, env.coroutine.wrap = countedResume, countedWrap
  env.pcall, env.error = countedPcall, countedError
  env.os = { time = safeTime, date = safeDate, clock = safeClock }
  env.collectgarbage = function(option)
    if option == "count" then
      error("collectgarbage(\"count\") is not for sandboxes: the Lua state's memory differs from one run to "
            .. "the next (the engine's own scripts, LuaJIT's hash seeds), and what a sandbox sees must not (the engine "
            .. "stops a sandbox that uses too much: docs/scripting.md, Limits)", 2)
    end
    error("collectgarbage: a sandbox may not drive the garbage collector", 2)
  end
  env.print = function(...)
    local parts, bytes = {}, 0
    for i = 1, select("#", ...) do
      parts[i] = safeTostring((select(i, ...)))
      bytes = bytes + bytesOf(parts[i])
    end
    chargeWork(bytes, 0)
    printSink(name, concat(parts, "\t"))
  end
  env.platon = readonly(api, "platon")
  return env
end

return newSandbox, readonly, safeTostring
