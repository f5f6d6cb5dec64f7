#include "lua_rules.h"

#include <cmath>

namespace platon::script {
namespace {

constexpr const char* kNames[] = {"pierce", "beginContact", "overContact", "endContact",
                                  "contact", "touchContact", "crushed"};
using lua::pushEntity;

}  // namespace

LuaRules::LuaRules(LuaHost& host, int index) : host_(host) {
  lua_State* L = host.state();
  lua::StackGuard guard(L);
  if (index < 0 && index > LUA_REGISTRYINDEX) index = lua_gettop(L) + 1 + index;
  if (lua_type(L, index) != LUA_TTABLE) throw ScriptError("rules: the script must return a table of callbacks", "");
  for (int i = 0; i < kCount; ++i) {
    lua_getfield(L, index, kNames[i]);
    if (lua_isfunction(L, -1)) callbacks_[i] = lua::Ref(L, -1);
    else if (!lua_isnil(L, -1))
      throw ScriptError(std::string("rules: '") + kNames[i] + "' is a " + luaL_typename(L, -1) + ", not a function", "");
    lua_pop(L, 1);
  }
  const char* kinds[] = {"solid", "warp", "oneway", "entity"};
  for (int i = 0; i < 4; ++i) {
    lua_pushstring(L, kinds[i]);
    kindNames_[i] = lua::Ref(L, -1);
    lua_pop(L, 1);
  }
}

int LuaRules::pushLine(physics::EntityId entity, const physics::LineRef& line) {
  lua_State* L = host_.state();
  pushEntity(L, entity);
  lua_pushnumber(L, line.tag);
  const bool withEntity = line.index == physics::kNoLine;
  kindNames_[withEntity ? 3 : static_cast<int>(line.kind)].push();
  lua_pushnumber(L, line.part);
  if (withEntity) lua_pushnil(L);
  else lua_pushnumber(L, line.index);
  return 5;
}

bool LuaRules::pierce(physics::EntityId entity, const physics::LineRef& line) {
  if (!callbacks_[kPierce].isSet()) return Rules::pierce(entity, line);
  lua_State* L = host_.state();
  callbacks_[kPierce].push();
  host_.call(pushLine(entity, line), 1);
  const bool passes = lua_toboolean(L, -1) != 0;
  lua_pop(L, 1);
  return passes;
}

void LuaRules::event(Callback which, const physics::Contact& c) {
  if (!callbacks_[which].isSet()) return;
  lua_State* L = host_.state();
  callbacks_[which].push();
  const int n = pushLine(c.entity, c.line);
  pushEntity(L, c.other);
  host_.call(n + 1, 0);
}

void LuaRules::contact(const physics::Contact& c, physics::ContactResponse& response) {
  if (!callbacks_[kContact].isSet()) return;
  lua_State* L = host_.state();
  callbacks_[kContact].push();
  const int n = pushLine(c.entity, c.line);
  double nx = 0, ny = 0;
  lua::unitNormal(c.normal.x, c.normal.y, nx, ny);
  lua_pushnumber(L, nx);
  lua_pushnumber(L, ny);
  pushEntity(L, c.other);
  host_.call(n + 3, 1);
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
    throw ScriptError("rules: contact() returned a " + std::string(lua_typename(L, type)) +
                          "; return nothing, false, or {slide =, keepVelocity =, restitution =}",
                      "");
  }
  lua_getfield(L, -1, "slide");
  if (!lua_isnil(L, -1)) response.slide = lua_toboolean(L, -1) != 0;
  lua_getfield(L, -2, "keepVelocity");
  if (!lua_isnil(L, -1)) response.removeNormalVelocity = lua_toboolean(L, -1) == 0;
  lua_getfield(L, -3, "restitution");
  if (!lua_isnil(L, -1)) {
    const double r = lua_tonumber(L, -1);
    if (lua_type(L, -1) != LUA_TNUMBER || !(r >= 0 && r <= 1)) {
      lua_pop(L, 4);
      throw ScriptError("rules: contact() returned restitution outside [0, 1]", "");
    }
    response.restitution = {std::llround(r * 65536), 65536};
  }
  lua_pop(L, 4);
}

}  // namespace platon::script
