// The data reader's reference (core/lua_data.h): whether a value LuaJIT read is the value the
// reader read. Shared by the data reader's tests and its fuzz target.
#pragma once
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <lua.hpp>
#include <string>

#include "platon/core/lua_data.h"

namespace platon::testing {

// Whether the Lua value at `index` is what the data reader read; `why` says where it differs.
inline bool sameAsLua(lua_State* L, int index, const core::DataValue& v, std::string& why) {
  using Kind = core::DataValue::Kind;
  const int type = lua_type(L, index);
  switch (v.kind) {
    case Kind::Nil:
      if (type == LUA_TNIL) return true;
      break;
    case Kind::Boolean:
      if (type == LUA_TBOOLEAN && (lua_toboolean(L, index) != 0) == v.boolean) return true;
      break;
    case Kind::Number:
      if (type == LUA_TNUMBER) {
        const double lua = lua_tonumber(L, index);
        if (std::bit_cast<uint64_t>(lua) == std::bit_cast<uint64_t>(v.number)) return true;  // -0 is not 0
        char text[80];
        std::snprintf(text, sizeof text, "Lua reads %.17g, the reader %.17g", lua, v.number);
        why = text;
        return false;
      }
      break;
    case Kind::String:
      if (type == LUA_TSTRING) {
        size_t length = 0;
        const char* bytes = lua_tolstring(L, index, &length);
        if (length == v.text.size() && std::memcmp(bytes, v.text.data(), length) == 0) return true;
        why = "Lua reads the string '" + std::string(bytes, length) + "', the reader '" + v.text + "'";
        return false;
      }
      break;
    case Kind::Table: {
      if (type != LUA_TTABLE) break;
      if (!lua_checkstack(L, 8)) return true;  // deeper than Lua's C stack lets us look
      size_t written = 0;
      for (const core::DataEntry& e : v.entries) {
        if (e.value.kind != Kind::Nil) ++written;
        if (e.key.kind == Kind::String)
          lua_pushlstring(L, e.key.text.data(), e.key.text.size());
        else if (e.key.kind == Kind::Number)
          lua_pushnumber(L, e.key.number);
        else
          lua_pushboolean(L, e.key.boolean);
        lua_rawget(L, index < 0 ? index - 1 : index);
        const bool same = sameAsLua(L, lua_gettop(L), e.value, why);
        lua_pop(L, 1);
        if (!same) {
          why = "at key " + core::dataKeyText(e.key) + ": " + why;
          return false;
        }
      }
      size_t held = 0;
      for (lua_pushnil(L); lua_next(L, index < 0 ? index - 1 : index); lua_pop(L, 1)) ++held;
      if (held == written) return true;
      why = "Lua's table holds " + std::to_string(held) + " keys, the reader's " + std::to_string(written);
      return false;
    }
    case Kind::Other:
      break;
  }
  why = std::string("Lua reads a ") + lua_typename(L, type) + ", the reader " + core::describeData(v);
  return false;
}

}  // namespace platon::testing
