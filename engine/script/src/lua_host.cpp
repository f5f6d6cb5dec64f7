#include "lua_host.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <luajit.h>
#include <mutex>
#include <signal.h>
#include <time.h>
#include <unistd.h>

#include "lua_pattern.h"
#include "platon/core/visible_text.h"
#include "platon/files/read_file.h"
#include "sandbox.h"

namespace platon::script {

// One sandbox's state (not in an anonymous namespace: LuaHost::Shared, which has external linkage,
// holds a vector of them).
struct Sandbox {
  std::string name;    // the chunk's file, as messages name it
  std::string source;  // its chunk name ("@file"): the frames of its functions carry it
  lua::Ref env;
  bool disabled = false;
  int64_t spent = 0;  // steps of this frame's budget
};

// The allocator's, the hook's and the timer's view of the host: reached through lua_getallocf's
// user data (and the timer's signal value), so none of them needs a global.
struct LuaHost::Shared {
  LuaLimits limits;
  lua_State* L = nullptr;
  size_t used = 0;
  int current = kNoSandbox;  // the sandbox whose code runs now (through callSandboxed)
  int handler = 0;           // > 0 while the message handler or a stop's message is built: the reserve is open
  // Memory: the sandbox whose allocation was refused during the running sandboxed call.
  int memoryStop = kNoSandbox;
  // Work: the steps charged to the frame's sandboxed calls.
  int64_t frameSteps = 0;
  // Time, the backstop. frameSpent counts the frame's sandboxed calls (outermost ones) that have
  // returned; enteredAt is when the running one began.
  int64_t frameSpent = 0;
  int64_t enteredAt = 0;
  bool expired = false;      // a limit stopped the call: the hook raises on every instruction until it returns
  bool skipNoted = false;    // a skipped call was reported this frame
  bool stopNoted = false;    // a stop was reported this frame (it says the rest is skipped)
  int hog = kNoSandbox;      // the sandbox disabled for the stop: the one that spent the most of the frame
  std::string stopMessage;   // what the hook raises once a limit stopped the call
  bool collectSoon = false;  // a disabled sandbox left garbage
  int callbackDepth = 0;     // C callbacks nested now (CallbackDepth)
  size_t printed = 0;        // bytes sandboxes printed this frame
  volatile sig_atomic_t timerArmed = 0;
  volatile sig_atomic_t timerFired = 0;  // the deadline may have passed: the next charge reads the clock
  bool hookFast = false;                 // the hook runs on every instruction (a stop is under way)
  // The fallback for trusted code: the count hook times each outermost call from its first look.
  bool inCall = false;
  int64_t callStart = 0;
  bool trustedExpired = false;
  // The deadline's timer, made on (and aimed at) the thread that runs the calls.
  bool timerMade = false;
  timer_t timer{};
  pid_t timerThread = 0;
  uint64_t gameFrame = 0;
  std::vector<Sandbox> sandboxes;
  std::function<void(std::string_view, std::string_view)> print;

  size_t sandboxLimit() const { return limits.memoryBytes - limits.memoryBytes / kTrustedReserveDivisor; }
};

namespace {

constexpr int kTrustedHookInstructions = 100'000;

int64_t nowNanoseconds() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return int64_t{t.tv_sec} * 1'000'000'000 + t.tv_nsec;
}

// The same clock read at its last tick (a few ms of resolution, a third of the cost): what the
// per-call bookkeeping of sandboxed calls reads. Over many short calls its errors cancel out.
int64_t coarseNanoseconds() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC_COARSE, &t);
  return int64_t{t.tv_sec} * 1'000'000'000 + t.tv_nsec;
}

LuaHost::Shared& sharedOf(lua_State* L) {
  void* ud = nullptr;
  lua_getallocf(L, &ud);
  return *static_cast<LuaHost::Shared*>(ud);
}

void budgetHook(lua_State* L, lua_Debug*);

void hookEveryInstruction(LuaHost::Shared& s) {
  s.hookFast = true;
  lua_sethook(s.L, budgetHook, LUA_MASKCOUNT, 1);
}

// Inside sandboxed calls: a look every kTickSteps instructions. Setting it starts the counter
// again, so a sandboxed call's first look comes after exactly kTickSteps of its instructions,
// whatever ran before it.
void hookForSandbox(LuaHost::Shared& s) {
  s.hookFast = false;
  lua_sethook(s.L, budgetHook, LUA_MASKCOUNT, kTickSteps);
}

