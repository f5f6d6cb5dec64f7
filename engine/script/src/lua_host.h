// One LuaJIT state with the limits the engine puts on it, a traceback on every error, and two
// kinds of code:
//
//  - trusted: the engine's own scripts (scripts/), nothing else (scenarios run sandboxed). All of
//    LuaJIT's libraries, the JIT on. A trusted endless loop that the JIT compiled cannot be stopped
//    from inside the process (LuaJIT runs no hooks in compiled traces); the scenario runner's
//    worker processes are killed from outside after their wall-clock limit instead. An interpreted one is stopped
//    by the count hook after twice the frame budget.
//  - sandboxed: level scripts, mods and a level's own rules. Each loaded chunk is a sandbox with
//    an id, its own globals (the safe part of the standard library, see sandbox.cpp), loaded from
//    text only, with the JIT off for every function it defines (so hooks fire inside its loops).
//
// Sandboxed code runs only through callSandboxed() (engine.call from Lua), which enforces:
//  - work: every sandboxed call of a frame shares one budget of steps (limits.frameSteps, counted
//    from beginFrame()). An interpreted instruction is a step, counted by a count hook every
//    kTickSteps instructions (the counter starts again at each call from the engine, which is
//    charged one tick for the part of a tick it may leave uncounted); C functions that loop charge
//    their work too (chargeSteps: patterns, ordering keys, sorting). The same calls cost the same
//    steps on every machine, so a stop happens at the same instruction everywhere and replays.
//    After the budget is spent, the frame's further sandboxed calls are skipped.
//  - time, the backstop: a wall-clock deadline (limits.deadlineNanoseconds) on the frame's
//    sandboxed calls together, for work nothing charged, and sooner when the time is far more
//    than the steps charged explain (limits.unchargedNanoseconds beyond kStepNanoseconds a step). A POSIX timer fires
//    at the deadline on the calling thread and its handler sets a flag the count hook and chargeSteps look at. A stop
//    by the deadline depends on the machine and says so.
//  - memory: sandboxed allocations are refused past limits.memoryBytes minus a reserve
//    (kTrustedReserve of it), so the engine's own scripts can still run; after a refusal, the
//    sandbox is stopped at its next instruction with its file:line and traceback.
//  - policy: a sandbox stopped by either limit is disabled (its later calls are skipped, its
//    globals cleared so its memory can be collected), with one error naming it.
//
// Errors come back as ScriptError with "file:line: message" and the Lua traceback. Calls nest
// (a callback from C++ inside a call from Lua).
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lua_stack.h"
#include "platon/script/script_error.h"

namespace platon::script {

struct LuaLimits {
  size_t memoryBytes = size_t{128} << 20;  // the whole state: every script and its data
  // All sandboxed calls of one frame together: 0.04-0.08 s of interpreted Lua on a 2020s x86-64
  // core (4-8 ns an instruction with the hook on), far above what a game's scripts use a frame.
  int64_t frameSteps = 10'000'000;
  // The same calls' wall-clock time, the backstop for uncharged work: far enough above the steps'
  // time (200 ns a step) that a machine or a step slower than usual still meets the budget first.
  int64_t deadlineNanoseconds = 2'000'000'000;
  // Work no step counts still has to be explained by the steps: the frame's sandboxed calls may
  // take this much machine time beyond kStepNanoseconds a charged step, never more (before the
  // deadline). A compare of two 50 MB strings is one instruction (a step) and 10 ms of memcmp: a
  // level doing a few hundred a frame ran at 1 frame a second, under the deadline, for good.
  int64_t unchargedNanoseconds = 250'000'000;
};
// The machine time a charged step may take before its frame is over time: the slowest build and
// machine the steps were measured on (4-8 ns with the hook on; AddressSanitizer, a loaded CI
// machine: up to 30) and a wide margin.
inline constexpr int64_t kStepNanoseconds = 200;

// Interpreted instructions between two looks of the count hook, and what each look charges.
inline constexpr int kTickSteps = 100;
// What an error a sandbox catches (pcall, xpcall, coroutine.resume) or an engine call's failure
// is charged: the unwinding costs 3 to 12 us (docs/scripting.md, Limits), 1,000 to 3,000 steps.
inline constexpr int kErrorSteps = 3000;

// Charges `steps` of C work (a C function's loop, where no hook runs) to the sandbox running now
// and to the frame's budget; past the budget, or past the deadline, it stops that sandbox at its
// line (raises the stop, which pcall cannot swallow). Does nothing when no sandbox runs. Call it
// with no C++ object alive that needs its destructor: it may not return.
void chargeSteps(lua_State* L, int64_t steps);

// Held by a C function of ours around a call back into Lua (a gsub replacement function or table, a
// sort comparator). Such a callback can call the same C function again, nesting C frames that
// LuaJIT does not count as Lua frames (a match's frame was large: gsub calling gsub crashed the
// process before LuaJIT's own limit): past kMaxCallbackDepth nested callbacks the call is refused
// with a Lua error, at the script's line. The depth starts again at each call from the engine.
// 150: below LuaJIT's own 200 nested C calls, above what stock Lua 5.1 scripts nest (its test
// suite's pm.lua reverses a 60-character string by gsub inside gsub); a gsub level takes about
// 11 KB of C stack, so 150 take 1.6 MB of the main thread's 8.
inline constexpr int kMaxCallbackDepth = 150;
class CallbackDepth {
 public:
  explicit CallbackDepth(lua_State* L);  // raises the error past the limit (nothing is held then)
  ~CallbackDepth() { --*depth_; }
  CallbackDepth(const CallbackDepth&) = delete;
  CallbackDepth& operator=(const CallbackDepth&) = delete;

