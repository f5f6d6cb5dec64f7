// A LuaHost: the state, its sandboxes, and the calls into them. Its limits are in lua_limits.cpp,
// its errors in lua_errors.cpp; lua_host_shared.h is what the three share.
#include "lua_host.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <luajit.h>

#include "lua_host_shared.h"
#include "lua_pattern.h"
#include "platon/core/visible_text.h"
#include "platon/files/read_file.h"
#include "sandbox.h"

namespace platon::script {

using namespace host;

namespace {

// What print() from sandboxes may write in one frame (all of them together): past it the frame's
// further prints are dropped, once said (503 MB of output in 60 frames filled a disk).
constexpr size_t kPrintBytesPerFrame = size_t{16} * 1024;

int printToSink(lua_State* L) {
  LuaHost::Shared& shared = sharedOf(L);
  size_t nameLength = 0, textLength = 0;
  const char* name = luaL_checklstring(L, 1, &nameLength);
  const char* text = luaL_checklstring(L, 2, &textLength);
  chargeSteps(L, static_cast<int64_t>(textLength / 16 + 1));
  std::string shown;
  if (shared.current != kNoSandbox) {
    if (shared.printed >= kPrintBytesPerFrame) return 0;
    shared.printed += textLength + 1;
    if (shared.printed > kPrintBytesPerFrame)
      shown = "print: more than 16 KB printed this frame: the frame's further prints are dropped";
  }
  if (shown.empty()) shown = core::visibleText(std::string(text, textLength), true);  // no terminal escapes
  if (shared.print) {
    shared.print({name, nameLength}, shown);
  } else {
    std::fprintf(stderr, "[%.*s] %s\n", static_cast<int>(nameLength), name, shown.c_str());
  }
  return 0;
}

// An error a sandbox caught: charged as the work its unwinding was (the prelude's pcall).
int chargeCaughtError(lua_State* L) {
  chargeSteps(L, kErrorSteps);
  return 0;
}

// C work over bytes and values (the prelude's string and table wrappers, before the call): a step
// per 16 bytes a library function makes or reads, a step per value it pushes or moves. Copying 16
// bytes costs about what an interpreted instruction does (docs/scripting.md, Limits).
void chargeBytesAndValues(lua_State* L, double bytes, double values) {
  // What cannot fit in the state's memory is never made: the allocator refuses it (a memory stop).
  if (bytes > static_cast<double>(sharedOf(L).limits.memoryBytes)) bytes = 0;
  const double steps = bytes / 16 + values;
  // Past any budget already (and not NaN): a huge count is charged as the most a budget holds.
  constexpr double kMost = 4.0e18;
  chargeSteps(L, steps > 0 ? static_cast<int64_t>(std::min(steps, kMost)) : 0);
}

int chargeLibraryWork(lua_State* L) {
  chargeBytesAndValues(L, lua_tonumber(L, 1), lua_tonumber(L, 2));
  return 0;
}

// table.concat's work, before it runs: the bytes of each value it will join (a number's at most
// 24) and of the separators, up to the first value it cannot join (where it raises). This walk is
// as long as concat's own, and charged, so a loop of joins is stopped by the budget.
int chargeConcat(lua_State* L) {
  if (lua_type(L, 1) != LUA_TTABLE) return 0;  // concat raises its own argument error
  size_t between = 0;
  if (lua_type(L, 2) == LUA_TSTRING) lua_tolstring(L, 2, &between);
  if (lua_type(L, 2) == LUA_TNUMBER) between = 24;
  // Bounds as concat reads them; any other is concat's own error (or an empty join).
  if (!lua_isnoneornil(L, 3) && !lua_isnumber(L, 3)) return 0;
  if (!lua_isnoneornil(L, 4) && !lua_isnumber(L, 4)) return 0;
  const double first = lua_isnoneornil(L, 3) ? 1 : lua_tonumber(L, 3);
  const double last = lua_isnoneornil(L, 4) ? static_cast<double>(lua_objlen(L, 1)) : lua_tonumber(L, 4);
  if (!(first >= INT32_MIN && last <= INT32_MAX)) return 0;
  double bytes = 0, values = 0;
  for (double k = first; k <= last; ++k) {
    lua_rawgeti(L, 1, static_cast<int>(k));
    const int type = lua_type(L, -1);
    size_t length = 24;
    if (type == LUA_TSTRING) lua_tolstring(L, -1, &length);
    lua_pop(L, 1);
    if (type != LUA_TSTRING && type != LUA_TNUMBER) break;
    bytes += static_cast<double>(length + between);
    ++values;
  }
  chargeBytesAndValues(L, bytes, values);
  return 0;
}

// A sandbox's coroutine resumed inside another (the prelude's resume): on the C callbacks' count.
// The error has no place of its own: the message handler puts the sandbox's line in front.
int enterCoroutine(lua_State* L) {
  LuaHost::Shared& s = sharedOf(L);
  if (s.current == kNoSandbox) return 0;
  if (s.callbackDepth >= kMaxCallbackDepth) {
    lua_pushfstring(L, "coroutines nested more than %d deep (a coroutine that resumes another without end?)",
                    kMaxCallbackDepth);
    return lua_error(L);
  }
  ++s.callbackDepth;
  return 0;
}

int leaveCoroutine(lua_State* L) {
  LuaHost::Shared& s = sharedOf(L);
  if (s.current != kNoSandbox && s.callbackDepth > 0) --s.callbackDepth;
  return 0;
}

// The game clock, in frames: what a sandbox's os.time, os.clock and os.date read.
int gameFrames(lua_State* L) {
  lua_pushnumber(L, static_cast<double>(sharedOf(L).gameFrame));
  return 1;
}

}  // namespace

LuaHost::LuaHost(LuaLimits limits) : shared_(std::make_unique<Shared>()) {
  shared_->limits = limits;
  L_ = lua_newstate(limitedAlloc, shared_.get());
  if (!L_) throw ScriptError("cannot create a Lua state (LuaJIT refused the allocator)", "");
  shared_->L = L_;
  registerHost(shared_.get());
  openTrusted();
}

LuaHost::~LuaHost() {
  unregisterHost(shared_.get());
  shared_->sandboxes.clear();  // their references go before the state
  if (L_) lua_close(L_);
}

void LuaHost::openTrusted() {
  luaL_openlibs(L_);
  hookForTrusted(*shared_);
  lua_pushcfunction(L_, tracebackHandler);
  lua_pushvalue(L_, -1);
  tracebackRef_ = luaL_ref(L_, LUA_REGISTRYINDEX);
  // The handler also stays in the state's first stack slot for good: calls from C++ name it there,
  // with no insert and remove around every call (rules callbacks run a million times a session).
  if (lua_gettop(L_) != kTracebackSlot) throw ScriptError("the Lua state did not start with an empty stack", "");
  lua_newtable(L_);
  lua_setfield(L_, LUA_REGISTRYINDEX, "platon.api");
  // The sandbox factory: trusted Lua, run once (sandbox.cpp). It gets the C functions it hands on.
  // Every function it defines runs interpreted: they run inside sandboxed calls (pairs, next,
  // tostring, the read-only views...), where each instruction is a step, and a loop the JIT compiled
  // would run uncounted (and whether one compiles differs from one process to the next).
  loadString(sandboxPrelude(), "=platon/sandbox", Trust::Trusted);
  luaJIT_setmode(L_, -1, LUAJIT_MODE_ALLFUNC | LUAJIT_MODE_OFF);
  static const luaL_Reg kPreludeFunctions[] = {{"print", printToSink},
                                               {"frames", gameFrames},
                                               {"orderedKeys", orderedKeys},
                                               {"countedComparator", countedComparator},
                                               {"chargeError", chargeCaughtError},
                                               {"chargeWork", chargeLibraryWork},
                                               {"chargeConcat", chargeConcat},
                                               {"enterCoroutine", enterCoroutine},
                                               {"leaveCoroutine", leaveCoroutine},
                                               {nullptr, nullptr}};
  lua_newtable(L_);
  for (const luaL_Reg* f = kPreludeFunctions; f->name; ++f) {
    lua_pushcfunction(L_, f->func);
    lua_setfield(L_, -2, f->name);
  }
  setPatternFunctions(L_, -1);
  call(1, 3);
  lua_setfield(L_, LUA_REGISTRYINDEX, "platon.tostring");
  lua_setfield(L_, LUA_REGISTRYINDEX, "platon.readonly");
  lua_setfield(L_, LUA_REGISTRYINDEX, "platon.newSandbox");
}

void LuaHost::pushApi() { lua_getfield(L_, LUA_REGISTRYINDEX, "platon.api"); }

void LuaHost::pushSandboxApi() {
  lua_newtable(L_);
  pushApi();
  for (lua_pushnil(L_); lua_next(L_, -2);) {  // rawset below pops the value and a copy of the key
    lua_pushvalue(L_, -2);
    lua_insert(L_, -2);
    lua_rawset(L_, -5);
  }
  lua_pop(L_, 1);
  lua_getfield(L_, LUA_REGISTRYINDEX, "platon.sandboxOverrides");
  if (lua_istable(L_, -1))
    for (lua_pushnil(L_); lua_next(L_, -2);) {  // rawset below pops the value and a copy of the key
      lua_pushvalue(L_, -2);
      lua_insert(L_, -2);
      lua_rawset(L_, -5);
    }
  lua_pop(L_, 1);
}

void LuaHost::setSandboxOverride(const char* name) {
  lua_getfield(L_, LUA_REGISTRYINDEX, "platon.sandboxOverrides");
  if (!lua_istable(L_, -1)) {
    lua_pop(L_, 1);
    lua_newtable(L_);
    lua_pushvalue(L_, -1);
    lua_setfield(L_, LUA_REGISTRYINDEX, "platon.sandboxOverrides");
  }
  lua_insert(L_, -2);
  lua_setfield(L_, -2, name);
  lua_pop(L_, 1);
}

void LuaHost::pushReadOnly(int index, std::string_view name) {
  if (index < 0 && index > LUA_REGISTRYINDEX) index = lua_gettop(L_) + 1 + index;
  lua_getfield(L_, LUA_REGISTRYINDEX, "platon.readonly");
  lua_pushvalue(L_, index);
  lua_pushlstring(L_, name.data(), name.size());
  call(2, 1);
}

namespace {
std::string nameOfChunk(const std::string& chunkName) {
  return chunkName.size() > 1 && (chunkName[0] == '@' || chunkName[0] == '=') ? chunkName.substr(1) : chunkName;
}
}  // namespace

int LuaHost::newSandbox(const std::string& chunkName) {
  const std::string name = nameOfChunk(chunkName);
  lua_getfield(L_, LUA_REGISTRYINDEX, "platon.newSandbox");
  lua_pushlstring(L_, name.data(), name.size());
  pushSandboxApi();
  call(2, 1);
  return addSandbox(chunkName, false);
}

void LuaHost::refreshSandboxApi() {
  lua::StackGuard guard(L_);
  for (const Sandbox& box : shared_->sandboxes) {
    if (box.disabled || box.borrowsEnv || !box.env.isSet()) continue;
    box.env.push();
    lua_getfield(L_, LUA_REGISTRYINDEX, "platon.readonly");
    pushSandboxApi();
    lua_pushliteral(L_, "platon");
    call(2, 1);
    lua_setfield(L_, -2, "platon");
    lua_pop(L_, 1);
  }
}

int LuaHost::addSandbox(const std::string& chunkName, bool borrowsEnv) {
  Sandbox box;
  box.name = nameOfChunk(chunkName);
  box.source = chunkName;
  box.env = lua::Ref(L_, -1);
  box.borrowsEnv = borrowsEnv;
  if (!shared_->released.empty()) {  // a released place: the list of sandboxes does not grow
    const int id = shared_->released.back();
    shared_->released.pop_back();
    shared_->sandboxes[static_cast<size_t>(id)] = std::move(box);
    return id;
  }
  shared_->sandboxes.push_back(std::move(box));
  shared_->heldBytes.resize(shared_->sandboxes.size() + 1, 0);
  return static_cast<int>(shared_->sandboxes.size() - 1);
}

void LuaHost::releaseSandbox(int sandbox) {
  if (sandbox < 0 || static_cast<size_t>(sandbox) >= shared_->sandboxes.size()) return;
  Sandbox& gone = shared_->sandboxes[static_cast<size_t>(sandbox)];
  if (!gone.env.isSet()) return;  // released already
  // Its globals are dropped, not wiped: a function the line left in another table still reads them.
  gone.disabled = true;
  gone.env.reset();
  shared_->released.push_back(sandbox);
}

int LuaHost::loadString(std::string_view code, const std::string& chunkName, Trust trust) {
  compile(code, chunkName, trust);
  if (trust == Trust::Trusted) return kNoSandbox;
  const int id = newSandbox(chunkName);
  lua_setfenv(L_, -2);
  return id;
}

void LuaHost::compile(std::string_view code, const std::string& chunkName, Trust trust) {
  const int top = lua_gettop(L_);
  if (trust == Trust::Sandboxed && !code.empty() && code[0] == '\x1b')
    throw ScriptError(nameOfChunk(chunkName) + ": a compiled (bytecode) chunk: sandboxed scripts load from text only",
                      "");
  const int status =
      luaL_loadbufferx(L_, code.data(), code.size(), chunkName.c_str(), trust == Trust::Sandboxed ? "t" : "bt");
  if (status != 0) {
    ScriptError error = errorFromStack(L_, status, *shared_);
    lua_settop(L_, top);
    throw error;
  }
  // No compiled traces for untrusted code: the hooks must see every loop.
  if (trust == Trust::Sandboxed) luaJIT_setmode(L_, -1, LUAJIT_MODE_ALLFUNC | LUAJIT_MODE_OFF);
}

int LuaHost::loadStringInGlobalsOf(std::string_view code, const std::string& chunkName, int envOf) {
  if (envOf < 0 || static_cast<size_t>(envOf) >= shared_->sandboxes.size())
    throw ScriptError("no sandbox " + std::to_string(envOf), "");
  compile(code, chunkName, Trust::Sandboxed);  // a sandbox of its own, with no globals of its own to make
  shared_->sandboxes[static_cast<size_t>(envOf)].env.push();
  const int id = addSandbox(chunkName, true);
  lua_setfenv(L_, -2);
  return id;
}

int LuaHost::loadFile(const std::string& path, Trust trust, const std::string& shownAs) {
  std::string code;
  try {
    code = files::readBoundedFile(path, kMaxScriptBytes);
  } catch (const files::FileError& e) {
    throw ScriptError(path + ": the script: " + e.reason(), "");
  }
  return loadString(code, "@" + (shownAs.empty() ? path : shownAs), trust);
}

void LuaHost::call(int nargs, int nresults) {
  // Outermost calls come from C++ with no Lua running, where the first stack slot is the state's
  // own: the handler waits there. Nested calls (C++ called from Lua calling Lua again) see their C
  // function's frame instead and put the handler below their function.
  if (depth_ != 0) return callNested(nargs, nresults);
  Shared& shared = *shared_;
  shared.inCall = true;
  shared.callStart = 0;
  shared.trustedExpired = false;
  depth_ = 1;
  const int status = lua_pcall(L_, nargs, nresults, kTracebackSlot);
  depth_ = 0;
  shared.inCall = false;
  if (status != 0 || shared.trustedExpired) [[unlikely]]
    afterFailedCall(status, lua_gettop(L_) - 1);
}

void LuaHost::callNested(int nargs, int nresults) {
  int below = 0;
  const int status = protectedCall(nargs, nresults, below);
  if (status != 0) {
    ScriptError error = errorFromStack(L_, status, *shared_);
    lua_settop(L_, below);
    throw error;
  }
}

// A nested call with the handler below the function; on success the handler is removed and the
// results stay. `below` is the stack top below the function.
int LuaHost::protectedCall(int nargs, int nresults, int& below) {
  const int handler = lua_gettop(L_) - nargs;  // the function's slot, where the handler goes
  below = handler - 1;
  lua_rawgeti(L_, LUA_REGISTRYINDEX, tracebackRef_);
  lua_insert(L_, handler);
  ++depth_;
  const int status = lua_pcall(L_, nargs, nresults, handler);
  --depth_;
  if (status == 0) lua_remove(L_, handler);
  return status;
}

// The outermost call's slow path: the budget's hook set back to its normal rate if it was spent,
// and on an error the message popped (leaving the stack as before the function was pushed), the
// garbage of a stopped script collected, and the error thrown.
void LuaHost::afterFailedCall(int status, int below) {
  if (shared_->trustedExpired) {
    hookForTrusted(*shared_);
    shared_->trustedExpired = false;
  }
  if (status == 0) return;
  ScriptError error = errorFromStack(L_, status, *shared_);
  lua_settop(L_, below);
  if (status == LUA_ERRMEM) lua_gc(L_, LUA_GCCOLLECT, 0);
  throw error;
}

namespace {

// The bookkeeping of an outermost sandboxed call as it starts: its clock, the deadline's timer, the
// sandbox's hook rate, and the tick it pays up front.
inline void beginOutermostSandboxedCall(LuaHost::Shared& s, Sandbox& box) {
  s.enteredAt = coarseNanoseconds();
  if (!s.timerArmed) armTimer(s, s.frameDeadline() - s.frameSpent);
  // The count starts again here, and the call pays one tick for the instructions of its last
  // tick, which no look counts: so its charge depends on nothing that ran before it.
  hookForSandbox(s);
  s.callbackDepth = 0;
  s.stopMessage.clear();  // a stopped trusted call's, which a memory stop would take for its own
  s.frameSteps += kTickSteps;
  box.spent += kTickSteps;
}

}  // namespace

bool LuaHost::callSandboxed(int sandbox, int nargs, int nresults) {
  Shared& s = *shared_;
  if (sandbox < 0 || sandbox >= static_cast<int>(s.sandboxes.size())) {
    lua_pop(L_, nargs + 1);
    throw ScriptError("callSandboxed: no sandbox " + std::to_string(sandbox), "");
  }
  Sandbox& box = s.sandboxes[static_cast<size_t>(sandbox)];
  if (box.disabled) {
    lua_pop(L_, nargs + 1);
    return false;
  }
  const int outer = s.current;
  if (outer == kNoSandbox) {
    const bool late = s.frameSpent >= s.frameDeadline();
    if (late || s.frameSteps >= s.limits.frameSteps) {  // the frame's budget is spent: skipped
      lua_pop(L_, nargs + 1);
      noteSkippedCall(sandbox, late);
      return false;
    }
    beginOutermostSandboxedCall(s, box);
  }
  s.current = sandbox;
  int below = 0;
  int status = 0;
  if (depth_ == 0) {  // from C++ with no Lua running: the handler waits in the first slot
    below = lua_gettop(L_) - nargs - 1;
    depth_ = 1;
    status = lua_pcall(L_, nargs, nresults, kTracebackSlot);
    depth_ = 0;
  } else {
    status = protectedCall(nargs, nresults, below);
  }
  s.current = outer;
  if (outer != kNoSandbox) {
    if (status != 0) {
      ScriptError error = errorFromStack(L_, status, s);
      lua_settop(L_, below);
      throw error;
    }
    return true;
  }
  // The outermost sandboxed call returned: its time goes to the frame.
  s.frameSpent += coarseNanoseconds() - s.enteredAt;
  const bool stopped = s.expired || s.memoryStop != kNoSandbox;
  // Back to the trusted rate at once: a look every kTickSteps in trusted code would abort the JIT's
  // recording of every trace it records (measured: a frame with a level tick took twice as long).
  hookForTrusted(s);
  if (status == 0 && !stopped) [[likely]]
    return true;
  failSandboxedCall(sandbox, status, below, stopped);
}

// A call skipped because the frame's budget is spent: said once a frame (and not after a stop,
// whose message already says the rest is skipped).
void LuaHost::noteSkippedCall(int sandbox, bool late) {
  Shared& s = *shared_;
  if (!s.skipNoted && !s.stopNoted)
    keepError(ScriptError(s.sandboxes[static_cast<size_t>(sandbox)].name + ": skipped: " +
                              (late ? "the frame's deadline of " + milliseconds(s.frameDeadline()) + " has passed"
                                    : "the frame's script budget of " + stepsText(s.limits.frameSteps) + " is spent") +
                              " (the level's scripts and mods share it; their other calls this frame are "
                              "skipped)",
                          ""));
  s.skipNoted = true;
}

// An outermost sandboxed call that failed or was stopped: the error (or the stop's message) with
// the sandbox named, the stack back to `below`, the sandbox that ran over disabled, and the error
// thrown.
void LuaHost::failSandboxedCall(int sandbox, int status, int below, bool stopped) {
  Shared& s = *shared_;
  std::string traceback;
  std::string message = failedCallMessage(sandbox, status, below, stopped, traceback);
  // A refusal that unwound the sandbox before it ran another instruction: no place is known, but
  // for the one the hook found before a later allocation failed (a pcall's unwinding grew the stack).
  if (s.memoryStop != kNoSandbox && (status == LUA_ERRMEM || message.empty()))
    message = !s.stopMessage.empty() ? s.stopMessage
                                     : s.sandboxes[static_cast<size_t>(s.memoryStop)].name + ": " + memoryStopText(s);
  if (s.memoryStop != kNoSandbox) blameTheBiggestHolder(s, message);
  disableAfterStop(sandbox, message);
  throw ScriptError(message, traceback);
}

// What a failed outermost call says: its error, named after its sandbox, or the stop's message;
// the stack is set back to `below`. An error's unwinding is charged as work (a rules callback
// failing on every contact).
std::string LuaHost::failedCallMessage(int sandbox, int status, int below, bool stopped, std::string& traceback) {
  Shared& s = *shared_;
  Sandbox& box = s.sandboxes[static_cast<size_t>(sandbox)];
  if (status != 0 && !stopped) {
    s.frameSteps += kErrorSteps;
    box.spent += kErrorSteps;
  }
  if (status == 0) {
    lua_settop(L_, below);  // its results: a stopped sandbox's call gives none
    return s.stopMessage;
  }
  ScriptError error = errorFromStack(L_, status, s);
  std::string message = error.what();
  traceback = error.traceback();
  lua_settop(L_, below);
  if (message.find("stack overflow") != std::string::npos || status == LUA_ERRERR) {
    // LuaJIT may not run the handler after an overflow in a metamethod (it says "stack
    // overflow", with no place and no traceback), and leaves the stack grown: a collection
    // shrinks it back.
    if (!located(message.c_str()))
      message = box.name + ": " + message + " (a function or metamethod that calls itself without end?)";
    lua_gc(L_, LUA_GCCOLLECT, 0);
  } else if (!located(message.c_str()) && message.rfind(box.name + ": ", 0) != 0) {
    message = box.name + ": " + message;
  }
  return message;
}

// A stop disables the sandbox that ran over: the one whose allocation was refused, or the one
// that spent the most of the frame's steps; after a budget stop the frame's other calls are
// skipped. The stop's state is cleared for the next call.
void LuaHost::disableAfterStop(int sandbox, std::string& message) {
  Shared& s = *shared_;
  int off = kNoSandbox;
  if (s.memoryStop != kNoSandbox)
    off = s.memoryStop;
  else if (s.expired)
    off = s.hog != kNoSandbox ? s.hog : sandbox;
  if (s.expired && s.memoryStop == kNoSandbox) {
    s.frameSteps = std::max(s.frameSteps, s.limits.frameSteps);  // the rest of the frame's calls are skipped
    s.stopNoted = true;
  }
  s.expired = false;
  s.memoryStop = kNoSandbox;
  s.hog = kNoSandbox;
  s.stopMessage.clear();
  // A file's sandbox stays off until it is saved again; a line of code not from a file (the
  // console's) is simply gone, and saving fixes nothing.
  if (off != kNoSandbox && s.sandboxes[static_cast<size_t>(off)].source.rfind('@', 0) != 0) {
    disable(off);
  } else if (off != kNoSandbox) {
    disable(off);
    message += "; " + s.sandboxes[static_cast<size_t>(off)].name + " disabled: fix it and save to reload";
    if (s.stopNoted && off == sandbox) message += " (the frame's other sandboxed calls are skipped)";
  }
}

// A memory stop is the fault of what holds the memory, not of the allocation that crossed the
// line: once the stopped call's garbage is collected, the sandbox that holds the most is the one
// stopped (and disabled), named first, with the place where the line was crossed.
void LuaHost::blameTheBiggestHolder(Shared& s, std::string& message) {
  lua_gc(L_, LUA_GCCOLLECT, 0);
  const int holder = biggestHolder(s);
  if (holder == kNoSandbox || holder == s.memoryStop) return;
  const auto held = [&](int box) { return s.heldBytes[static_cast<size_t>(box) + 1]; };
  if (held(holder) <= held(s.memoryStop)) return;
  const Sandbox& stopped = s.sandboxes[static_cast<size_t>(s.memoryStop)];
  std::string at = located(message.c_str()) ? message.substr(0, message.find(": ")) : stopped.name;
  message = s.sandboxes[static_cast<size_t>(holder)].name + ": " + memoryStopText(s) + "; it holds " +
            std::to_string((held(holder) + (1 << 19)) >> 20) + " MB, the most of any script (" + at +
            " was running, holding " + std::to_string((std::max<int64_t>(held(s.memoryStop), 0) + (1 << 19)) >> 20) +
            " MB)";
  s.memoryStop = holder;
}

void LuaHost::disable(int sandbox) {
  Sandbox& gone = shared_->sandboxes[static_cast<size_t>(sandbox)];
  gone.disabled = true;
  // Its globals go, so what it holds can be collected once the engine drops its functions (not
  // when they are another sandbox's: the console's line in the level's globals).
  if (gone.borrowsEnv) return;
  gone.env.push();
  if (lua_istable(L_, -1)) {
    lua_pushnil(L_);
    while (lua_next(L_, -2)) {
      lua_pop(L_, 1);
      lua_pushvalue(L_, -1);
      lua_pushnil(L_);
      lua_rawset(L_, -4);
    }
  }
  lua_pop(L_, 1);
  // What it held is garbage now (its functions too, once the engine drops them: again then).
  lua_gc(L_, LUA_GCCOLLECT, 0);
  shared_->collectSoon = true;
}

std::optional<ScriptError> LuaHost::chargeWork(int sandbox, int64_t steps, const std::string& what) {
  Shared& s = *shared_;
  if (sandbox < 0 || sandbox >= static_cast<int>(s.sandboxes.size())) return std::nullopt;
  Sandbox& box = s.sandboxes[static_cast<size_t>(sandbox)];
  if (box.disabled || steps <= 0) return std::nullopt;
  box.spent += steps;
  s.frameSteps += steps;
  if (s.frameSteps <= s.limits.frameSteps) return std::nullopt;
  disable(sandbox);
  s.frameSteps = std::max(s.frameSteps, s.limits.frameSteps);
  return ScriptError(box.name + ": stopped: " + what + " cost " + stepsText(steps) +
                         " this frame, past the frame's script budget of " + stepsText(s.limits.frameSteps) +
                         " (what a script makes the engine do is charged to it); what it made is removed; " + box.name +
                         " disabled: fix it and save to reload",
                     "");
}

int LuaHost::luaCallSandboxed(lua_State* L) {
  auto* host = static_cast<LuaHost*>(lua_touserdata(L, lua_upvalueindex(1)));
  const int sandbox = static_cast<int>(luaL_checkinteger(L, 1));
  luaL_checktype(L, 2, LUA_TFUNCTION);
  if (sandbox < 0 || sandbox >= static_cast<int>(host->shared_->sandboxes.size()))
    luaL_argerror(L, 1, "no such sandbox");
  lua_remove(L, 1);
  bool ran = false;
  try {
    ran = host->callSandboxed(sandbox, lua_gettop(L) - 1, LUA_MULTRET);
  } catch (ScriptError& e) {
    host->keepError(std::move(e));
  }
  if (!ran) {
    lua_settop(L, 0);
    lua_pushboolean(L, 0);
    return 1;
  }
  lua_pushboolean(L, 1);
  lua_insert(L, 1);
  return lua_gettop(L);
}

void LuaHost::pushCallFunction() {
  lua_pushlightuserdata(L_, this);
  lua_pushcclosure(L_, luaCallSandboxed, 1);
}

void LuaHost::beginFrame() {
  Shared& s = *shared_;
  s.frameSteps = 0;
  s.frameSpent = 0;
  s.printed = 0;
  s.skipNoted = false;
  s.stopNoted = false;
  for (Sandbox& box : s.sandboxes) box.spent = 0;
}

LuaHost::Budget LuaHost::budget() const {
  const Shared& s = *shared_;
  Budget b{s.frameSteps, s.frameSpent, s.printed, s.skipNoted, s.stopNoted, {}};
  for (const Sandbox& box : s.sandboxes) b.spent.push_back(box.spent);
  return b;
}

void LuaHost::restoreBudget(const Budget& b) {
  Shared& s = *shared_;
  s.frameSteps = b.frameSteps, s.frameSpent = b.frameSpent, s.printed = b.printed;
  s.skipNoted = b.skipNoted, s.stopNoted = b.stopNoted;
  for (size_t i = 0; i < s.sandboxes.size(); ++i) s.sandboxes[i].spent = i < b.spent.size() ? b.spent[i] : 0;
}

void LuaHost::setGameFrame(uint64_t frame) { shared_->gameFrame = frame; }

bool LuaHost::disabled(int sandbox) const {
  return sandbox >= 0 && sandbox < static_cast<int>(shared_->sandboxes.size()) &&
         shared_->sandboxes[static_cast<size_t>(sandbox)].disabled;
}

const std::string& LuaHost::sandboxName(int sandbox) const {
  return shared_->sandboxes.at(static_cast<size_t>(sandbox)).name;
}

int LuaHost::runningSandbox() const { return shared_->current; }

void LuaHost::keepError(ScriptError error) {
  for (const ScriptError& kept : errors_)
    if (std::strcmp(kept.what(), error.what()) == 0) return;  // said already
  if (errors_.size() < kMaxKeptErrors) errors_.push_back(std::move(error));
}

std::vector<ScriptError> LuaHost::takeErrors() {
  std::vector<ScriptError> out;
  out.swap(errors_);
  return out;
}

void LuaHost::setPrintSink(std::function<void(std::string_view, std::string_view)> sink) {
  shared_->print = std::move(sink);
}

size_t LuaHost::memoryUsed() const { return shared_->used; }
int64_t LuaHost::frameSteps() const { return shared_->frameSteps; }

const LuaLimits& LuaHost::limits() const { return shared_->limits; }
void LuaHost::setLimits(const LuaLimits& limits) { shared_->limits = limits; }
void LuaHost::collectGarbage() {
  shared_->collectSoon = false;
  lua_gc(L_, LUA_GCCOLLECT, 0);
}
void LuaHost::collectIfNeeded() {
  if (shared_->collectSoon) collectGarbage();
}

}  // namespace platon::script
