#include "lua_host.h"

#include <luajit.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>

#include "sandbox.h"

namespace platon::script {

// The allocator's and the hook's view of the host: reached through lua_getallocf's user data, so
// neither needs a global.
struct LuaHost::Shared {
  LuaLimits limits;
  size_t used = 0;
  bool memoryRefused = false;  // the allocator said no since the outermost call began
  // The time budget: set by call() at depth 0, read by the hook.
  bool inCall = false;
  int64_t callStart = 0;  // 0 until the hook first runs inside a call
  bool expired = false;
  std::function<void(std::string_view, std::string_view)> print;
};

namespace {

constexpr int kHookInstructions = 100000;

int64_t monotonicNanoseconds() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return int64_t{t.tv_sec} * 1'000'000'000 + t.tv_nsec;
}

void* limitedAlloc(void* ud, void* ptr, size_t oldSize, size_t newSize) {
  auto* shared = static_cast<LuaHost::Shared*>(ud);
  const size_t old = ptr ? oldSize : 0;
  if (newSize == 0) {
    std::free(ptr);
    shared->used -= old;
    return nullptr;
  }
  if (newSize > old && shared->used - old + newSize > shared->limits.memoryBytes) {
    shared->memoryRefused = true;
    return nullptr;
  }
  void* grown = std::realloc(ptr, newSize);
  if (!grown) return nullptr;
  shared->used = shared->used - old + newSize;
  return grown;
}

LuaHost::Shared& sharedOf(lua_State* L) {
  void* ud = nullptr;
  lua_getallocf(L, &ud);
  return *static_cast<LuaHost::Shared*>(ud);
}

// Runs every kHookInstructions interpreted instructions. Once the budget is spent it fires on every
// instruction and raises each time, so a script cannot catch the error with pcall and go on: every
// Lua frame up to C++ fails in turn.
void budgetHook(lua_State* L, lua_Debug*) {
  LuaHost::Shared& shared = sharedOf(L);
  if (!shared.inCall) return;
  if (!shared.expired) {
    const int64_t now = monotonicNanoseconds();
    if (shared.callStart == 0) {
      shared.callStart = now;
      return;
    }
    if (now - shared.callStart <= shared.limits.callNanoseconds) return;
    shared.expired = true;
    lua_sethook(L, budgetHook, LUA_MASKCOUNT, 1);
  }
  // Name the innermost line of a script file (engine chunks are named "=platon/...").
  lua_Debug where{};
  bool named = false;
  for (int level = 0; !named && lua_getstack(L, level, &where); ++level) {
    if (lua_getinfo(L, "Sl", &where) && where.currentline > 0 && where.source[0] == '@') {
      lua_pushfstring(L, "%s:%d: ", where.short_src, where.currentline);
      named = true;
    }
  }
  if (!named) lua_pushliteral(L, "");
  lua_pushfstring(L, "script stopped: it ran longer than its budget of %d ms in one call (an endless loop?)",
                  static_cast<int>(shared.limits.callNanoseconds / 1'000'000));
  lua_concat(L, 2);
  lua_error(L);
}

// The message handler of every call: the message (file:line already in front for errors raised by
// Lua code) and the traceback, separated by a newline the C++ side splits at.
// Runs where the error was raised. It calls no metamethod of a non-string error object: for the
// time budget's error that point is inside the hook, where no hook fires, and a script's
// __tostring could loop there for ever.
int tracebackHandler(lua_State* L) {
  const char* message = lua_tostring(L, 1);
  if (!message) message = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
  luaL_traceback(L, L, message, 1);
  return 1;
}

int printToSink(lua_State* L) {
  LuaHost::Shared& shared = sharedOf(L);
  size_t nameLength = 0, textLength = 0;
  const char* name = luaL_checklstring(L, 1, &nameLength);
  const char* text = luaL_checklstring(L, 2, &textLength);
  if (shared.print) {
    shared.print({name, nameLength}, {text, textLength});
  } else {
    std::fprintf(stderr, "[%.*s] %.*s\n", static_cast<int>(nameLength), name, static_cast<int>(textLength), text);
  }
  return 0;
}

ScriptError errorFromStack(lua_State* L, int status, const LuaHost::Shared& shared) {
  std::string text = lua_isstring(L, -1) ? lua_tostring(L, -1) : "(error object is not a string)";
  if (status == LUA_ERRMEM || shared.memoryRefused) {
    return ScriptError("script stopped: its Lua state reached the memory limit of " +
                           std::to_string(shared.limits.memoryBytes >> 20) + " MB (" + text + ")",
                       "");
  }
  const size_t split = text.find("\nstack traceback:");
  if (split == std::string::npos) return ScriptError(text, "");
  return ScriptError(text.substr(0, split), text.substr(split + 1));
}

}  // namespace

LuaHost::LuaHost(LuaLimits limits) : shared_(std::make_unique<Shared>()) {
  shared_->limits = limits;
  L_ = lua_newstate(limitedAlloc, shared_.get());
  if (!L_) throw ScriptError("cannot create a Lua state (LuaJIT refused the allocator)", "");
  openTrusted();
}

LuaHost::~LuaHost() {
  if (L_) lua_close(L_);
}

