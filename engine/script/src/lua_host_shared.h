// The inside of a LuaHost (lua_host.h), shared by its three files: the host (lua_host.cpp), its
// limits (lua_limits.cpp: the allocator, the count hook, the deadline's timer, the stops) and its
// errors (lua_errors.cpp: the message handler, where an error is, what a message shows).
#pragma once
#include <algorithm>
#include <functional>
#include <signal.h>
#include <string>
#include <time.h>
#include <vector>

#include "lua_host.h"

namespace platon::script {

// One sandbox's state (not in an anonymous namespace: LuaHost::Shared, which has external linkage,
// holds a vector of them).
struct Sandbox {
  std::string name;    // the chunk's file, as messages name it
  std::string source;  // its chunk name ("@file"): the frames of its functions carry it
  lua::Ref env;
  bool disabled = false;
  bool borrowsEnv = false;  // its globals are another sandbox's (loadStringInGlobalsOf): never wiped
  int64_t spent = 0;        // steps of this frame's budget
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
  std::vector<int> released;  // sandboxes released (releaseSandbox): their places are taken again
  // The bytes of the state's blocks each sandbox made or last grew, [sandbox + 1] ([0]: the
  // engine's): what a memory stop blames. Never shrinks (a block names its maker's place for good).
  std::vector<int64_t> heldBytes = std::vector<int64_t>(1, 0);
  std::function<void(std::string_view, std::string_view)> print;

  size_t sandboxLimit() const { return limits.memoryBytes - limits.memoryBytes / kTrustedReserveDivisor; }
  // When the frame's sandboxed calls are over time: the deadline, or sooner, the time the steps
  // charged so far explain and the uncharged allowance.
  int64_t frameDeadline() const {
    return std::min(limits.deadlineNanoseconds, limits.unchargedNanoseconds + frameSteps * kStepNanoseconds);
  }
};

namespace host {

inline LuaHost::Shared& sharedOf(lua_State* L) {
  void* ud = nullptr;
  lua_getallocf(L, &ud);
  return *static_cast<LuaHost::Shared*>(ud);
}

// The message handler's and the stops' reserve: memory refused to sandboxes is open to them.
struct OpenReserve {
  LuaHost::Shared& s;
  explicit OpenReserve(LuaHost::Shared& shared) : s(shared) { ++s.handler; }
  ~OpenReserve() { --s.handler; }
};

// ---- lua_limits.cpp ----

int64_t nowNanoseconds();
// The same clock read at its last tick (a few ms of resolution, a third of the cost): what the
// per-call bookkeeping of sandboxed calls reads. Over many short calls its errors cancel out.
int64_t coarseNanoseconds();

// The count hook: on every instruction (a stop is under way), every kTickSteps (inside sandboxed
// calls), or rarely (trusted code's fallback).
void hookEveryInstruction(LuaHost::Shared& s);
void hookForSandbox(LuaHost::Shared& s);
void hookForTrusted(LuaHost::Shared& s);

// The deadline's timer: a host registers itself for the signal's handler.
void registerHost(LuaHost::Shared* shared);
void unregisterHost(LuaHost::Shared* shared);
void armTimer(LuaHost::Shared& s, int64_t nanoseconds);

// The state's allocator: its user data is the Shared.
void* limitedAlloc(void* ud, void* ptr, size_t oldSize, size_t newSize);

std::string milliseconds(int64_t nanoseconds);
std::string stepsText(int64_t steps);
std::string memoryStopText(const LuaHost::Shared& s);
// The enabled sandbox whose blocks hold the most of the state (kNoSandbox if none).
int biggestHolder(const LuaHost::Shared& s);

// ---- lua_errors.cpp ----

// "file:line: " of the innermost frame of a script file: of the running sandbox's own file when
// it is on the stack, else of any script file; "" when there is none.
std::string where(lua_State* L, const LuaHost::Shared& s);
// Whether a message already starts with "place:line: " (on its first line).
bool located(const char* message);
// The message handler of every call (file:line in front, the traceback after).
int tracebackHandler(lua_State* L);
// The error on top of the stack after a failed call, as a ScriptError.
ScriptError errorFromStack(lua_State* L, int status, const LuaHost::Shared& shared);

}  // namespace host
}  // namespace platon::script
