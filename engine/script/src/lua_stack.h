// The one binding layer between C++ and LuaJIT: typed reads of Lua arguments, typed pushes, and
// the wrapper that turns a C++ exception into a Lua error. Every function Lua can call is
// wrapped by `bound<F>`, so no C++ exception ever crosses into Lua and no Lua error unwinds
// through a C++ frame that holds a live object: checks throw ArgError inside the try block,
// the wrapper leaves it, and only then raises the Lua error.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <lua.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "platon/physics/ids.h"
#include "platon/script/script_error.h"

namespace platon::script::lua {

// A bad argument from Lua. `bound` turns it into a Lua error at the caller's file:line.
class ArgError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline std::string typeName(lua_State* L, int index) { return luaL_typename(L, index); }

// The value at `index` as an error message shows it: a number in the shortest form that reads
// back the same (no 300 digits for 1e300), a string quoted and cut to 40 bytes, else its type.
inline std::string shownValue(lua_State* L, int index) {
  if (lua_type(L, index) == LUA_TNUMBER) {
    const double v = lua_tonumber(L, index);
    if (std::isnan(v)) return "nan";
    char text[32];
    for (int digits = 6; digits <= 17; ++digits) {
      std::snprintf(text, sizeof text, "%.*g", digits, v);
      if (std::strtod(text, nullptr) == v) break;
    }
    return text;
  }
  if (lua_type(L, index) == LUA_TSTRING) {
    size_t length = 0;
    const char* s = lua_tolstring(L, index, &length);
    std::string out = "\"";
    for (size_t i = 0; i < length && i < 40; ++i)
      out += static_cast<unsigned char>(s[i]) >= 0x20 && s[i] != '"' && s[i] != '\\' ? std::string(1, s[i]) : "?";
    return out + (length > 40 ? "...\"" : "\"");
  }
  return typeName(L, index);
}

[[noreturn]] inline void argError(lua_State* L, int index, std::string_view expected) {
  throw ArgError("argument " + std::to_string(index) + ": expected " + std::string(expected) + ", got " +
                 shownValue(L, index));
}

inline double checkNumber(lua_State* L, int index) {
  if (lua_type(L, index) != LUA_TNUMBER) argError(L, index, "a number");
  const double value = lua_tonumber(L, index);
  if (!std::isfinite(value)) argError(L, index, "a finite number");
  return value;
}

// An integer in [low, high]; a fraction or a value out of range is an error, never a silent cast.
inline int64_t checkInteger(lua_State* L, int index, int64_t low, int64_t high) {
  const double value = checkNumber(L, index);
  if (value != std::floor(value) || value < static_cast<double>(low) || value > static_cast<double>(high))
    argError(L, index, "an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
  return static_cast<int64_t>(value);
}

inline int32_t checkInt32(lua_State* L, int index, int32_t low = INT32_MIN, int32_t high = INT32_MAX) {
  return static_cast<int32_t>(checkInteger(L, index, low, high));
}

inline uint32_t checkUint32(lua_State* L, int index) {
  return static_cast<uint32_t>(checkInteger(L, index, 0, UINT32_MAX));
}

inline bool checkBoolean(lua_State* L, int index) {
  if (lua_type(L, index) != LUA_TBOOLEAN) argError(L, index, "a boolean");
  return lua_toboolean(L, index) != 0;
}

inline std::string_view checkString(lua_State* L, int index) {
  if (lua_type(L, index) != LUA_TSTRING) argError(L, index, "a string");
  size_t length = 0;
  const char* text = lua_tolstring(L, index, &length);
  return {text, length};
}

inline void checkTable(lua_State* L, int index) {
  if (lua_type(L, index) != LUA_TTABLE) argError(L, index, "a table");
}

inline void checkFunction(lua_State* L, int index) {
  if (lua_type(L, index) != LUA_TFUNCTION) argError(L, index, "a function");
}

// A contact normal (not normalized, Q16-scaled integers) as the unit vector Lua sees. One
// definition for world.contact, its FFI twin and the rules' contact(), so all three agree to the bit.
inline void unitNormal(int64_t x, int64_t y, double& nx, double& ny) {
  const double dx = static_cast<double>(x), dy = static_cast<double>(y);
  const double length = std::sqrt(dx * dx + dy * dy);
  nx = length > 0 ? dx / length : 0;
  ny = length > 0 ? dy / length : 0;
}

// Entity and platform handles as Lua numbers: index + 2^24 * generation, exact in a double while
// the index stays below 2^24 and the generation below 2^29 (a slot reused 536 million times);
// beyond that pushing the handle is an error, never a wrong handle.
constexpr double kHandleIndexScale = 16777216.0;

struct HandleBits {
  uint32_t index = UINT32_MAX;
  uint32_t generation = 0;
};

inline double handleNumber(uint32_t index, uint32_t generation) {
  if (index >= (1u << 24) || generation >= (1u << 29))
    throw ArgError("handle out of the range Lua numbers hold exactly");
  return static_cast<double>(index) + kHandleIndexScale * static_cast<double>(generation);
}

inline void pushHandle(lua_State* L, uint32_t index, uint32_t generation) {
  lua_pushnumber(L, handleNumber(index, generation));
}

inline void pushEntity(lua_State* L, physics::EntityId id) {
  if (!id.isSet()) return lua_pushnil(L);
  pushHandle(L, id.index, id.generation);
}

// The handle's parts, or nothing when the value is not a handle number at all.
inline std::optional<HandleBits> toHandle(lua_State* L, int index) {
  const double value = lua_type(L, index) == LUA_TNUMBER ? lua_tonumber(L, index) : -1;
  if (!(value >= 0) || value != std::floor(value) || value >= 9007199254740992.0) return std::nullopt;
  const auto bits = static_cast<uint64_t>(value);
  return HandleBits{static_cast<uint32_t>(bits % (1u << 24)), static_cast<uint32_t>(bits >> 24)};
}

// Platform handles are the negative numbers -(1 + index + 2^24 * generation), so that no number
// is both an entity's and a platform's handle: passing one for the other is an error, never the
// wrong object.
inline double platformNumber(uint32_t index, uint32_t generation) { return -1.0 - handleNumber(index, generation); }

// The parts of a platform number (platformNumber's inverse; the number must be one).
inline HandleBits platformBits(double value) {
  const auto bits = static_cast<uint64_t>(-1.0 - value);
  return HandleBits{static_cast<uint32_t>(bits % (1u << 24)), static_cast<uint32_t>(bits >> 24)};
}

inline std::optional<HandleBits> toPlatformHandle(lua_State* L, int index) {
  const double value = lua_type(L, index) == LUA_TNUMBER ? lua_tonumber(L, index) : 1;
  if (!(value <= -1) || value != std::floor(value) || value <= -9007199254740992.0) return std::nullopt;
  return platformBits(value);
}

inline HandleBits checkHandle(lua_State* L, int index, std::string_view what) {
  const std::optional<HandleBits> handle = toHandle(L, index);
  if (!handle) argError(L, index, std::string(what) + " handle");
  return *handle;
}

// Wraps `F(lua_State*) -> int` (results pushed) as a lua_CFunction: a C++ exception becomes a Lua
// error "file:line: name: message" at the calling Lua line. Lua errors raised inside F by the Lua
// API itself (out of memory) pass through: LuaJIT unwinds x64 C++ frames like exceptions.
// A ScriptError (a script that F loaded or called failed) already names its own file:line and
// passes unchanged.
template <int (*F)(lua_State*)>
int bound(lua_State* L) {
  std::string error;
  bool located = false;
  try {
    return F(L);
  } catch (const ScriptError& e) {
    error = e.what();
    located = true;
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (located) {
    lua_pushlstring(L, error.data(), error.size());
  } else {
    luaL_where(L, 1);
    lua_pushlstring(L, error.data(), error.size());
    lua_concat(L, 2);
  }
  return lua_error(L);
}

// A registry reference that frees itself: functions and tables C++ keeps across calls.
class Ref {
 public:
  Ref() = default;
  Ref(lua_State* L, int index) : L_(L) {
    lua_pushvalue(L, index);
    ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  }
  Ref(const Ref&) = delete;
  Ref& operator=(const Ref&) = delete;
  Ref(Ref&& other) noexcept : L_(other.L_), ref_(other.ref_) { other.ref_ = LUA_NOREF; }
  Ref& operator=(Ref&& other) noexcept {
    if (this != &other) {
      reset();
      L_ = other.L_, ref_ = other.ref_;
      other.ref_ = LUA_NOREF;
    }
    return *this;
  }
  ~Ref() { reset(); }
  void reset() {
    if (L_ && ref_ != LUA_NOREF && ref_ != LUA_REFNIL) luaL_unref(L_, LUA_REGISTRYINDEX, ref_);
    ref_ = LUA_NOREF;
  }
  bool isSet() const { return ref_ != LUA_NOREF && ref_ != LUA_REFNIL; }
  void push() const { lua_rawgeti(L_, LUA_REGISTRYINDEX, ref_); }

 private:
  lua_State* L_ = nullptr;
  int ref_ = LUA_NOREF;
};

// f(...) -> the results of f(...), as a plain C function (no C++ object lives in its frame, so a
// Lua error may unwind through it). Trusted code calls sandboxed functions, which run with the JIT
// off, through it: LuaJIT stitches the caller's trace around a C function instead of aborting it
// and, after a few aborts, blacklisting the caller.
inline int callThrough(lua_State* L) {
  luaL_checktype(L, 1, LUA_TFUNCTION);
  lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
  return lua_gettop(L);
}

// Restores the stack top on scope exit: C++ code that reads Lua values cannot leak slots.
class StackGuard {
 public:
  explicit StackGuard(lua_State* L) : L_(L), top_(lua_gettop(L)) {}
  ~StackGuard() { lua_settop(L_, top_); }
  StackGuard(const StackGuard&) = delete;
  StackGuard& operator=(const StackGuard&) = delete;

 private:
  lua_State* L_;
  int top_;
};

}  // namespace platon::script::lua
