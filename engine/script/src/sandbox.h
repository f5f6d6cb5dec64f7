// The sandbox's environment factory, written in Lua and run once per state as trusted code.
#pragma once
#include <lua.hpp>
#include <string_view>

namespace platon::script {

// A chunk that takes a table of C functions (print, frames, orderedKeys and the pattern functions)
// and returns newSandbox(name, api) -> environment table, readonly(t, name) -> a read-only view,
// and the sandboxes' tostring (no address in it: what the engine shows of a sandbox's value).
std::string_view sandboxPrelude();

// orderedKeys(t) -> the keys of t in a fixed order (the array part 1..n, then the other numbers
// increasing, strings in byte order, false, true), or nil and why there is none (a key of another
// type, or more than kMaxOrderedKeys keys). What a sandbox's pairs and next walk.
// orderedKeys(t, true) -> only the first key of that order (nil for an empty table), found in one
// pass that builds nothing, or nil and why (the same refusals): what next(t) returns.
int orderedKeys(lua_State* L);
// countedComparator(less) -> a comparator for LuaJIT's table.sort that charges one step to the
// frame's budget for each comparison, then compares with `less` (nil: with <). Sorting runs in C,
// where no hook counts, and LuaJIT's quicksort takes n^2 comparisons on some orders.
int countedComparator(lua_State* L);
inline constexpr size_t kMaxOrderedKeys = 1'000'000;

}  // namespace platon::script