void LuaHost::openTrusted() {
  luaL_openlibs(L_);
  lua_sethook(L_, budgetHook, LUA_MASKCOUNT, kHookInstructions);
  lua_pushcfunction(L_, tracebackHandler);
  lua_pushvalue(L_, -1);
  tracebackRef_ = luaL_ref(L_, LUA_REGISTRYINDEX);
  // The handler also stays in the state's first stack slot for good: calls from C++ name it there,
  // with no insert and remove around every call (rules callbacks run a million times a session).
  if (lua_gettop(L_) != kTracebackSlot) throw ScriptError("the Lua state did not start with an empty stack", "");
  lua_newtable(L_);
  lua_setfield(L_, LUA_REGISTRYINDEX, "platon.api");
  // The sandbox factory: trusted Lua, run once (sandbox.cpp).
  loadString(sandboxPrelude(), "=platon/sandbox", Trust::Trusted);
  lua_pushcfunction(L_, printToSink);
  call(1, 1);
  lua_setfield(L_, LUA_REGISTRYINDEX, "platon.newSandbox");
}

void LuaHost::pushApi() { lua_getfield(L_, LUA_REGISTRYINDEX, "platon.api"); }

void LuaHost::newSandbox(std::string_view name) {
  lua_getfield(L_, LUA_REGISTRYINDEX, "platon.newSandbox");
  lua_pushlstring(L_, name.data(), name.size());
  pushApi();
  call(2, 1);
}

void LuaHost::loadString(std::string_view code, const std::string& chunkName, Trust trust, int sandbox) {
  const int top = lua_gettop(L_);
  if (sandbox < 0 && sandbox > LUA_REGISTRYINDEX) sandbox = top + 1 + sandbox;
  if (trust == Trust::Sandboxed && !code.empty() && code[0] == '\x1b')
    throw ScriptError(chunkName.substr(chunkName[0] == '@' || chunkName[0] == '=' ? 1 : 0) +
                          ": a compiled (bytecode) chunk: sandboxed scripts load from text only",
                      "");
  const int status = luaL_loadbufferx(L_, code.data(), code.size(), chunkName.c_str(),
                                      trust == Trust::Sandboxed ? "t" : "bt");
  if (status != 0) {
    ScriptError error = errorFromStack(L_, status, *shared_);
    lua_settop(L_, top);
    throw error;
  }
  if (trust == Trust::Trusted) return;
  // No compiled traces for untrusted code: the count hook must see every loop.
  luaJIT_setmode(L_, -1, LUAJIT_MODE_ALLFUNC | LUAJIT_MODE_OFF);
  if (sandbox == 0) {
    newSandbox(chunkName.size() > 1 ? std::string_view(chunkName).substr(1) : std::string_view("sandbox"));
  } else {
    lua_pushvalue(L_, sandbox);
  }
  lua_setfenv(L_, -2);
}

void LuaHost::loadFile(const std::string& path, Trust trust, int sandbox) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) throw ScriptError(path + ": cannot open the script", "");
  std::string code;
  char buffer[65536];
  size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) code.append(buffer, n);
  std::fclose(file);
  if (sandbox < 0 && sandbox > LUA_REGISTRYINDEX) sandbox = lua_gettop(L_) + 1 + sandbox;
  loadString(code, "@" + path, trust, sandbox);
}

void LuaHost::call(int nargs, int nresults) {
  // Outermost calls come from C++ with no Lua running, where the first stack slot is the state's
  // own: the handler waits there. Nested calls (C++ called from Lua calling Lua again) see their C
  // function's frame instead and put the handler below their function.
  if (depth_ != 0) return callNested(nargs, nresults);
  Shared& shared = *shared_;
  shared.inCall = true;
  shared.callStart = 0;
  shared.expired = false;
  shared.memoryRefused = false;
  depth_ = 1;
  const int status = lua_pcall(L_, nargs, nresults, kTracebackSlot);
  depth_ = 0;
  shared.inCall = false;
  if (status != 0 || shared.expired) [[unlikely]] afterFailedCall(status, lua_gettop(L_) - 1);
}

void LuaHost::callNested(int nargs, int nresults) {
  const int handler = lua_gettop(L_) - nargs;  // the function's slot, where the handler goes
  lua_rawgeti(L_, LUA_REGISTRYINDEX, tracebackRef_);
  lua_insert(L_, handler);
  ++depth_;
  const int status = lua_pcall(L_, nargs, nresults, handler);
  --depth_;
  if (status != 0) {
    ScriptError error = errorFromStack(L_, status, *shared_);
    lua_settop(L_, handler - 1);
    throw error;
  }
  lua_remove(L_, handler);
}

// The outermost call's slow path: the budget's hook set back to its normal rate if it was spent,
// and on an error the message popped (leaving the stack as before the function was pushed), the
// garbage of a stopped script collected, and the error thrown.
void LuaHost::afterFailedCall(int status, int below) {
  if (shared_->expired) lua_sethook(L_, budgetHook, LUA_MASKCOUNT, kHookInstructions);
  if (status == 0) return;
  ScriptError error = errorFromStack(L_, status, *shared_);
  lua_settop(L_, below);
  if (shared_->memoryRefused || shared_->expired) lua_gc(L_, LUA_GCCOLLECT, 0);
  throw error;
}

void LuaHost::setPrintSink(std::function<void(std::string_view, std::string_view)> sink) {
  shared_->print = std::move(sink);
}

size_t LuaHost::memoryUsed() const { return shared_->used; }
const LuaLimits& LuaHost::limits() const { return shared_->limits; }
void LuaHost::setLimits(const LuaLimits& limits) { shared_->limits = limits; }
void LuaHost::collectGarbage() { lua_gc(L_, LUA_GCCOLLECT, 0); }

}  // namespace platon::script
