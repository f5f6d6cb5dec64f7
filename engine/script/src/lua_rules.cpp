#include "lua_rules.h"

#include <cmath>

#include "embedded_lua.h"

namespace platon::script {
namespace {

constexpr const char* kNames[] = {"pierce",  "beginContact", "overContact", "endContact",
                                  "contact", "touchContact", "crushed"};
using lua::pushEntity;

// The FFI trampolines, loaded anew for every LuaRules so that each has prototypes of its own (a
// trace blacklisted for one rules script stays interpreted for that script only; sandboxed rules,
// whose functions run with the JIT off, get none: engine.setRules calls them the classic way).
// Arguments: ffi, the slot's address, the callbacks.
constexpr const char* kTrampolines = embedded_lua::rules_trampolines;  // lua/rules_trampolines.lua

}  // namespace

LuaRules::LuaRules(LuaHost& host, int index, Call how, int sandbox) : host_(host), sandbox_(sandbox) {
  lua_State* L = host.state();
  lua::StackGuard guard(L);
  if (index < 0 && index > LUA_REGISTRYINDEX) index = lua_gettop(L) + 1 + index;
  if (lua_type(L, index) != LUA_TTABLE) throw ScriptError("rules: the script must return a table of callbacks", "");
  // Raw reads: no metamethod of a (sandboxed) script's table runs outside a sandboxed call.
  for (int i = 0; i < kCount; ++i) {
    lua_pushstring(L, kNames[i]);
    lua_rawget(L, index);
    if (!lua_isfunction(L, -1) && !lua_isnil(L, -1))
      throw ScriptError(std::string("rules: '") + kNames[i] + "' is a " + luaL_typename(L, -1) + ", not a function",
                        "");
    if (lua_isfunction(L, -1)) {
      // Where the callback is written, for errors about what it returns (file:line of its start).
      lua_Debug ar;
      lua_pushvalue(L, -1);
      if (lua_getinfo(L, ">S", &ar) && ar.source[0] == '@' && ar.linedefined > 0)
        places_[i] = std::string(ar.source + 1) + ":" + std::to_string(ar.linedefined) + ": ";
    }
    lua_pop(L, 1);
  }
  const char* kinds[] = {"solid", "warp", "oneway", "entity"};
  for (int i = 0; i < 4; ++i) {
    lua_pushstring(L, kinds[i]);
    kindNames_[i] = lua::Ref(L, -1);
    lua_pop(L, 1);
  }
  if (how != Call::Classic) {
    slot_ = std::make_unique<Slot>();
    makeTrampolines(index);
    index = lua_gettop(L);  // the table of trampolines
  }
  for (int i = 0; i < kCount; ++i) {
    lua_pushstring(L, kNames[i]);
    lua_rawget(L, index);
    if (lua_isfunction(L, -1)) callbacks_[i] = lua::Ref(L, -1);
    lua_pop(L, 1);
  }
}

void LuaRules::makeTrampolines(int index) {
  lua_State* L = host_.state();
  host_.loadString(kTrampolines, "=platon/rules (FFI)", Trust::Trusted);
  lua_getglobal(L, "require");
  lua_pushliteral(L, "ffi");
  host_.call(1, 1);
  lua_pushlightuserdata(L, slot_.get());
  // The trampolines read the callbacks raw as well.
  lua_newtable(L);
  for (const char* name : kNames) {
    lua_pushstring(L, name);
    lua_rawget(L, index);
    lua_setfield(L, -2, name);
  }
  host_.call(3, 1);
}

inline int LuaRules::pushLine(physics::EntityId entity, const physics::LineRef& line) {
  const bool withEntity = line.index == physics::kNoLine;
  const int kind = withEntity ? 3 : static_cast<int>(line.kind);
  if (slot_) {
    Slot& s = *slot_;
    s.entity = lua::handleNumber(entity.index, entity.generation);
    s.tag = line.tag, s.kind = kind, s.part = line.part;
    s.line = withEntity ? -1.0 : static_cast<double>(line.index);
    return 0;
  }
  lua_State* L = host_.state();
  pushEntity(L, entity);
  lua_pushnumber(L, line.tag);
  kindNames_[kind].push();
  lua_pushnumber(L, line.part);
  if (withEntity)
    lua_pushnil(L);
  else
    lua_pushnumber(L, line.index);
  return 5;
}

inline int LuaRules::pushOther(physics::EntityId other) {
  if (slot_) {
    slot_->other = other.isSet() ? lua::handleNumber(other.index, other.generation) : -1.0;
    return 0;
  }
  pushEntity(host_.state(), other);
  return 1;
}

inline int LuaRules::pushNormal(const physics::Vec2w& normal) {
  if (slot_) {  // the trampoline makes it a unit vector
    slot_->nx = static_cast<double>(normal.x), slot_->ny = static_cast<double>(normal.y);
    return 0;
  }
  double nx = 0, ny = 0;
  lua::unitNormal(normal.x, normal.y, nx, ny);
  lua_State* L = host_.state();
  lua_pushnumber(L, nx);
  lua_pushnumber(L, ny);
  return 2;
}

void LuaRules::fail(const std::string& message) {
  // A message that does not say where yet (file:line of the callback) gets the script's name.
  const bool placed = message.rfind("rules:", 0) != 0;
  ScriptError error(sandbox_ == kNoSandbox || placed ? message : host_.sandboxName(sandbox_) + ": " + message, "");
  if (sandbox_ == kNoSandbox) throw error;
  host_.keepError(std::move(error));
}

bool LuaRules::invokeSandboxed(int n, int results) {
  try {
    return host_.callSandboxed(sandbox_, n, results);
  } catch (ScriptError& e) {
    host_.keepError(std::move(e));
    return false;
  }
}

bool LuaRules::pierce(physics::EntityId entity, const physics::LineRef& line) {
  if (!callbacks_[kPierce].isSet() || skipped()) return Rules::pierce(entity, line);
  lua_State* L = host_.state();
  const int top = lua_gettop(L);
  callbacks_[kPierce].push();
  if (!invoke(pushArguments(top, [&] { return pushLine(entity, line); }), 1)) return Rules::pierce(entity, line);
  const bool passes = lua_toboolean(L, -1) != 0;
  lua_pop(L, 1);
  return passes;
}

void LuaRules::event(Callback which, const physics::Contact& c) {
  if (!callbacks_[which].isSet() || skipped()) return;
  const int top = lua_gettop(host_.state());
  callbacks_[which].push();
  invoke(pushArguments(top,
                       [&] {
                         const int n = pushLine(c.entity, c.line);  // in this order: the arguments' order
                         return n + pushOther(c.other);
                       }),
         0);
}

void LuaRules::contact(const physics::Contact& c, physics::ContactResponse& response) {
  if (!callbacks_[kContact].isSet() || skipped()) return;
  lua_State* L = host_.state();
  if (slot_ && sandbox_ == kNoSandbox) {  // the engine's own rules: the hot path, kept short
    Slot& s = *slot_;
    // The handles first: one out of range throws before anything is pushed.
    s.entity = lua::handleNumber(c.entity.index, c.entity.generation);
    s.other = c.other.isSet() ? lua::handleNumber(c.other.index, c.other.generation) : -1.0;
    const bool withEntity = c.line.index == physics::kNoLine;
    s.tag = c.line.tag, s.kind = withEntity ? 3 : static_cast<int>(c.line.kind), s.part = c.line.part;
    s.line = withEntity ? -1.0 : static_cast<double>(c.line.index);
    s.nx = static_cast<double>(c.normal.x), s.ny = static_cast<double>(c.normal.y);
    callbacks_[kContact].push();
    host_.call(0, LUA_MULTRET);  // the trampoline leaves nil, false and true in the slot
    if (s.answer == 0) return;
    if (s.answer < 3) {
      response.slide = s.answer == 2;
      return;
    }
  } else {
    const int top = lua_gettop(L);
    callbacks_[kContact].push();
    const int n = pushArguments(top, [&] {
      int pushed = pushLine(c.entity, c.line);  // in this order: the arguments' order
      pushed += pushNormal(c.normal);
      return pushed + pushOther(c.other);
    });
    if (!invoke(n, 1)) return;
  }
  const int type = lua_type(L, -1);
  if (type == LUA_TNIL) {
    lua_pop(L, 1);
    return;
  }
  if (type == LUA_TBOOLEAN) {
    response.slide = lua_toboolean(L, -1) != 0;
    lua_pop(L, 1);
    return;
  }
  if (type != LUA_TTABLE) {
    lua_pop(L, 1);
    fail(places_[kContact] + "rules: contact() returned a " + std::string(lua_typename(L, type)) +
         "; return nothing, false, or {slide =, keepVelocity =, restitution =}");
    return;
  }
  // Raw reads: the table may be a sandboxed script's, and its metamethods must not run out here.
  lua_pushliteral(L, "slide");
  lua_rawget(L, -2);
  if (!lua_isnil(L, -1)) response.slide = lua_toboolean(L, -1) != 0;
  lua_pushliteral(L, "keepVelocity");
  lua_rawget(L, -3);
  if (!lua_isnil(L, -1)) response.removeNormalVelocity = lua_toboolean(L, -1) == 0;
  lua_pushliteral(L, "restitution");
  lua_rawget(L, -4);
  if (!lua_isnil(L, -1)) {
    const double r = lua_tonumber(L, -1);
    if (lua_type(L, -1) != LUA_TNUMBER || !(r >= 0 && r <= 1)) {
      lua_pop(L, 4);
      fail(places_[kContact] + "rules: contact() returned restitution outside [0, 1]");
      return;
    }
    response.restitution = {std::llround(r * 65536), 65536};
  }
  lua_pop(L, 4);
}

}  // namespace platon::script
