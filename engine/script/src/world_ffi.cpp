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

#include "embedded_lua.h"
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
    out[5] = c.line.index == physics::kNoLine ? -1 : static_cast<double>(c.line.index) + 1;  // from 1, as lineAt
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
constexpr const char* kWrappers = embedded_lua::world_ffi;  // lua/world_ffi.lua

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
