// What the Lua API functions reach through their upvalue: the scene they act on, the draw list of
// the current frame (or none), the current input. One per ScriptSystem; no globals.
#pragma once
#include <map>
#include <memory>
#include <set>
#include <string>

#include "lua_host.h"
#include "platon/core/draw_list.h"
#include "platon/core/input.h"
#include "platon/core/scene.h"

namespace platon::script {

// Lua numbers are units; the world's are Q16 (1/65536 unit).
inline constexpr double kQ16 = 65536.0;
// The world's largest move per frame, and largest gravity per frame: 2^30 units (2^46 in Q16).
inline constexpr double kMaxPerFrame = 1073741824.0;

struct ScriptContext {
  core::Scene* scene = nullptr;
  core::DrawList* draw = nullptr;  // set only while draw() runs with a renderer
  LuaHost* host = nullptr;
  std::shared_ptr<void> ffi;          // the FFI fast path's function table (world_ffi.cpp), when registered
  std::string ffiError;               // the message of the FFI path's last exception
  physics::EntityId protectedEntity;  // the player's: no sandbox may destroy or erase it
  // The live platforms scripts made (as handle numbers) -> the sandbox that made each (kNoSandbox:
  // trusted code).
  std::map<double, int> platforms;
  // The live bodies sandboxes made (EntityId index << 32 | generation) -> the sandbox: the physics
  // they cost is charged to it, and a sandbox stopped for it loses them.
  std::map<uint64_t, int> madeBy;
  // Draw calls this frame that were dropped over DrawList's limits (one error a frame says so).
  bool drawOverflowReported = false;
};

inline ScriptContext& contextOf(lua_State* L) {
  return *static_cast<ScriptContext*>(lua_touserdata(L, lua_upvalueindex(1)));
}

// Argument `index` as a live entity's handle, or a Lua error naming it (world_api.cpp).
physics::EntityId checkEntity(lua_State* L, int index);

// Registers platon.world.* (world_api.cpp) and platon.draw.* (draw_api.cpp) in the API table
// sandboxes see, with `context` as their upvalue.
void registerWorldApi(LuaHost& host, ScriptContext& context);
void registerDrawApi(LuaHost& host, ScriptContext& context);
void registerSoundApi(LuaHost& host, ScriptContext& context);  // platon.sound.* (sound_api.cpp)
// Replaces the per-frame world functions with FFI calls (world_ffi.cpp). Trusted states only: it
// needs the ffi library, which sandboxes never get.
void registerWorldFfi(LuaHost& host, ScriptContext& context);

// Sets platon.<name> in the API table to a table of `functions` (ends with {nullptr, nullptr}),
// each with `context` as its upvalue.
void addApiTable(LuaHost& host, ScriptContext& context, const char* name, const luaL_Reg* functions);

}  // namespace platon::script