 private:
  int* depth_;
};

enum class Trust { Trusted, Sandboxed };

inline constexpr int kNoSandbox = -1;

class LuaHost {
 public:
  explicit LuaHost(LuaLimits limits = {});
  ~LuaHost();
  LuaHost(const LuaHost&) = delete;
  LuaHost& operator=(const LuaHost&) = delete;

  lua_State* state() const { return L_; }

  // Compiles a file or a string and pushes the chunk as a function; throws ScriptError with the
  // syntax error's file:line. Sandboxed: text only (bytecode is refused), the chunk gets a new
  // sandbox (its environment) named after the chunk, the JIT is off for the chunk and every
  // function inside it, and the sandbox's id is returned (kNoSandbox for trusted code). Run the
  // chunk with callSandboxed(id, ...).
  // `shownAs`: the name the chunk carries (messages, tracebacks) instead of the path: sandboxed
  // code is named from its level's folder ("level.lua"), so what it sees of its own errors is the
  // same wherever the level is installed and tells nothing of the player's folders.
  int loadFile(const std::string& path, Trust trust, const std::string& shownAs = "");
  static constexpr size_t kMaxScriptBytes = size_t{16} << 20;  // a script file (a regular file)
  int loadString(std::string_view code, const std::string& chunkName, Trust trust);
  // Compiles `code` as sandboxed code that sees sandbox `envOf`'s globals (reads and writes them),
  // as a sandbox of its own: its budget, its errors, its being disabled are its own. Pushes the
  // chunk; returns its id. The game's console, in the level script's globals.
  int loadStringInGlobalsOf(std::string_view code, const std::string& chunkName, int envOf);
  // Ends sandbox `sandbox` for good, once its chunk has run (a console line): disabled, its
  // globals let go (garbage unless a function it left elsewhere still reads them), and its place in
  // the list taken by the next sandbox made, so lines that come and go leave nothing behind.
  void releaseSandbox(int sandbox);

  // The table of functions trusted scripts see as `platon`. Pushes it.
  void pushApi();
  // What sandboxes see as `platon` (read-only for them): the same table, but for the entries
  // replaced for them with setSandboxOverride (a new table each call). Pushes it.
  void pushSandboxApi();
  // Pops a value that replaces api entry `name` in what sandboxes see (the world's classic C
  // functions where trusted code calls FFI wrappers the JIT compiles: a sandbox's calls must cost
  // the same steps in every run).
  void setSandboxOverride(const char* name);
  // Gives every sandbox made so far a new view of the API (its `platon`): what the engine added
  // since (the scene's tags, known once every mod declared its own) is in it. A view is a copy made
  // when it is made, so a mod loaded to declare its tags saw no tags at all, not even the game's.
  void refreshSandboxApi();
  // Pushes readonly(t, name) of the prelude: a read-only view of the table at `index` (nested
  // tables are views too), for the engine's tables that sandboxes are handed.
  void pushReadOnly(int index, std::string_view name);

  // Calls the function at -(nargs + 1) with the nargs values above it; leaves nresults results.
  // Any Lua error, time budget or memory limit throws ScriptError and leaves the stack as it was
  // before the function was pushed.
  void call(int nargs, int nresults);