// Outside them, only the trusted fallback's rare look: a hook call aborts the JIT's trace
// recording, so a frequent one would keep the engine's own scripts from compiling.
void hookForTrusted(LuaHost::Shared& s) {
  s.hookFast = false;
  lua_sethook(s.L, budgetHook, LUA_MASKCOUNT, kTrustedHookInstructions);
}

// --- the deadline's timer ---

int timerSignal() { return SIGRTMIN + 2; }

// The hosts alive in this process: the signal handler only touches one it finds here (a signal
// may be queued when its host is destroyed).
constexpr int kMaxHosts = 256;
std::atomic<LuaHost::Shared*> gHosts[kMaxHosts];

// Only raises a flag: the hook's next look (at most kTickSteps instructions later) or the next
// charge of C work reads the clock. The hook's count is never touched from here, so where the hook
// looks, and so what a sandbox is charged, does not depend on when a signal came.
void onTimer(int, siginfo_t* info, void*) {
  auto* target = static_cast<LuaHost::Shared*>(info->si_value.sival_ptr);
  if (!target) return;
  for (auto& slot : gHosts) {
    if (slot.load(std::memory_order_acquire) != target) continue;
    target->timerArmed = 0;
    target->timerFired = 1;
    return;
  }
}

void registerHost(LuaHost::Shared* shared) {
  static std::once_flag installed;
  std::call_once(installed, [] {
    struct sigaction action {};
    action.sa_sigaction = onTimer;
    action.sa_flags = SA_SIGINFO | SA_RESTART;
    sigemptyset(&action.sa_mask);
    sigaction(timerSignal(), &action, nullptr);
  });
  for (auto& slot : gHosts) {
    LuaHost::Shared* empty = nullptr;
    if (slot.compare_exchange_strong(empty, shared)) return;
  }
  // More than kMaxHosts states at once: this one goes without the timer (the count hook remains).
}

void unregisterHost(LuaHost::Shared* shared) {
  for (auto& slot : gHosts) {
    LuaHost::Shared* mine = shared;
    if (slot.compare_exchange_strong(mine, nullptr)) break;
  }
  if (shared->timerMade) timer_delete(shared->timer);
}

