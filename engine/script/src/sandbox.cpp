#include "sandbox.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "embedded_lua.h"
#include "lua_host.h"

namespace platon::script {

namespace {

// How many keys 1, 2, ... the table at index 1 holds in a row (at most kMaxOrderedKeys): the
// array part the fixed order walks first.
size_t arrayLength(lua_State* L) {
  size_t n = 0;
  for (;; ++n) {
    lua_rawgeti(L, 1, static_cast<int>(n + 1));
    const bool present = !lua_isnil(L, -1);
    lua_pop(L, 1);
    if (!present || n >= kMaxOrderedKeys) return n;
  }
}

// A key of the fixed order outside the array part: a number, a string or a boolean.
struct Key {
  int kind;
  double number = 0;
  const char* text = nullptr;  // the table's own string: alive while the table is unchanged
  size_t length = 0;
  bool boolean = false;
};

bool bytesBefore(const Key& a, const Key& b) {
  const int c = std::memcmp(a.text, b.text, std::min(a.length, b.length));
  return c != 0 ? c < 0 : a.length < b.length;
}

// Calls visit(key) for every key of the table at index 1 outside its array part 1..n; returns why
// the keys have no fixed order ("" when they have one).
template <class Visit>
std::string visitKeys(lua_State* L, size_t n, Visit&& visit) {
  size_t others = 0;
  lua_pushnil(L);
  while (lua_next(L, 1)) {
    lua_pop(L, 1);
    if (++others > kMaxOrderedKeys) {
      lua_pop(L, 1);
      return "pairs over more than 1000000 keys in a sandbox (it would take too long to order them)";
    }
    Key key{lua_type(L, -1)};
    if (key.kind == LUA_TNUMBER) {
      key.number = lua_tonumber(L, -1);
      if (key.number >= 1 && key.number <= static_cast<double>(n) && key.number == std::floor(key.number)) {
        --others;  // in the array part
        continue;
      }
    } else if (key.kind == LUA_TSTRING) {
      key.text = lua_tolstring(L, -1, &key.length);
    } else if (key.kind == LUA_TBOOLEAN) {
      key.boolean = lua_toboolean(L, -1);
    } else {
      std::string why = std::string("pairs over ") + lua_typename(L, key.kind) +
                        " keys has no fixed order in a replayable game (key the table by numbers, strings or booleans)";
      lua_pop(L, 1);
      return why;
    }
    visit(key);
  }
  return "";
}

void pushKey(lua_State* L, const Key& key) {
  if (key.kind == LUA_TNUMBER)
    lua_pushnumber(L, key.number);
  else if (key.kind == LUA_TSTRING)
    lua_pushlstring(L, key.text, key.length);
  else
    lua_pushboolean(L, key.boolean);
}

int refuse(lua_State* L, const std::string& why) {
  lua_pushnil(L);
  lua_pushlstring(L, why.data(), why.size());
  return 2;
}

// The first key of the fixed order and the array part's length, in one pass that builds nothing:
// next(t) (what "is it empty?" asks) costs a walk over the keys, not a sort. Every key is still
// visited, so a table whose keys have no fixed order is refused by next(t) as by pairs(t).
int firstKey(lua_State* L, int64_t& cost) {
  const size_t n = arrayLength(L);
  cost += static_cast<int64_t>(n);
  bool any = false;
  Key first{LUA_TNIL};
  auto rank = [](const Key& k) { return k.kind == LUA_TNUMBER ? 0 : k.kind == LUA_TSTRING ? 1 : k.boolean ? 3 : 2; };
  const std::string why = visitKeys(L, n, [&](const Key& key) {
    const bool before =
        !any || rank(key) < rank(first) ||
        (rank(key) == rank(first) &&
         (key.kind == LUA_TNUMBER ? key.number < first.number : key.kind == LUA_TSTRING && bytesBefore(key, first)));
    if (before) first = key;
    any = true;
    ++cost;
  });
  if (!why.empty()) return refuse(L, why);
  if (n > 0)
    lua_pushnumber(L, 1);
  else if (any)
    pushKey(L, first);
  else
    lua_pushnil(L);
  lua_pushnumber(L, static_cast<double>(n));
  return 2;
}

// What sorting m keys costs in steps: about m log2 m comparisons.
int64_t sortCost(size_t m) {
  int64_t log = 1;
  while ((size_t{1} << log) < m) ++log;
  return static_cast<int64_t>(m) * log;
}

int allKeys(lua_State* L, int64_t& cost) {
  // The array part the walk began with, when a walk's first key came from firstKey: its keys keep
  // their place even if one of them was removed since (the rest would sort among the numbers).
  const size_t n = lua_isnumber(L, 2)
                       ? static_cast<size_t>(std::clamp(lua_tonumber(L, 2), 0.0, double(kMaxOrderedKeys)))
                       : arrayLength(L);
  std::vector<double> numbers;
  std::vector<Key> strings;
  bool hasFalse = false, hasTrue = false;
  const std::string why = visitKeys(L, n, [&](const Key& key) {
    if (key.kind == LUA_TNUMBER)
      numbers.push_back(key.number);
    else if (key.kind == LUA_TSTRING)
      strings.push_back(key);
    else
      (key.boolean ? hasTrue : hasFalse) = true;
  });
  if (!why.empty()) return refuse(L, why);
  cost += 2 * static_cast<int64_t>(n) + sortCost(numbers.size()) + sortCost(strings.size()) +
          static_cast<int64_t>(numbers.size() + strings.size());
  std::sort(numbers.begin(), numbers.end());
  std::sort(strings.begin(), strings.end(), bytesBefore);
  lua_createtable(L, static_cast<int>(n + numbers.size() + strings.size() + 2), 0);
  int k = 0;
  for (size_t i = 1; i <= n; ++i) {
    lua_rawgeti(L, 1, static_cast<int>(i));
    const bool present = !lua_isnil(L, -1);
    lua_pop(L, 1);
    if (!present) continue;
    lua_pushnumber(L, static_cast<double>(i));
    lua_rawseti(L, -2, ++k);
  }
  for (const double d : numbers) {
    lua_pushnumber(L, d);
    lua_rawseti(L, -2, ++k);
  }
  for (const Key& key : strings) {
    pushKey(L, key);
    lua_rawseti(L, -2, ++k);
  }
  if (hasFalse) {
    lua_pushboolean(L, 0);
    lua_rawseti(L, -2, ++k);
  }
  if (hasTrue) {
    lua_pushboolean(L, 1);
    lua_rawseti(L, -2, ++k);
  }
  return 1;
}

}  // namespace

namespace {

int countedLess(lua_State* L) {
  chargeSteps(L, 1);
  const CallbackDepth nested(L);  // the comparator, or an __lt metamethod, may sort again
  if (lua_isnil(L, lua_upvalueindex(1))) {
    lua_pushboolean(L, lua_lessthan(L, 1, 2));
    return 1;
  }
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_pushvalue(L, 1);
  lua_pushvalue(L, 2);
  lua_call(L, 2, 1);
  return 1;
}

}  // namespace

int countedComparator(lua_State* L) {
  lua_settop(L, 1);
  lua_pushcclosure(L, countedLess, 1);
  return 1;
}

// The keys are walked, and sorted, in C, where no hook counts: their work is charged here, once
// the vectors are gone (the charge may stop the sandbox).
int orderedKeys(lua_State* L) {
  luaL_checktype(L, 1, LUA_TTABLE);
  int64_t cost = 0;
  const int results = lua_isboolean(L, 2) && lua_toboolean(L, 2) ? firstKey(L, cost) : allKeys(L, cost);
  chargeSteps(L, cost);
  return results;
}

// What a sandbox holds, and why each thing it lacks is missing (docs/scripting.md, "Sandbox"):
//   io, os (but time, date, clock: the game's clock), debug, ffi, jit, package, require, module:
//     reach the machine or the engine's internals;
//   load, loadstring, loadfile, dofile: bytecode is unverified in LuaJIT and can break memory
//     safety; text could be loaded, but nothing needs it;
//   getfenv, setfenv: would hand out the trusted globals;
//   rawset: would write past the engine's read-only tables;
//   newproxy, gcinfo, collectgarbage (but "count"): GC control;
//   string.dump: produces bytecode.
// xpcall runs its handler after the stack unwound (see safeXpcall below).
// Replays must be exact, so what would differ between runs or machines is the game's: math.random
// is a deterministic generator per sandbox, os.time/clock/date read the game clock, pairs, next
// and table.foreach walk keys in a fixed order, tostring names tables and functions by a counter,
// not an address.
// The pattern functions count their steps (lua_pattern.cpp); table.sort charges each comparison
// and refuses huge tables (it
// sorts in C, where no hook runs).
// For every script: the shared string metatable is locked (getmetatable("") returns "locked"), and
// its methods (s:find(...)) are the counted pattern functions, without dump.
std::string_view sandboxPrelude() { return embedded_lua::sandbox_prelude; }

}  // namespace platon::script