  // The same for sandbox `sandbox`'s code, under the frame's budget and the sandboxes' memory
  // limit. Returns false, with the function and its arguments popped and nothing pushed, when the
  // call was skipped: the sandbox is disabled, or the frame's budget is spent. Throws ScriptError
  // for its errors (a limit's stop names the sandbox and says it is now disabled).
  bool callSandboxed(int sandbox, int nargs, int nresults);

  // A new frame: the sandboxes' shared budget of steps and time starts again.
  void beginFrame();
  // What the frame's budget has spent, to be put back (drawing runs on a budget of its own, at the
  // display's rate, between the frames that replays run: it must not spend theirs).
  struct Budget {
    int64_t frameSteps, frameSpent;
    size_t printed;
    bool skipNoted, stopNoted;
    std::vector<int64_t> spent;
  };
  Budget budget() const;
  void restoreBudget(const Budget& budget);
  // The game clock sandboxes read through os.time/os.clock/os.date (frames, 60 a second).
  void setGameFrame(uint64_t frame);

  // Charges sandbox `sandbox` for engine work done for it outside its calls (the physics of the
  // bodies it made: `steps` of the same budget its instructions spend). Past the frame's budget the
  // sandbox is disabled and the returned error says why, with `what` (what the work was); else
  // nothing. A disabled sandbox is not charged.
  std::optional<ScriptError> chargeWork(int sandbox, int64_t steps, const std::string& what);

  bool disabled(int sandbox) const;
  // The sandbox whose code runs now, or kNoSandbox (trusted code, or nothing).
  int runningSandbox() const;
  const std::string& sandboxName(int sandbox) const;
  // Where sandboxed calls that Lua made through engine.call (pushCallFunction) failed: the errors
  // kept for the caller to report, oldest first, and cleared.
  std::vector<ScriptError> takeErrors();
  bool hasErrors() const { return !errors_.empty(); }
  // Keeps an error for takeErrors() (at most kMaxKeptErrors between two looks: a rules callback
  // that fails on every contact says it a few times, not a million).
  void keepError(ScriptError error);
  static constexpr size_t kMaxKeptErrors = 8;
  // Pushes engine.call(sandbox, f, ...) -> true, f's results | false: a C function that calls f
  // as sandbox `sandbox`'s code behind its own error boundary. An error is kept (takeErrors) and
  // the caller goes on; a disabled sandbox or a spent budget skips the call.
  void pushCallFunction();

  // Where print() goes: the script's name and its text. Default: stderr.
  void setPrintSink(std::function<void(std::string_view name, std::string_view text)> sink);

  size_t memoryUsed() const;
  const LuaLimits& limits() const;
  void setLimits(const LuaLimits& limits);

  // Full garbage collection (after a script was dropped, say); also when a disabled sandbox left
  // memory behind.
  void collectGarbage();
  void collectIfNeeded();

  // The part of memoryBytes sandboxes may not use: kept for trusted code.
  static constexpr size_t kTrustedReserveDivisor = 4;

  // Steps charged to sandboxed calls this frame (interpreted instructions and C work).
  int64_t frameSteps() const;

  struct Shared;  // what the allocator, the hook and the timer reach through the state

 private:
  std::unique_ptr<Shared> shared_;
  lua_State* L_ = nullptr;
  int depth_ = 0;
  int tracebackRef_ = LUA_NOREF;
  std::vector<ScriptError> errors_;
  static constexpr int kTracebackSlot = 1;
  void openTrusted();
  int newSandbox(const std::string& chunkName);
  // A sandbox whose globals are the table on top of the stack (left there); returns its id.
  int addSandbox(const std::string& chunkName, bool borrowsEnv);
  // Compiles and pushes the chunk (throws ScriptError with the syntax error's file:line).
  void compile(std::string_view code, const std::string& chunkName, Trust trust);
  void disable(int sandbox);  // for good: its globals dropped, its garbage collected
  void blameTheBiggestHolder(Shared& s, std::string& message);
  void callNested(int nargs, int nresults);
  int protectedCall(int nargs, int nresults, int& below);
  [[gnu::cold]] void afterFailedCall(int status, int below);
  // callSandboxed's slow paths: a skipped call said, a failed or stopped call turned into its error.
  [[gnu::cold]] void noteSkippedCall(int sandbox, bool late);
  [[noreturn, gnu::cold]] void failSandboxedCall(int sandbox, int status, int below, bool stopped);
  std::string failedCallMessage(int sandbox, int status, int below, bool stopped, std::string& traceback);
  void disableAfterStop(int sandbox, std::string& message);
  static int luaCallSandboxed(lua_State* L);
};

}  // namespace platon::script
