// The FFI fast path of platon.world: the calls a player script makes every frame (position,
// velocity, setVelocity, gravity, contactCount, contact, valid) as C functions LuaJIT calls from inside
// its compiled traces (~3 ns), where a classic Lua C function costs ~16 ns and ends the trace.
// bench/script/script_frames measures the difference.
//
// Rules of the FFI boundary: plain C types only (no struct by value), and no C++ exception may
// cross it, so each function catches everything and returns a status the Lua wrapper turns into
// the same error message, at the same caller's line, as the classic function would give. The
// wrappers replace the classic functions in the API table; sandboxes reach them through their
// read-only view and cannot reach the FFI itself (no ffi, no debug, no upvalues).
#include <cmath>

#include "script_context.h"

namespace platon::script {
namespace {

using physics::EntityId;

enum Status : int {
  kOk = 0,
  kNotHandle = 1,
  kStale = 2,
  kNotInserted = 3,
  kNoPart = 4,
  kBadIndex = 5,
  kBadValue = 6,
  kFailed = 7,
  kBadValue3 = 8
};

struct WorldFfi {
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

physics::World& worldOf(void* context) { return static_cast<ScriptContext*>(context)->scene->world(); }

int entityOf(physics::World& world, double handle, EntityId& out) {
  if (!(handle >= 0) || handle != std::floor(handle) || handle >= 9007199254740992.0) return kNotHandle;
  const auto bits = static_cast<uint64_t>(handle);
  out = {static_cast<uint32_t>(bits % (1u << 24)), static_cast<uint32_t>(bits >> 24)};
  return world.valid(out) ? kOk : kStale;
}

// Runs f; an exception becomes kFailed, its message kept for lastError().
template <class F>
int guarded(void* context, F&& f) noexcept {
  try {
    return f();
  } catch (const std::exception& e) {
    try {
      static_cast<ScriptContext*>(context)->ffiError = e.what();
    } catch (...) {}
    return kFailed;
  } catch (...) {
    return kFailed;
  }
}

// The entity functions' shared part: the handle checked, then f(world, entity) with nothing thrown.
template <class F>
int withEntity(void* context, double handle, F&& f) noexcept {
  return guarded(context, [&] {
    physics::World& world = worldOf(context);
    EntityId e;
    if (const int s = entityOf(world, handle, e)) return s;
    return f(world, e);
  });
}

int ffiPosition(void* context, double handle, double* out) {
  return withEntity(context, handle, [&](physics::World& world, EntityId e) {
    const physics::EntityView view = world.entity(e);
    if (!view.inserted()) return static_cast<int>(kNotInserted);
    const physics::InstanceView anchor = view.instance(0);
    out[0] = anchor.part, out[1] = anchor.position.x, out[2] = anchor.position.y;
    return static_cast<int>(kOk);
  });
}

int ffiVelocity(void* context, double handle, double* out) {
  return withEntity(context, handle, [&](physics::World& world, EntityId e) {
    const physics::Vec2w v = world.entity(e).velocity();
    out[0] = static_cast<double>(v.x) / kQ16, out[1] = static_cast<double>(v.y) / kQ16;
    return static_cast<int>(kOk);
  });
}

int ffiSetVelocity(void* context, double handle, double vx, double vy) {
  return withEntity(context, handle, [&](physics::World& world, EntityId e) {
    if (!(std::fabs(vx) <= kMaxPerFrame)) return static_cast<int>(kBadValue);
    if (!(std::fabs(vy) <= kMaxPerFrame)) return static_cast<int>(kBadValue3);
    world.setVelocity(e, {std::llround(vx * kQ16), std::llround(vy * kQ16)});
    return static_cast<int>(kOk);
  });
}

int ffiGravity(void* context, double part, double* out) {
  return guarded(context, [&] {
    physics::World& world = worldOf(context);
    if (!(part >= 0 && part <= 4294967295.0) || part != std::floor(part)) return static_cast<int>(kBadIndex);
    const physics::MapPart* map = world.findMapPart(static_cast<physics::MapPartId>(part));
    if (!map) return static_cast<int>(kNoPart);
    out[0] = static_cast<double>(map->gravity().x) / kQ16, out[1] = static_cast<double>(map->gravity().y) / kQ16;
    return static_cast<int>(kOk);
  });
}

int ffiContactCount(void* context, double handle, double* out) {
  return withEntity(context, handle, [&](physics::World& world, EntityId e) {
    out[0] = static_cast<double>(world.entity(e).contacts().size());
    return static_cast<int>(kOk);
  });
}

// out: nx, ny, tag, kind (0 solid, 1 warp, 2 oneway, 3 entity), part, line, other (-1: none).
int ffiContact(void* context, double handle, double i, double* out) {
  return withEntity(context, handle, [&](physics::World& world, EntityId e) {
    const auto contacts = world.entity(e).contacts();
    if (!(i >= 1 && i <= static_cast<double>(contacts.size()) + 1) || i != std::floor(i))
      return static_cast<int>(kBadIndex);
    if (i > static_cast<double>(contacts.size())) {
      out[0] = -2;  // past the end: no results, as the classic function returns none
      return static_cast<int>(kOk);
    }
    const physics::Contact& c = contacts[static_cast<size_t>(i) - 1];
    lua::unitNormal(c.normal.x, c.normal.y, out[0], out[1]);
    out[2] = c.line.tag;
    out[3] = c.line.index == physics::kNoLine ? 3 : static_cast<int>(c.line.kind);
    out[4] = c.part;
    out[5] = c.line.index;
    out[6] = c.other.isSet() ? static_cast<double>(c.other.index) + 16777216.0 * static_cast<double>(c.other.generation)
                             : -1;
    return static_cast<int>(kOk);
  });
}

int ffiValid(void* context, double handle) {
  EntityId e;
  return guarded(context, [&] { return entityOf(worldOf(context), handle, e) == kOk ? 1 : 0; });
}

const char* ffiLastError(void* context) { return static_cast<ScriptContext*>(context)->ffiError.c_str(); }

// The Lua side, run once in the trusted state: `api` is the struct above, `world` the table the
// classic functions live in. Messages match world_api.cpp's.
constexpr const char* kWrappers = R"lua(
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
  local other = out[6]
  if other < 0 then other = nil end
  return out[0], out[1], out[2], KINDS[out[3]], out[4], out[5], other
end
)lua";

}  // namespace

void registerWorldFfi(LuaHost& host, ScriptContext& context) {
  static_assert(sizeof(WorldFfi) == 9 * sizeof(void*));
  lua_State* L = host.state();
  lua::StackGuard guard(L);
  // The struct lives as long as the context (one per ScriptSystem); Lua holds a pointer to it.
  context.ffi = std::make_shared<WorldFfi>(WorldFfi{&context, ffiPosition, ffiVelocity, ffiSetVelocity, ffiGravity,
                                                    ffiContactCount, ffiContact, ffiValid, ffiLastError});
  // Sandboxes keep the classic C functions: they run interpreted, where an FFI call is slow, and
  // their calls must cost the same steps in every run (a wrapper the JIT compiled counts none).
  host.pushApi();
  lua_getfield(L, -1, "world");
  lua_newtable(L);
  for (lua_pushnil(L); lua_next(L, -3);) {  // rawset below pops the value and a copy of the key
    lua_pushvalue(L, -2);
    lua_insert(L, -2);
    lua_rawset(L, -4);
  }
  host.setSandboxOverride("world");
  lua_pop(L, 2);
  host.loadString(kWrappers, "=platon.world (FFI)", Trust::Trusted);
  lua_getglobal(L, "require");
  lua_pushliteral(L, "ffi");
  host.call(1, 1);
  lua_pushlightuserdata(L, context.ffi.get());
  host.pushApi();
  lua_getfield(L, -1, "world");
  lua_remove(L, -2);
  host.call(3, 0);
}

}  // namespace platon::script
