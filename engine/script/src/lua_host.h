// One LuaJIT state with the limits the engine puts on it: a memory ceiling (a counting
// allocator), a time budget per call from C++ (a count hook that reads the clock), a traceback on
// every error, and two kinds of code:
//
//  - trusted: the engine's own scripts (scripts/) and scenarios. All of LuaJIT's libraries,
//    the JIT on. A trusted endless loop that the JIT compiled cannot be stopped from inside the
//    process (LuaJIT runs no hooks in compiled traces); the scenario runner's worker processes
//    are killed from outside after their wall-clock limit instead.
//  - sandboxed: level scripts and mods. Each runs in an environment of its own with the safe
//    part of the standard library (see sandbox.cpp), loaded from text only, and with the JIT
//    off for every function the chunk defines, so the count hook fires inside every loop and the
//    time budget always holds.
//
// Errors come back as ScriptError with "file:line: message" and the Lua traceback. Calls nest
// (a callback from C++ inside a call from Lua); the budget runs from the outermost one.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "lua_stack.h"
#include "platon/script/script_error.h"

namespace platon::script {

struct LuaLimits {
  size_t memoryBytes = size_t{128} << 20;  // the whole state: every script and its data
  int64_t callNanoseconds = 250'000'000;   // one call from C++ into Lua, nested calls included
};

enum class Trust { Trusted, Sandboxed };

class LuaHost {
 public:
  explicit LuaHost(LuaLimits limits = {});
  ~LuaHost();
  LuaHost(const LuaHost&) = delete;
  LuaHost& operator=(const LuaHost&) = delete;

  lua_State* state() const { return L_; }

  // Compiles a file or a string and pushes the chunk as a function; throws ScriptError with the
  // syntax error's file:line. Sandboxed: text only (bytecode is refused), the chunk's environment
  // is the sandbox table at stack index `sandbox` (0: a fresh one from newSandbox()), and the JIT
  // is off for the chunk and every function inside it.
  void loadFile(const std::string& path, Trust trust, int sandbox = 0);
  void loadString(std::string_view code, const std::string& chunkName, Trust trust, int sandbox = 0);

  // Pushes a new sandbox environment: the safe globals, a read-only `platon` table (the API
  // registered with exposeToSandboxes), and `print` that goes to the print sink tagged `name`.
  void newSandbox(std::string_view name);

  // The table of functions sandboxes see as `platon` (read-only for them). Pushes it.
  void pushApi();

  // Calls the function at -(nargs + 1) with the nargs values above it; leaves nresults results.
  // Any Lua error, time budget or memory limit throws ScriptError and leaves the stack as it was
  // before the function was pushed.
  void call(int nargs, int nresults);

  // Where print() goes: the script's name and its text. Default: stderr.
  void setPrintSink(std::function<void(std::string_view name, std::string_view text)> sink);

  size_t memoryUsed() const;
  const LuaLimits& limits() const;
  void setLimits(const LuaLimits& limits);

  // Full garbage collection (after a script was dropped, say).
  void collectGarbage();

  struct Shared;  // what the allocator and the hook reach through the state

 private:
  std::unique_ptr<Shared> shared_;
  lua_State* L_ = nullptr;
  int depth_ = 0;
  int tracebackRef_ = LUA_NOREF;
  static constexpr int kTracebackSlot = 1;
  void openTrusted();
  void callNested(int nargs, int nresults);
  [[gnu::cold]] void afterFailedCall(int status, int below);
};

}  // namespace platon::script
