local ffi, api, world = ...
ffi.cdef [[
struct platon_world_ffi {
  void* context;
  int (*position)(void*, double, double*);
  int (*velocity)(void*, double, double*);
  int (*setVelocity)(void*, double, double, double);
  int (*gravity)(void*, double, double*);
  int (*contactCount)(void*, double, double*);
  int (*contact)(void*, double, double, double*);
  int (*valid)(void*, double);
  const char* (*lastError)(void*);
};
]]
api = ffi.cast("struct platon_world_ffi*", api)
local context = api.context
local out = ffi.new("double[8]")
local type, error, tostring = type, error, tostring
local KINDS = { [0] = "solid", "warp", "oneway", "entity" }

-- As lua::shownValue shows a value (the classic path's messages): a number in the shortest form
-- that reads back the same, a string quoted and cut to 40 bytes, else its type.
local function got(v)
  if type(v) == "number" then
    if v ~= v then return "nan" end
    local s
    for digits = 6, 17 do
      s = string.format("%." .. digits .. "g", v)
      if tonumber(s) == v then break end
    end
    return s
  end
  if type(v) == "string" then
    local shown = v:sub(1, 40):gsub('[%z\1-\31"\\]', "?")
    return '"' .. shown .. (#v > 40 and '..."' or '"')
  end
  return type(v)
end

local function fail(status, what, v, v2, v3)
  if status == 1 then error("argument 1: expected " .. what .. " handle, got " .. got(v), 3) end
  if status == 2 then error("argument 1: stale entity handle (destroyed, or never created)", 3) end
  if status == 3 then error("position: the entity is in no map part (insert it first)", 3) end
  if status == 4 then error("argument 1: no map part " .. tostring(v), 3) end
  if status == 5 then error("argument 1: expected an integer in [0, 4294967295], got " .. got(v), 3) end
  if status == 6 then error("argument 2: expected a velocity within +-2^30 units per frame, got " .. got(v2), 3) end
  if status == 8 then error("argument 3: expected a velocity within +-2^30 units per frame, got " .. got(v3), 3) end
  error(ffi.string(api.lastError(context)), 3)  -- what the world's C++ said
end

local function number(v, i, what)
  if type(v) ~= "number" then error("argument " .. i .. ": expected " .. what .. ", got " .. got(v), 3) end
end

function world.position(e)
  number(e, 1, "an entity handle")
  local s = api.position(context, e, out)
  if s ~= 0 then fail(s, "an entity", e) end
  return out[0], out[1], out[2]
end

function world.velocity(e)
  number(e, 1, "an entity handle")
  local s = api.velocity(context, e, out)
  if s ~= 0 then fail(s, "an entity", e) end
  return out[0], out[1]
end

function world.setVelocity(e, vx, vy)
  number(e, 1, "an entity handle")
  number(vx, 2, "a number")
  number(vy, 3, "a number")
  local s = api.setVelocity(context, e, vx, vy)
  if s ~= 0 then fail(s, "an entity", e, vx, vy) end
end

function world.valid(e)
  if type(e) ~= "number" then return false end
  return api.valid(context, e) == 1
end

function world.gravity(part)
  number(part, 1, "a number")
  local s = api.gravity(context, part, out)
  if s ~= 0 then fail(s, "a part", part) end
  return out[0], out[1]
end

function world.contactCount(e)
  number(e, 1, "an entity handle")
  local s = api.contactCount(context, e, out)
  if s ~= 0 then fail(s, "an entity", e) end
  return out[0]
end

function world.contact(e, i)
  number(e, 1, "an entity handle")
  number(i, 2, "a number")
  local s = api.contact(context, e, i, out)
  if s == 5 then
    api.contactCount(context, e, out)
    error("argument 2: expected an integer in [1, " .. (out[0] + 1) .. "], got " .. got(i), 2)
  end
  if s ~= 0 then fail(s, "an entity", e) end
  if out[0] == -2 then return end  -- past the last contact: nothing, as ipairs-style loops expect
  local line, other = out[5], out[6]
  if line < 0 then line = nil end  -- against a body
  if other < 0 then other = nil end
  return out[0], out[1], out[2], KINDS[out[3]], out[4], line, other
end
