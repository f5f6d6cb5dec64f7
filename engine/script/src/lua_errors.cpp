// A LuaHost's errors: the message handler every call runs (the place in front of a message, the
// traceback after it), and messages made printable (NUL bytes shown, a length cut) on their way
// to C++.
#include <algorithm>
#include <cctype>
#include <cstring>

#include "lua_host_shared.h"

namespace platon::script::host {

std::string where(lua_State* L, const LuaHost::Shared& s) {
  const std::string* own = s.current != kNoSandbox ? &s.sandboxes[s.current].source : nullptr;
  lua_Debug ar{};
  for (int level = 0; lua_getstack(L, level, &ar); ++level) {
    if (!lua_getinfo(L, "Sl", &ar) || ar.currentline <= 0 || ar.source[0] != '@') continue;
    // A sandbox's error is placed in its own file or nowhere (its name only): a line of the
    // engine's scripts that happened to call it would send the modder to the wrong file (a world
    // call the sandbox made as a tail call left no frame of its own).
    if (!own || *own == ar.source) return std::string(ar.short_src) + ":" + std::to_string(ar.currentline) + ": ";
  }
  return "";
}

namespace {

// Whether `message` starts with "file:line: " naming a Lua function that is on the stack now: a
// place Lua put there. A message that only looks like one ("the time is 12:30:45", "fake.lua:99:
// x" raised with level 0) is not, and gets the real place in front.
bool placedOnStack(lua_State* L, const char* message) {
  lua_Debug ar{};
  for (int level = 0; lua_getstack(L, level, &ar); ++level) {
    if (!lua_getinfo(L, "Sl", &ar) || ar.what == nullptr || std::strcmp(ar.what, "C") == 0) continue;
    const size_t n = std::strlen(ar.short_src);
    if (std::strncmp(message, ar.short_src, n) != 0 || message[n] != ':') continue;
    const char* q = message + n + 1;
    if (*q < '0' || *q > '9') continue;
    long line = 0;
    while (*q >= '0' && *q <= '9' && line < 100'000'000) line = line * 10 + (*q++ - '0');
    // The frame's own line: "mod.lua:99: x" raised at line 1 only looks like a place.
    if (*q == ':' && line == ar.currentline) return true;
  }
  return false;
}

}  // namespace

// Whether a message already starts with "place:line: " (on its first line): after the call, where
// the handler has placed every message it could.
bool located(const char* message) {
  for (const char* p = message; *p && *p != '\n'; ++p) {
    if (*p != ':' || !(p[1] >= '0' && p[1] <= '9')) continue;
    const char* q = p + 1;
    while (*q >= '0' && *q <= '9') ++q;
    if (*q == ':') return true;
  }
  return false;
}

namespace {

// An error message as text that prints whole: a NUL (which would end it early wherever it is shown
// as a C string) becomes \0, and it is cut at 16 KB (a script may raise an error of megabytes).
std::string printableText(const char* raw, size_t length) {
  constexpr size_t kLongest = size_t{16} * 1024;
  std::string text;
  text.reserve(std::min(length, kLongest) + 16);
  for (size_t i = 0; i < length && text.size() < kLongest; ++i) {
    if (raw[i] == '\0')
      text += "\\0";
    else
      text += raw[i];
  }
  if (text.size() >= kLongest && length > kLongest) text += "... (cut: " + std::to_string(length) + " bytes in all)";
  return text;
}

std::string printableMessage(lua_State* L, int index) {
  size_t length = 0;
  const char* raw = lua_tolstring(L, index, &length);
  return printableText(raw, length);
}

}  // namespace

// The message handler of every call: the message (file:line in front: Lua puts it there for errors
// raised by Lua code, this adds it for the others) and the traceback, separated by a newline the
// C++ side splits at. Runs where the error was raised. It calls no metamethod of a non-string error
// object: for a stop that point is inside the hook, where no hook fires, and a script's __tostring
// could loop there for ever.
int tracebackHandler(lua_State* L) {
  LuaHost::Shared& s = sharedOf(L);
  OpenReserve reserve(s);
  // Room first: after a stack overflow LuaJIT leaves a little (a push without it fails in here).
  if (!lua_checkstack(L, 8)) return 1;
  size_t length = 0;
  if (const char* raw = lua_type(L, 1) == LUA_TSTRING ? lua_tolstring(L, 1, &length) : nullptr;
      raw && (std::memchr(raw, '\0', length) || length > size_t{16} * 1024)) {  // the traceback takes it as a C string
    const std::string whole = printableMessage(L, 1);
    lua_pushlstring(L, whole.data(), whole.size());
    lua_replace(L, 1);
  }
  const char* message = lua_tostring(L, 1);
  if (!message) message = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
  // A stop's message was placed when the stop was decided; it is raised again at every instruction
  // until the call returns, so where it is raised last is no place of its own.
  const bool stop = s.expired && s.stopMessage == message;
  if (!stop && !placedOnStack(L, message) &&
      (s.current != kNoSandbox || !lua_isstring(L, 1) || std::strstr(message, "stack overflow"))) {
    std::string at = where(L, s);
    if (at.empty() && s.current != kNoSandbox) at = s.sandboxes[s.current].name + ": ";
    lua_pushlstring(L, at.data(), at.size());
    lua_pushstring(L, message);
    lua_concat(L, 2);
    message = lua_tostring(L, -1);
  }
  luaL_traceback(L, L, message, 1);
  return 1;
}

// A report with no address in it: LuaJIT names a built-in function's frame by where its code is
// ("[builtin#19]: at 0x7f..."), and a trusted script's message may hold a table's; an address
// differs from run to run and from machine to machine, and a report must not. Each run of eight
// or more hex digits after "0x" is cut, and "at 0x..." becomes "in a built-in function".
std::string withoutAddresses(std::string text) {
  for (size_t at = text.find("0x"); at != std::string::npos; at = text.find("0x", at + 1)) {
    size_t end = at + 2;
    while (end < text.size() && std::isxdigit(static_cast<unsigned char>(text[end]))) ++end;
    if (end - at - 2 < 8) continue;
    if (at >= 3 && text.compare(at - 3, 3, "at ") == 0) {
      text.replace(at - 3, end - at + 3, "in a built-in function");
      at -= 3;
    } else {
      text.replace(at, end - at, "(an address)");
    }
  }
  return text;
}

// The message and its traceback, each made printable and cut on its own (cutting them together
// lost the traceback of a long message), with no address in either.
ScriptError errorFromStack(lua_State* L, int status, const LuaHost::Shared& shared) {
  if (!lua_isstring(L, -1)) return ScriptError("(error object is not a string)", "");
  size_t length = 0;
  const char* raw = lua_tolstring(L, -1, &length);
  const std::string_view whole(raw, length);
  if (status == LUA_ERRMEM) {
    return ScriptError("script stopped: its Lua state reached the memory limit of " +
                           std::to_string(shared.limits.memoryBytes >> 20) + " MB (" + printableText(raw, length) + ")",
                       "");
  }
  const size_t split = whole.rfind("\nstack traceback:");
  if (split == std::string_view::npos) return ScriptError(withoutAddresses(printableText(raw, length)), "");
  return ScriptError(withoutAddresses(printableText(raw, split)),
                     withoutAddresses(printableText(raw + split + 1, length - split - 1)));
}

}  // namespace platon::script::host