// Arms the timer to fire in `nanoseconds` on this thread. Without a timer (none could be made),
// the count hook still stops the call, later.
void armTimer(LuaHost::Shared& s, int64_t nanoseconds) {
  const pid_t thread = gettid();
  if (!s.timerMade || s.timerThread != thread) {  // another thread, or a forked child
    if (s.timerMade) timer_delete(s.timer);
    s.timerMade = false;
    sigevent event{};
    event.sigev_notify = SIGEV_THREAD_ID;
    event.sigev_signo = timerSignal();
    event.sigev_value.sival_ptr = &s;
    event._sigev_un._tid = thread;  // sigev_notify_thread_id (glibc 2.36 has no name for it)
    if (timer_create(CLOCK_MONOTONIC, &event, &s.timer) != 0) return;
    s.timerMade = true;
    s.timerThread = thread;
  }
  if (nanoseconds < 100'000) nanoseconds = 100'000;
  itimerspec when{};
  when.it_value.tv_sec = static_cast<time_t>(nanoseconds / 1'000'000'000);
  when.it_value.tv_nsec = static_cast<long>(nanoseconds % 1'000'000'000);
  s.timerArmed = 1;
  if (timer_settime(s.timer, 0, &when, nullptr) != 0) s.timerArmed = 0;
}

// --- memory ---

void* limitedAlloc(void* ud, void* ptr, size_t oldSize, size_t newSize) {
  auto* shared = static_cast<LuaHost::Shared*>(ud);
  const size_t old = ptr ? oldSize : 0;
  if (newSize == 0) {
    std::free(ptr);
    shared->used -= old;
    return nullptr;
  }
  if (newSize > old) {
    const size_t after = shared->used - old + newSize;
    if (shared->current != kNoSandbox && shared->handler == 0 && after > shared->sandboxLimit()) {
      // A sandbox past its share. The allocator cannot tell where the script is (it is called from
      // inside the VM); the hook can, at the sandbox's next instruction, and stops it there with
      // its file:line. So the first allocation past the share is granted from the engine's
      // reserve (when it fits), and the sandbox's later ones are refused.
      const bool first = shared->memoryStop == kNoSandbox;
      if (first) {
        shared->memoryStop = shared->current;
        hookEveryInstruction(*shared);
      }
      if (!first || after > shared->limits.memoryBytes) return nullptr;
    } else if (after > shared->limits.memoryBytes) {
      return nullptr;  // LuaJIT raises "not enough memory"
    }
  }
  void* grown = std::realloc(ptr, newSize);
  if (!grown) return nullptr;
  shared->used = shared->used - old + newSize;
  return grown;
}

// --- messages ---

// The message handler's and the stops' reserve: memory refused to sandboxes is open to them.
struct OpenReserve {
  LuaHost::Shared& s;
  explicit OpenReserve(LuaHost::Shared& shared) : s(shared) { ++s.handler; }
  ~OpenReserve() { --s.handler; }
};

// "file:line: " of the innermost frame of a script file: of the running sandbox's own file when
// it is on the stack, else of any script file; "" when there is none.
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

std::string milliseconds(int64_t nanoseconds) { return std::to_string((nanoseconds + 500'000) / 1'000'000) + " ms"; }

std::string memoryStopText(const LuaHost::Shared& s) {
  return "script stopped: the sandboxes reached their memory limit of " + std::to_string(s.sandboxLimit() >> 20) +
         " MB (of the Lua state's " + std::to_string(s.limits.memoryBytes >> 20) +
         " MB; the rest is kept for the engine)";
}

// Raises the stop the hook decided on (the same message at every instruction until the sandboxed
// call has returned: pcall cannot swallow it).
[[noreturn]] void raiseStop(lua_State* L, LuaHost::Shared& s) {
  ++s.handler;  // not a guard object: lua_error leaves this frame
  lua_pushlstring(L, s.stopMessage.data(), s.stopMessage.size());
  --s.handler;
  lua_error(L);
  std::abort();  // unreachable: lua_error does not return
}

std::string stepsText(int64_t steps) { return std::to_string(steps) + " steps"; }

// Stops the running sandbox for the frame's budget (or, with `deadline`, for the wall-clock
// backstop): the stop is raised at every instruction until the call returns, and the sandbox that
// spent the most of the frame is the one disabled.
[[noreturn]] void stopOverBudget(lua_State* L, LuaHost::Shared& s, bool deadline) {
  {
    OpenReserve reserve(s);
    s.expired = true;
    hookEveryInstruction(s);
    int hog = s.current;
    if (!deadline)
      for (size_t i = 0; i < s.sandboxes.size(); ++i)
        if (s.sandboxes[i].spent > s.sandboxes[hog].spent) hog = static_cast<int>(i);
    s.hog = hog;
    std::string at = where(L, s);
    if (at.empty()) at = s.sandboxes[s.current].name + ": ";
    if (deadline) {
      s.stopMessage = at + "script stopped: the frame's scripts ran past the deadline of " +
                      milliseconds(s.limits.deadlineNanoseconds) +
                      " of machine time (work the step budget does not count, or a very slow machine: a replay of "
                      "this run may differ)";
    } else if (hog == s.current) {
      s.stopMessage = at + "script stopped: it ran past the frame's script budget of " +
                      stepsText(s.limits.frameSteps) + " (an endless loop?)";
    } else {
      s.stopMessage = at + "script stopped: the frame's script budget of " + stepsText(s.limits.frameSteps) +
                      " is spent (" + s.sandboxes[hog].name + " ran " + stepsText(s.sandboxes[hog].spent) + " of it)";
    }
  }
  raiseStop(L, s);
}

// Charges the running sandbox; stops it past the budget, or past the deadline once the timer
// said it may have come.
void charge(lua_State* L, LuaHost::Shared& s, int64_t steps) {
  s.frameSteps += steps;
  s.sandboxes[s.current].spent += steps;
  if (s.frameSteps > s.limits.frameSteps) stopOverBudget(L, s, false);
  if (s.timerFired) {
    s.timerFired = 0;
    const int64_t spent = s.frameSpent + (coarseNanoseconds() - s.enteredAt);  // the clock enteredAt was read with
    if (spent >= s.limits.deadlineNanoseconds) stopOverBudget(L, s, true);
    if (!s.timerArmed) armTimer(s, s.limits.deadlineNanoseconds - spent);  // a timer armed in an earlier frame
  }
}

// Runs every kTickSteps interpreted instructions, and on every one once a stop was decided or
// memory was refused.
void budgetHook(lua_State* L, lua_Debug*) {
  LuaHost::Shared& s = sharedOf(L);
  if (s.current != kNoSandbox) {
    if (s.expired) raiseStop(L, s);
    if (s.memoryStop != kNoSandbox) {
      {
        OpenReserve reserve(s);
        s.expired = true;
        std::string at = where(L, s);
        if (at.empty()) at = s.sandboxes[s.memoryStop].name + ": ";
        s.stopMessage = at + memoryStopText(s);
      }
      raiseStop(L, s);
    }
    charge(L, s, kTickSteps);
    return;
  }
  // Trusted code, after a sandboxed call that was stopped: back to the rare look.
  if (s.hookFast && !s.trustedExpired) {
    hookForTrusted(s);
    return;
  }
  if (!s.inCall) return;
  const int64_t limit = 2 * s.limits.deadlineNanoseconds;  // its own time and the sandboxes' it waited for
  if (!s.trustedExpired) {
    const int64_t now = nowNanoseconds();
    if (s.callStart == 0) {
      s.callStart = now;
      return;
    }
    if (now - s.callStart <= limit) return;
    s.trustedExpired = true;
    hookEveryInstruction(s);
  }
  {
    OpenReserve reserve(s);
    s.stopMessage = where(L, s) + "script stopped: one call from the engine ran longer than " + milliseconds(limit) +
                    " (an endless loop?)";
  }
  raiseStop(L, s);
}

// The message handler of every call: the message (file:line in front: Lua puts it there for errors
// raised by Lua code, this adds it for the others) and the traceback, separated by a newline the
// C++ side splits at. Runs where the error was raised. It calls no metamethod of a non-string error
// object: for a stop that point is inside the hook, where no hook fires, and a script's __tostring
// could loop there for ever.
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
  if (!placedOnStack(L, message) &&
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

// The game clock, in frames: what a sandbox's os.time, os.clock and os.date read.
int gameFrames(lua_State* L) {
  lua_pushnumber(L, static_cast<double>(sharedOf(L).gameFrame));
  return 1;
}

// The message and its traceback, each made printable and cut on its own (cutting them together
// lost the traceback of a long message).
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
  if (split == std::string_view::npos) return ScriptError(printableText(raw, length), "");
  return ScriptError(printableText(raw, split), printableText(raw + split + 1, length - split - 1));
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
  lua_newtable(L_);
  lua_pushcfunction(L_, printToSink);
  lua_setfield(L_, -2, "print");
  lua_pushcfunction(L_, gameFrames);
  lua_setfield(L_, -2, "frames");
  lua_pushcfunction(L_, orderedKeys);
  lua_setfield(L_, -2, "orderedKeys");
  lua_pushcfunction(L_, countedComparator);
  lua_setfield(L_, -2, "countedComparator");
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

int LuaHost::newSandbox(const std::string& chunkName) {
  const std::string name =
      chunkName.size() > 1 && (chunkName[0] == '@' || chunkName[0] == '=') ? chunkName.substr(1) : chunkName;
  lua_getfield(L_, LUA_REGISTRYINDEX, "platon.newSandbox");
  lua_pushlstring(L_, name.data(), name.size());
  pushSandboxApi();
  call(2, 1);
  Sandbox box;
  box.name = name;
  box.source = chunkName;
  box.env = lua::Ref(L_, -1);
  shared_->sandboxes.push_back(std::move(box));
  return static_cast<int>(shared_->sandboxes.size() - 1);
}

int LuaHost::loadString(std::string_view code, const std::string& chunkName, Trust trust) {
  const int top = lua_gettop(L_);
  if (trust == Trust::Sandboxed && !code.empty() && code[0] == '\x1b')
    throw ScriptError(chunkName.substr(chunkName[0] == '@' || chunkName[0] == '=' ? 1 : 0) +
                          ": a compiled (bytecode) chunk: sandboxed scripts load from text only",
                      "");
  const int status =
      luaL_loadbufferx(L_, code.data(), code.size(), chunkName.c_str(), trust == Trust::Sandboxed ? "t" : "bt");
  if (status != 0) {
    ScriptError error = errorFromStack(L_, status, *shared_);
    lua_settop(L_, top);
    throw error;
  }
  if (trust == Trust::Trusted) return kNoSandbox;
  // No compiled traces for untrusted code: the hooks must see every loop.
  luaJIT_setmode(L_, -1, LUAJIT_MODE_ALLFUNC | LUAJIT_MODE_OFF);
  const int id = newSandbox(chunkName);
  lua_setfenv(L_, -2);
  return id;
}

int LuaHost::loadFile(const std::string& path, Trust trust) {
  std::string code;
  try {
    code = files::readBoundedFile(path, kMaxScriptBytes);
  } catch (const files::FileError& e) {
    throw ScriptError(path + ": the script: " + e.reason(), "");
  }
  return loadString(code, "@" + path, trust);
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
    const bool late = s.frameSpent >= s.limits.deadlineNanoseconds;
    if (late || s.frameSteps >= s.limits.frameSteps) {  // the frame's budget is spent: skipped
      lua_pop(L_, nargs + 1);
      if (!s.skipNoted && !s.stopNoted)
        keepError(ScriptError(
            box.name + ": skipped: " +
                (late ? "the frame's deadline of " + milliseconds(s.limits.deadlineNanoseconds) + " has passed"
                      : "the frame's script budget of " + stepsText(s.limits.frameSteps) + " is spent") +
                " (the level's scripts and mods share it; their other calls this frame are "
                "skipped)",
            ""));
      s.skipNoted = true;
      return false;
    }
    s.enteredAt = coarseNanoseconds();
    if (!s.timerArmed) armTimer(s, s.limits.deadlineNanoseconds - s.frameSpent);
    // The count starts again here, and the call pays one tick for the instructions of its last
    // tick, which no look counts: so its charge depends on nothing that ran before it.
    hookForSandbox(s);
    s.callbackDepth = 0;
    s.frameSteps += kTickSteps;
    box.spent += kTickSteps;
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
  // An error, or a stop. A stop disables the sandbox that ran over: the one whose allocation was
  // refused, or the one that spent the most of the frame's steps.
  std::string message, traceback;
  if (status != 0) {
    ScriptError error = errorFromStack(L_, status, s);
    message = error.what();
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
  } else {
    lua_settop(L_, below);  // its results: a stopped sandbox's call gives none
    message = s.stopMessage;
  }
  // A refusal that unwound the sandbox before it ran another instruction: no place is known.
  if (s.memoryStop != kNoSandbox && (status == LUA_ERRMEM || message.empty()))
    message = s.sandboxes[static_cast<size_t>(s.memoryStop)].name + ": " + memoryStopText(s);
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
  if (off != kNoSandbox) {
    disable(off);
    message += "; " + s.sandboxes[static_cast<size_t>(off)].name + " disabled: fix it and save to reload";
    if (s.stopNoted && off == sandbox) message += " (the frame's other sandboxed calls are skipped)";
  }
  throw ScriptError(message, traceback);
}

void LuaHost::disable(int sandbox) {
  Sandbox& gone = shared_->sandboxes[static_cast<size_t>(sandbox)];
  gone.disabled = true;
  // Its globals go, so what it holds can be collected once the engine drops its functions.
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

CallbackDepth::CallbackDepth(lua_State* L) {
  void* ud = nullptr;
  static thread_local int otherStates = 0;  // a state of no host's (the pattern tests' own)
  depth_ = lua_getallocf(L, &ud) == limitedAlloc ? &static_cast<LuaHost::Shared*>(ud)->callbackDepth : &otherStates;
  if (*depth_ >= kMaxCallbackDepth)
    luaL_error(L, "callbacks nested more than %d deep (a gsub or sort callback that calls gsub or sort again?)",
               kMaxCallbackDepth);
  ++*depth_;
}

void chargeSteps(lua_State* L, int64_t steps) {
  void* ud = nullptr;
  if (lua_getallocf(L, &ud) != limitedAlloc) return;  // a state of no host's (the pattern tests' own)
  LuaHost::Shared& s = *static_cast<LuaHost::Shared*>(ud);
  if (s.current == kNoSandbox) return;
  if (s.expired) raiseStop(L, s);
  charge(L, s, steps);
}
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
