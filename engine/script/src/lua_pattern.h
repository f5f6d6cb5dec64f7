// Lua 5.1 patterns with a bound on their work: string.find, match, gmatch and gsub written here
// from the reference manual's pattern rules (section 5.4.1), with LuaJIT 2.1's behaviour at the
// edges (a pattern ends at its first "\0", %g is a class, an argument beyond the string is clamped
// to its end, a "%" that ends a gsub replacement adds a "\0").
//
// LuaJIT's own pattern functions backtrack in C, where no hook runs, so one call can take hours
// (".-.-.-.-b" on 40 characters). These count their steps (every character tried against a pattern
// item, every start position, every character a back-reference or a replacement copies, every byte
// of a [set] read; a set is read once per call into a 256-bit table, not once per character) and give
// up with "pattern too costly (more than 2000000 steps)" past kPatternStepBudget: about 2-6 ms of
// work, whatever the pattern, and a fifth of a frame's budget of steps (lua_host.h), so one call is
// refused (an error pcall can catch) before it could spend the frame's budget. The engine installs them in every
// sandbox's `string` and behind the shared string metatable (s:find(...)), for every script; trusted code keeps
// LuaJIT's own in its global `string`.
#pragma once
#include <cstdint>
#include <lua.hpp>

namespace platon::script {

inline constexpr uint64_t kPatternStepBudget = 2'000'000;

int patternFind(lua_State* L);    // string.find(s, pattern [, init [, plain]])
int patternMatch(lua_State* L);   // string.match(s, pattern [, init])
int patternGmatch(lua_State* L);  // string.gmatch(s, pattern)
int patternGsub(lua_State* L);    // string.gsub(s, pattern, replacement [, n])

// Sets find, match, gmatch and gsub in the table at `index` to the functions above.
void setPatternFunctions(lua_State* L, int index);

}  // namespace platon::script
