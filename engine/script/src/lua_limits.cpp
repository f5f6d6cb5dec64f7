// A LuaHost's limits: the allocator (memory), the count hook and the C work's charges (steps),
// the deadline's timer (time), and the stops they raise. lua_host.h says what each limit does.
#include <atomic>
#include <cstdlib>
#include <mutex>
#include <unistd.h>

#include "lua_host_shared.h"

namespace platon::script {
namespace host {

namespace {
constexpr int kTrustedHookInstructions = 100'000;
void budgetHook(lua_State* L, lua_Debug*);
}  // namespace

int64_t nowNanoseconds() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return int64_t{t.tv_sec} * 1'000'000'000 + t.tv_nsec;
}

int64_t coarseNanoseconds() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC_COARSE, &t);
  return int64_t{t.tv_sec} * 1'000'000'000 + t.tv_nsec;
}

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

namespace {

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

}  // namespace

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

namespace {
// Each block of the state carries who made it (or last grew it), so a memory stop can blame the
// sandbox that holds the most, not the one whose allocation happened to cross the line (a level's
// script, after many mods filled the state). 16 bytes keep malloc's alignment.
struct alignas(16) BlockHeader {
  int32_t owner;
};
static_assert(sizeof(BlockHeader) == 16);

int64_t& heldBy(LuaHost::Shared& s, int owner) {
  const size_t at = static_cast<size_t>(owner) + 1;  // kNoSandbox (-1): the engine's, [0]
  return at < s.heldBytes.size() ? s.heldBytes[at] : s.heldBytes[0];
}
}  // namespace

void* limitedAlloc(void* ud, void* ptr, size_t oldSize, size_t newSize) {
  auto* shared = static_cast<LuaHost::Shared*>(ud);
  const size_t old = ptr ? oldSize : 0;
  BlockHeader* block = ptr ? static_cast<BlockHeader*>(ptr) - 1 : nullptr;
  if (newSize == 0) {
    if (block) heldBy(*shared, block->owner) -= static_cast<int64_t>(old);
    std::free(block);
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
  auto* header = static_cast<BlockHeader*>(std::realloc(block, newSize + sizeof(BlockHeader)));
  if (!header) return nullptr;
  if (!block) {
    header->owner = shared->current;
  } else if (newSize > old && header->owner != shared->current) {  // a shrink is the collector's
    heldBy(*shared, header->owner) -= static_cast<int64_t>(old);
    header->owner = shared->current;
    heldBy(*shared, header->owner) += static_cast<int64_t>(old);
  }
  heldBy(*shared, header->owner) += static_cast<int64_t>(newSize) - static_cast<int64_t>(old);
  shared->used = shared->used - old + newSize;
  return header + 1;
}

int biggestHolder(const LuaHost::Shared& s) {
  int most = kNoSandbox;
  for (size_t i = 0; i < s.sandboxes.size(); ++i) {
    if (s.sandboxes[i].disabled) continue;
    if (most == kNoSandbox || s.heldBytes[i + 1] > s.heldBytes[static_cast<size_t>(most) + 1])
      most = static_cast<int>(i);
  }
  return most;
}

std::string milliseconds(int64_t nanoseconds) { return std::to_string((nanoseconds + 500'000) / 1'000'000) + " ms"; }

std::string memoryStopText(const LuaHost::Shared& s) {
  return "script stopped: the sandboxes reached their memory limit of " + std::to_string(s.sandboxLimit() >> 20) +
         " MB (of the Lua state's " + std::to_string(s.limits.memoryBytes >> 20) +
         " MB; the rest is kept for the engine)";
}

std::string stepsText(int64_t steps) { return std::to_string(steps) + " steps"; }

namespace {

// Raises the stop the hook decided on (the same message at every instruction until the sandboxed
// call has returned: pcall cannot swallow it).
[[noreturn]] void raiseStop(lua_State* L, LuaHost::Shared& s) {
  ++s.handler;  // not a guard object: lua_error leaves this frame
  lua_pushlstring(L, s.stopMessage.data(), s.stopMessage.size());
  --s.handler;
  lua_error(L);
  std::abort();  // unreachable: lua_error does not return
}

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
    if (deadline && s.frameDeadline() < s.limits.deadlineNanoseconds) {
      s.stopMessage = at + "script stopped: the frame's scripts ran " + milliseconds(s.frameDeadline()) +
                      " of machine time, far more than the " + stepsText(s.frameSteps) +
                      " they were charged explain (work the step budget does not count, such as comparing very long "
                      "strings; or a very slow machine: a replay of this run may differ)";
    } else if (deadline) {
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
    if (spent >= s.frameDeadline()) stopOverBudget(L, s, true);
    if (!s.timerArmed) armTimer(s, s.frameDeadline() - spent);  // not over yet: the steps explained more
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

}  // namespace
}  // namespace host

CallbackDepth::CallbackDepth(lua_State* L) {
  void* ud = nullptr;
  static thread_local int otherStates = 0;  // a state of no host's (the pattern tests' own)
  depth_ =
      lua_getallocf(L, &ud) == host::limitedAlloc ? &static_cast<LuaHost::Shared*>(ud)->callbackDepth : &otherStates;
  if (*depth_ >= kMaxCallbackDepth)
    luaL_error(L, "callbacks nested more than %d deep (a gsub or sort callback that calls gsub or sort again?)",
               kMaxCallbackDepth);
  ++*depth_;
}

void chargeSteps(lua_State* L, int64_t steps) {
  void* ud = nullptr;
  if (lua_getallocf(L, &ud) != host::limitedAlloc) return;  // a state of no host's (the pattern tests' own)
  LuaHost::Shared& s = *static_cast<LuaHost::Shared*>(ud);
  if (s.current == kNoSandbox) return;
  if (s.expired) host::raiseStop(L, s);
  host::charge(L, s, steps);
}

}  // namespace platon::script
