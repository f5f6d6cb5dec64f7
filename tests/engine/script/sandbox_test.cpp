// Every refusal of the sandbox, proved by the error a script gets, and the limits that stop a
// runaway script: an endless loop (also one the JIT would compile), unbounded memory, pcall games.
#include <chrono>

#include <gtest/gtest.h>

#include "lua_host.h"
#include "lua_rules.h"
#include "lua_stack.h"

namespace platon::script {
namespace {

// Runs `code` as a sandboxed chunk named "mod.lua", as the first call of a frame; returns the
// error's message ("" if none).
std::string runSandboxed(LuaHost& host, const std::string& code) {
  try {
    const int id = host.loadString(code, "@mod.lua", Trust::Sandboxed);
    host.beginFrame();
    if (!host.callSandboxed(id, 0, 0)) return "skipped";
  } catch (const ScriptError& e) {
    return e.what();
  }
  return "";
}

std::string runSandboxed(const std::string& code) {
  LuaHost host;
  return runSandboxed(host, code);
}

TEST(Sandbox, PlainLuaRuns) {
  EXPECT_EQ(runSandboxed("local t = {} for i = 1, 100 do t[#t + 1] = string.format('%d', i) end "
                         "assert(table.concat(t):sub(1, 3) == '123') assert(math.floor(2.5) == 2) "
                         "assert(bit.band(6, 3) == 2) assert(type(os.time()) == 'number') "
                         "local co = coroutine.wrap(function() coroutine.yield(1) end) assert(co() == 1)"),
            "");
}

struct Refusal {
  const char* code;
  const char* message;  // a part of the error the script gets
};

class SandboxRefuses : public testing::TestWithParam<Refusal> {};

TEST_P(SandboxRefuses, WithAClearError) {
  const std::string error = runSandboxed(GetParam().code);
  EXPECT_NE(error.find(GetParam().message), std::string::npos) << "code: " << GetParam().code << "\nerror: " << error;
  EXPECT_EQ(error.rfind("mod.lua:", 0), 0u) << error;  // every error names the script's file:line
}

INSTANTIATE_TEST_SUITE_P(
    Each, SandboxRefuses,
    testing::Values(
        Refusal{"io.open('/etc/passwd')", "attempt to index global 'io' (a nil value)"},
        Refusal{"os.execute('true')", "attempt to call field 'execute' (a nil value)"},
        Refusal{"os.exit(1)", "attempt to call field 'exit' (a nil value)"},
        Refusal{"os.remove('x')", "attempt to call field 'remove' (a nil value)"},
        Refusal{"os.getenv('HOME')", "attempt to call field 'getenv' (a nil value)"},
        Refusal{"require('os')", "attempt to call global 'require' (a nil value)"},
        Refusal{"package.loadlib('libc.so.6', 'system')", "attempt to index global 'package'"},
        Refusal{"local ffi = ffi.C", "attempt to index global 'ffi' (a nil value)"},
        Refusal{"jit.off()", "attempt to index global 'jit' (a nil value)"},
        Refusal{"debug.getregistry()", "attempt to index global 'debug' (a nil value)"},
        Refusal{"load('return 1')", "attempt to call global 'load' (a nil value)"},
        Refusal{"loadstring('\\27LJ')", "attempt to call global 'loadstring' (a nil value)"},
        Refusal{"dofile('/etc/passwd')", "attempt to call global 'dofile' (a nil value)"},
        Refusal{"loadfile('x')", "attempt to call global 'loadfile' (a nil value)"},
        Refusal{"string.dump(print)", "attempt to call field 'dump' (a nil value)"},
        Refusal{"getfenv(0).x = 1", "attempt to call global 'getfenv' (a nil value)"},
        Refusal{"setfenv(1, {})", "attempt to call global 'setfenv' (a nil value)"},
        Refusal{"rawset(platon, 'x', 1)", "attempt to call global 'rawset' (a nil value)"},
        Refusal{"newproxy(true)", "attempt to call global 'newproxy' (a nil value)"},
        Refusal{"collectgarbage('stop')", "a sandbox may not drive the garbage collector"},
        Refusal{"collectgarbage('count')", "collectgarbage(\"count\") is not for sandboxes"},
        Refusal{"getmetatable('').__index = {}", "attempt to index a string value"},
        Refusal{"setmetatable(platon, {})", "cannot change a protected metatable"},
        Refusal{"platon.x = 1", "platon is read-only (tried to set x)"},
        Refusal{"string.find(string.rep('a', 5000), '.-.-.-b')", "pattern too costly"},
        Refusal{"for w in string.gmatch(string.rep('a', 20000), 'a*a*b') do end", "pattern too costly"},
        Refusal{"module('x')", "attempt to call global 'module' (a nil value)"},
        // The string methods are the sandbox's too: no dump, and counted patterns.
        Refusal{"local dump = ('').dump; dump(print)", "attempt to call local 'dump' (a nil value)"},
        Refusal{"local s = string.rep('a', 40) local r = s:find('.-.-.-.-.-.-.-.-.-.-b')", "pattern too costly"},
        Refusal{"for k in pairs({ [print] = 1 }) do end", "pairs over function keys has no fixed order"},
        Refusal{"local t = {} for i = 1, 1000001 do t[i] = i end table.sort(t)", "table.sort: at most 1000000 items"}),
    // Named by their place in the list: the default name prints the struct's bytes, pointers
    // included, so the tests' names would change from one build to the next.
    [](const testing::TestParamInfo<Refusal>& param) { return "Case" + std::to_string(param.index); });

TEST(Sandbox, ChangesToTheSharedLibrariesStayInTheSandbox) {
  LuaHost host;
  EXPECT_EQ(runSandboxed(host, "string.upper = nil; math.floor = nil; table.insert = nil"), "");
  EXPECT_EQ(runSandboxed(host,
                         "assert(string.upper('a') == 'A'); assert(('a'):upper() == 'A'); "
                         "assert(math.floor(1.5) == 1); table.insert({}, 1)"),
            "");
  // Trusted code sees its own libraries untouched too.
  host.loadString("return string.upper('a'), math.floor(1.5)", "=trusted", Trust::Trusted);
  host.call(0, 2);
  EXPECT_STREQ(lua_tostring(host.state(), -2), "A");
  lua_pop(host.state(), 2);
}

// Every string's methods are the counted pattern functions and have no dump, for trusted code too;
// trusted code's global string keeps LuaJIT's own (and dump).
TEST(Sandbox, StringMethodsAreTheSandboxsForEveryone) {
  LuaHost host;
  host.loadString(
      "return ('').dump == nil, string.dump ~= nil, ('').find ~= string.find, ('').len == string.len, "
      "getmetatable('')",
      "=trusted", Trust::Trusted);
  host.call(0, 5);
  lua_State* L = host.state();
  EXPECT_TRUE(lua_toboolean(L, -5));
  EXPECT_TRUE(lua_toboolean(L, -4));
  EXPECT_TRUE(lua_toboolean(L, -3));
  EXPECT_TRUE(lua_toboolean(L, -2));
  EXPECT_STREQ(lua_tostring(L, -1), "locked");
  lua_pop(L, 5);
}

TEST(Sandbox, GlobalsOfOneSandboxAreNotAnothers) {
  LuaHost host;
  EXPECT_EQ(runSandboxed(host, "secret = 42"), "");
  EXPECT_EQ(runSandboxed(host, "assert(secret == nil, 'leaked')"), "");
}

TEST(Sandbox, RandomIsTheSameSequenceEveryRun) {
  LuaHost host;
  EXPECT_EQ(runSandboxed(host,
                         "math.randomseed(7) local a = math.random(1, 1000) math.randomseed(7) "
                         "assert(a == math.random(1, 1000)) assert(a >= 1 and a <= 1000)"),
            "");
}

TEST(Sandbox, BytecodeIsRefused) {
  LuaHost host;
  host.loadString("return string.dump(function() return 1 end)", "=trusted", Trust::Trusted);
  host.call(0, 1);
  size_t length = 0;
  const char* bytes = lua_tolstring(host.state(), -1, &length);
  const std::string bytecode(bytes, length);
  lua_pop(host.state(), 1);
  try {
    host.loadString(bytecode, "@mod.luac", Trust::Sandboxed);
    FAIL() << "bytecode loaded in a sandbox";
  } catch (const ScriptError& e) {
    EXPECT_NE(
        std::string(e.what()).find("mod.luac: a compiled (bytecode) chunk: sandboxed scripts load from text only"),
        std::string::npos)
        << e.what();
  }
}

// --- runaway scripts ---

// A budget of a million steps; the wall-clock deadline far beyond what they take on any machine,
// so the steps decide every stop here.
LuaLimits shortBudget() {
  LuaLimits limits;
  limits.frameSteps = 1'000'000;
  limits.deadlineNanoseconds = int64_t{3600} * 1'000'000'000;
  limits.unchargedNanoseconds = limits.deadlineNanoseconds;
  return limits;
}

// Runs `code` sandboxed under a budget of a million steps and checks it is stopped by them.
void expectStoppedByBudget(const std::string& code) {
  LuaHost host(shortBudget());
  const std::string error = runSandboxed(host, code);
  EXPECT_NE(error.find("script stopped: it ran past the frame's script budget of 1000000 steps (an endless loop?); "
                       "mod.lua disabled: fix it and save to reload"),
            std::string::npos)
      << error;
  EXPECT_EQ(error.rfind("mod.lua:", 0), 0u) << error;
  EXPECT_GT(host.frameSteps(), 1'000'000);
  // The host is usable afterwards.
  EXPECT_EQ(runSandboxed(host, "local x = 0 for i = 1, 1000 do x = x + i end assert(x == 500500)"), "");
}

TEST(Runaway, AnEndlessLoopIsStopped) { expectStoppedByBudget("while true do end"); }

// The loop LuaJIT would compile after a few dozen iterations; compiled traces run no hooks. The
// sandbox turns the JIT off for the chunk's functions, so the hook still sees it.
TEST(Runaway, AHotNumericLoopIsStopped) { expectStoppedByBudget("local x = 0 for i = 1, 1e15 do x = x + i * 0.5 end"); }

TEST(Runaway, ALoopInAFunctionItDefinedIsStopped) {
  expectStoppedByBudget("local function spin(n) local s = 0 while n > 0 do s = s + n end return s end spin(1)");
}

TEST(Runaway, PcallCannotSwallowTheStop) {
  expectStoppedByBudget("while true do pcall(function() while true do end end) end");
  expectStoppedByBudget("while true do xpcall(function() while true do end end, function() while true do end end) end");
  expectStoppedByBudget("xpcall(function() while true do end end, function(e) while true do end end)");
}

TEST(Runaway, XpcallHandlersStillWork) {
  EXPECT_EQ(runSandboxed(
                "local ok, m = xpcall(function(a) error('x' .. a, 0) end, function(e) return 'handled ' .. e end, 1) "
                "assert(not ok and m == 'handled x1', m) "
                "local ok2, a, b = xpcall(function(x, y) return x, y end, print, 1, nil) assert(ok2 and a == 1 and b "
                "== nil)"),
            "");
}

TEST(Runaway, ALoopInsideACoroutineIsStopped) {
  expectStoppedByBudget("local co = coroutine.wrap(function() while true do end end) co()");
}

TEST(Runaway, ALoopInAMetamethodIsStopped) {
  expectStoppedByBudget("local t = setmetatable({}, {__index = function() while true do end end}) local _ = t.x");
}

// Trusted code is not charged: a loop of far more instructions than a frame's budget runs to its
// end (the JIT compiles it: its compiled trace runs no hook at all, which is why the sandbox turns
// the JIT off), and charges nothing.
TEST(Runaway, TrustedCodeIsNotCharged) {
  LuaHost host(shortBudget());
  host.beginFrame();
  host.loadString("local x = 0 for i = 1, 1e7 do x = x + i end return x", "=trusted", Trust::Trusted);
  host.call(0, 1);
  EXPECT_EQ(lua_tonumber(host.state(), -1), 5e13 + 5e6);
  lua_pop(host.state(), 1);
  EXPECT_EQ(host.frameSteps(), 0);
}

// Runs sandboxed `code` with a table {n = 0} as its argument (a counter it can raise); returns
// its error and the counter's last value.
std::pair<std::string, double> runCounting(LuaHost& host, const std::string& code) {
  lua_State* L = host.state();
  lua_newtable(L);
  lua_pushnumber(L, 0);
  lua_setfield(L, -2, "n");
  std::string error;
  try {
    const int box = host.loadString(code, "@mod.lua", Trust::Sandboxed);
    host.beginFrame();
    lua_pushvalue(L, -2);
    host.callSandboxed(box, 1, 0);
  } catch (const ScriptError& e) {
    error = e.what();
  }
  lua_getfield(L, -1, "n");
  const double n = lua_tonumber(L, -1);
  lua_pop(L, 2);
  return {error, n};
}

// The budget counts work, not time: the same calls are charged the same steps in every run, and a
// loop is stopped at the same iteration, whatever the machine is doing.
TEST(Runaway, TheSameCallsCostTheSameStepsInEveryRun) {
  const std::string code =
      "local t = ... local s = string.rep('ab', 5000)\n"
      "while true do t.n = t.n + 1 local x = s:find('b', t.n % 1000, true) .. #tostring(t.n) end";
  std::vector<double> stoppedAt;
  for (int run = 0; run < 3; ++run) {
    LuaHost host(shortBudget());
    const auto [error, n] = runCounting(host, code);
    EXPECT_EQ(error.rfind("mod.lua:2: script stopped: it ran past the frame's script budget", 0), 0u) << error;
    stoppedAt.push_back(n);
  }
  EXPECT_GT(stoppedAt[0], 1000);
  EXPECT_EQ(stoppedAt[1], stoppedAt[0]);
  EXPECT_EQ(stoppedAt[2], stoppedAt[0]);
}

// The wall-clock deadline stops what the steps allow but the machine cannot do in time (work no
// step counts): here a budget of steps no frame spends, and a deadline of 20 ms. Time decides this
// stop, so where it comes depends on the machine; that it comes, and what it says, does not.
TEST(Runaway, TheDeadlineStopsWhatTheStepsAllow) {
  LuaLimits limits;
  limits.frameSteps = int64_t{1} << 60;
  limits.deadlineNanoseconds = 20'000'000;
  LuaHost host(limits);
  EXPECT_EQ(runSandboxed(host, "local n = 0\nwhile true do n = n + 1 end"),
            "mod.lua:2: script stopped: the frame's scripts ran past the deadline of 20 ms of machine time (work the "
            "step budget does not count, or a very slow machine: a replay of this run may differ); mod.lua disabled: "
            "fix it and save to reload (the frame's other sandboxed calls are skipped)");
  // The next frame's calls run again.
  EXPECT_EQ(runSandboxed(host, "local x = 0 for i = 1, 1000 do x = x + i end assert(x == 500500)"), "");
}

// One instruction whose work no step counts (two long strings compared: a memcmp of their common
// part) is stopped by time, long before the deadline: the frame's time may exceed what its steps
// explain by limits.unchargedNanoseconds only. Each route here compares 8 MB strings in a loop
// of a few steps: the 10 million steps of the budget would take hours, the 2 s deadline was met
// anew each frame by a level that did a few hundred a frame.
TEST(Runaway, WorkTheStepsDoNotExplainIsStoppedByTime) {
  const std::string setup = "local a = string.rep('x', 2^23) .. 'a' local b = string.rep('x', 2^23) .. 'b'\n";
  const char* routes[] = {
      "while true do local _ = a < b end",
      "while true do local _ = a <= b end",
      "while true do local _ = b > a end",
      "local t = {} for i = 1, 64 do t[i] = (i % 2 == 0) and a or b end while true do table.sort(t) end",
      "local n = 0 while true do if a < b then n = n + 1 end end",
      "while true do local y = a .. 'c' end",  // a join copies both strings
  };
  for (const char* route : routes) {
    LuaHost host;
    const std::string error = runSandboxed(host, setup + route);
    EXPECT_EQ(error.rfind("mod.lua:2: script stopped: the frame's scripts ran ", 0), 0u) << route << "\n" << error;
    EXPECT_NE(error.find(" ms of machine time, far more than the "), std::string::npos) << error;
    EXPECT_NE(error.find("they were charged explain (work the step budget does not count, such as comparing very long "
                         "strings; or a very slow machine: a replay of this run may differ); mod.lua disabled"),
              std::string::npos)
        << error;
  }
}

// C functions that loop charge their work: a sort whose comparator is a pattern function runs no
// Lua instruction between comparisons, yet each comparison's matching is charged, so the sort is
// stopped by the budget (it would take hours otherwise).
TEST(Runaway, CWorkIsChargedWithNoInstructionBetween) {
  expectStoppedByBudget(
      "local t = {} for i = 1, 2000 do t[i] = string.rep('a', 2000) .. i end\n"
      "table.sort(t, string.find)");
  // Ordering 20,000 keys for pairs costs about 340,000 steps: a few walks spend the budget (were
  // it not charged, the loop's own instructions would allow some 50,000 walks).
  LuaHost host(shortBudget());
  const auto [error, walks] = runCounting(host,
                                          "local t, keys = ..., {} for i = 1, 2e4 do keys['k' .. i] = i end\n"
                                          "while true do t.n = t.n + 1 for k in pairs(keys) do break end end");
  EXPECT_EQ(error.rfind("mod.lua:2: script stopped: it ran past the frame's script budget", 0), 0u) << error;
  EXPECT_GE(walks, 1);
  EXPECT_LE(walks, 5);
}

// Library functions that make or read long strings, or push or move many values, loop in C: each
// call is charged its bytes (a step per 16) or values (a step each) before it runs, so a loop of
// them meets the budget after as many calls as their charges allow. Uncharged, their few
// instructions a call let each loop run for minutes (upper over 100 KB: about 2 million calls,
// 200 GB of bytes), stopped by the deadline only. Short calls cost their own instructions.
TEST(Runaway, CWorkOverBytesAndValuesIsCharged) {
  struct Case {
    const char* setup;  // runs once; `big` is 100,000 bytes, `list` 6,000 numbers
    const char* call;   // runs in the loop
    int most;           // the calls the budget allows with their charges
  };
  const Case cases[] = {
      // 100,000 bytes are 6,250 steps: 1,600 calls in 10 million steps.
      {"", "local r = string.rep('ab', 50000)", 1'600},
      {"", "local r = ('x'):rep(100, big)", 16},  // 10 MB a call
      {"", "local r = big:upper()", 1'600},
      {"", "local r = big:lower()", 1'600},
      {"", "local r = big:reverse()", 1'600},
      {"", "local r = big:sub(2)", 1'600},
      {"", "local r = string.format('%s', big)", 1'600},
      {"", "local r = string.format('%s%s%s', big, big, big)", 534},
      {"", "local r = big:byte(1, 6000)", 1'667},                   // 6,000 values
      {"", "local r = string.char(unpack(list, 1, 100))", 50'000},  // 200 values
      {"", "local r = unpack(list)", 1'667},
      {"", "local r = select(2, unpack(list))", 834},
      {"local t = {} for i = 1, 100 do t[i] = big end", "local r = table.concat(t)", 16},
      {"local t = {} for i = 1, 6000 do t[i] = 'ab' end", "local r = table.concat(t, ',')", 1'404},
      {"local pad = string.rep(' ', 100000) .. '1'", "local r = tonumber(pad)", 1'600},
      {"local t = {} for i = 1, 100000 do t[i] = i end", "table.insert(t, 1, 0) table.remove(t, 1)", 50},
      {"local t = {} for i = 1, 100000 do t[i] = i end", "local r = table.maxn(t)", 30},  // interpreted
      {"", "print(big)", 1'600},
      {"", "local r = os.date(big)", 1'600},
  };
  for (const Case& c : cases) {
    LuaLimits limits;  // the game's budget (10 million steps); a deadline far past what it allows
    limits.deadlineNanoseconds = int64_t{60} * 1'000'000'000;
    limits.unchargedNanoseconds = limits.deadlineNanoseconds;
    LuaHost host(limits);
    host.setPrintSink([](std::string_view, std::string_view) {});
    const std::string code = std::string(
                                 "local t0, big, list = ..., string.rep('x', 100000), {}\n"
                                 "for i = 1, 6000 do list[i] = 65 end\n") +
                             c.setup + "\nwhile true do t0.n = t0.n + 1 " + c.call + " end";
    const auto [error, calls] = runCounting(host, code);
    EXPECT_NE(error.find("past the frame's script budget"), std::string::npos) << c.call << "\n" << error;
    EXPECT_LE(calls, c.most) << c.call;
  }
  // Short calls are charged nothing past their instructions: a parser's inner loop stays cheap.
  LuaHost host;
  EXPECT_EQ(runSandboxed(host,
                         "local s, n = string.rep('ab', 5000), 0\n"
                         "for i = 1, #s do if s:sub(i, i) == 'a' and s:byte(i) == 97 then n = n + 1 end end\n"
                         "assert(n == 5000)"),
            "");
  EXPECT_LT(host.frameSteps(), 1'000'000);
}

// C functions that call back into Lua nest C frames a script can pile up without end (gsub calling
// gsub crashed the process): each way of nesting them ends in a Lua error at the script's line, and
// the host goes on.
TEST(Runaway, CallbacksNestedWithoutEndAreAnError) {
  const char* nestings[] = {
      "local function g(s) return (string.gsub(s, '.', g)) end\ng('ab')",
      "local function g(s) return (s:gsub('.', g)) end\ng('ab')",
      "local t = setmetatable({}, {})\ngetmetatable(t).__index = function(_, k) return (string.gsub(k, '.', t)) end\n"
      "string.gsub('ab', '.', t)",
      "local t = {3, 1, 2}\nlocal function less(a, b) table.sort(t, less) return a < b end\ntable.sort(t, less)",
      "local function g(s) local t = {s, s .. 'x'} table.sort(t, function(a, b) g(a) return a < b end) return s end\n"
      "g('ab')",
      "local mt = {}\nmt.__lt = function(a, b) table.sort({setmetatable({}, mt), setmetatable({}, mt)}) return false "
      "end\n"
      "table.sort({setmetatable({}, mt), setmetatable({}, mt)})",
  };
  for (const char* code : nestings) {
    LuaHost host;
    const std::string error = runSandboxed(host, code);
    EXPECT_NE(error.find("callbacks nested more than 150 deep"), std::string::npos) << code << "\n" << error;
    EXPECT_EQ(error.rfind("mod.lua:", 0), 0u) << error;
    EXPECT_EQ(runSandboxed(host, "assert(('ab'):gsub('a', function() return 'x' end) == 'xb')"), "") << code;
  }
  // Nesting that ends is not refused.
  EXPECT_EQ(runSandboxed("local function g(s, n) if n == 0 then return s end\n"
                         "return (s:gsub('a', function(c) return g(c, n - 1) end)) end\nassert(g('aa', 40) == 'aa')"),
            "");
}

TEST(Runaway, UnboundedMemoryIsStopped) {
  LuaLimits limits;
  limits.memoryBytes = size_t{32} << 20;
  LuaHost host(limits);
  const std::string error =
      runSandboxed(host, "local t = {} while true do t[#t + 1] = string.rep('x', 1000) .. #t end");
  // Stopped where it was (its file:line), at the sandboxes' share of the state: the rest is the
  // engine's, so its own scripts still run.
  EXPECT_EQ(error.rfind("mod.lua:1: script stopped: the sandboxes reached their memory limit of 24 MB (of the Lua "
                        "state's 32 MB; the rest is kept for the engine); mod.lua disabled: fix it and save to reload",
                        0),
            0u)
      << error;
  EXPECT_LE(host.memoryUsed(), limits.memoryBytes);
  EXPECT_EQ(runSandboxed(host, "local t = {} for i = 1, 1000 do t[i] = i end"), "");  // the garbage went
}

// A memory stop blames what holds the memory: with several scripts holding some each, the one
// holding the most is stopped and disabled, whichever script's allocation crossed the line.
TEST(Runaway, AMemoryStopBlamesTheScriptThatHoldsTheMost) {
  struct Case {
    std::vector<int> holdsMb;  // what each of mod1.lua, mod2.lua... keeps in its globals
    int crossing;              // the script that then allocates without end (an index into holdsMb)
  };
  const Case cases[] = {{{2, 14, 3}, 0}, {{14, 2, 3}, 2}, {{1, 1, 1, 1, 1, 1, 12}, 3}, {{3, 3}, 1}, {{1, 12}, 1}};
  for (const Case& c : cases) {
    LuaLimits limits;
    limits.memoryBytes = size_t{32} << 20;  // the sandboxes' share: 24 MB
    LuaHost host(limits);
    std::vector<int> ids;
    std::vector<lua::Ref> chunks;
    for (size_t i = 0; i < c.holdsMb.size(); ++i) {
      const std::string name = "@mod" + std::to_string(i + 1) + ".lua";
      ids.push_back(
          host.loadString("if held then local t = {} while true do t[#t + 1] = string.rep('y', 1000) .. #t end end "
                          "held = {} for i = 1, " +
                              std::to_string(c.holdsMb[i] * 1024) + " do held[i] = string.rep('x', 1000) .. '" + name +
                              "' .. i end",  // its own strings (equal ones are one)
                          name, Trust::Sandboxed));
      chunks.emplace_back(host.state(), -1);
      host.beginFrame();
      ASSERT_TRUE(host.callSandboxed(ids.back(), 0, 0));
    }
    size_t most = static_cast<size_t>(c.crossing);  // which, of equals, crossed the line
    for (size_t i = 0; i < c.holdsMb.size(); ++i)
      if (c.holdsMb[i] > c.holdsMb[most]) most = i;
    const std::string blamed = "mod" + std::to_string(most + 1) + ".lua";
    const std::string crossing = "mod" + std::to_string(c.crossing + 1) + ".lua";
    std::string error;
    host.beginFrame();
    try {
      chunks[static_cast<size_t>(c.crossing)].push();
      host.callSandboxed(ids[static_cast<size_t>(c.crossing)], 0, 0);
    } catch (const ScriptError& e) {
      error = e.what();
    }
    const std::string what = "stopped: the sandboxes reached their memory limit of 24 MB";
    if (static_cast<size_t>(c.crossing) == most) {
      EXPECT_EQ(error.rfind(blamed + ":1: script " + what, 0), 0u) << error;
    } else {
      EXPECT_EQ(error.rfind(blamed + ": script " + what, 0), 0u) << error;
      EXPECT_NE(error.find(" MB, the most of any script (" + crossing + ":1 was running, holding "), std::string::npos)
          << error;
    }
    EXPECT_NE(error.find(blamed + " disabled"), std::string::npos) << error;
    // The blamed one is off and its memory is free: what is left is what the others hold.
    host.beginFrame();
    chunks[most].push();
    EXPECT_FALSE(host.callSandboxed(ids[most], 0, 0));
    int others = 0;
    for (size_t i = 0; i < c.holdsMb.size(); ++i)
      if (i != most) others += c.holdsMb[i];
    EXPECT_LE(host.memoryUsed(), static_cast<size_t>(others + 4) << 20) << blamed;
  }
}

TEST(Runaway, OneHugeStringIsStopped) {
  LuaLimits limits;
  limits.memoryBytes = size_t{32} << 20;
  LuaHost host(limits);
  const std::string error = runSandboxed(host, "local s = string.rep('x', 1e9)");
  // Refused at once (more than the whole state): no instruction ran after it, so the sandbox, not
  // a line, is named.
  EXPECT_EQ(error.rfind("mod.lua: script stopped: the sandboxes reached their memory limit of 24 MB", 0), 0u) << error;
}

TEST(Runaway, EndlessRecursionIsAnError) {
  const std::string error = runSandboxed("local function f(n) return 1 + f(n + 1) end f(1)");
  EXPECT_NE(error.find("stack overflow"), std::string::npos) << error;
}

// --- errors ---

TEST(Errors, CarryFileLineAndTraceback) {
  LuaHost host;
  try {
    host.loadString("local function inner()\n  error('boom')\nend\nlocal function outer() inner() end\nouter()\n",
                    "@levels/x.lua", Trust::Sandboxed);
    host.call(0, 0);
    FAIL();
  } catch (const ScriptError& e) {
    EXPECT_STREQ(e.what(), "levels/x.lua:2: boom");
    EXPECT_NE(e.traceback().find("levels/x.lua:4: in function 'outer'"), std::string::npos) << e.traceback();
    EXPECT_EQ(e.traceback().rfind("stack traceback:", 0), 0u) << e.traceback();
  }
}

TEST(Errors, SyntaxErrorsCarryFileLine) {
  LuaHost host;
  try {
    host.loadString("local x = \nif", "@levels/y.lua", Trust::Sandboxed);
    FAIL();
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("levels/y.lua:2:", 0), 0u) << e.what();
  }
}

TEST(Errors, NonStringErrorObjectsAreReported) {
  EXPECT_NE(runSandboxed("error({})").find("error object is a table value"), std::string::npos);
  // No metamethod runs in the message handler (it may run inside the budget hook, where nothing
  // could stop a looping __tostring).
  EXPECT_NE(runSandboxed("error(setmetatable({}, {__tostring = function() while true do end end}))")
                .find("error object is a table value"),
            std::string::npos);
}

TEST(Errors, TheStackIsLeftAsItWas) {
  LuaHost host;
  const int top = lua_gettop(host.state());
  for (int i = 0; i < 100; ++i) runSandboxed(host, "error('x')");
  EXPECT_EQ(lua_gettop(host.state()), top);
}

// --- read-only views ---

// A read-only view names the key it refused by the sandbox's tostring, never by an address
// (re-audit N5: "tried to set table: 0x55..." gave a sandbox a number that differs per process).
TEST(ReadOnlyViews, NameARefusedKeyWithoutAnAddress) {
  EXPECT_EQ(runSandboxed(
                "for _, key in ipairs { {}, print, coroutine.create(print) } do\n"
                "  local ok, e = pcall(function() platon[key] = 1 end)\n"
                "  assert(not ok and not e:find('0x'), e)\n"
                "  assert(e:find('^mod.lua:2: platon is read%-only %(tried to set ' .. type(key) .. ': #%d+%)$'), e)\n"
                "end"),
            "");
}

// --- pairs and next: the documented order, and what it costs ---

// Random tables (an array part with holes after it, other integers, fractions, strings with
// shared prefixes, NULs and high bytes, false and true): pairs, a walk with next and next(t) give
// the order docs/scripting.md states, computed here from the keys put in, also while a walk
// removes keys and after keys were added between walks.
TEST(PairsAndNext, WalkTheDocumentedOrderOverRandomTables) {
  const char* check = R"lua(
    local state = 12345
    local function rand(n)
      state = bit.bxor(state, bit.lshift(state, 13))
      state = bit.bxor(state, bit.rshift(state, 17))
      state = bit.bxor(state, bit.lshift(state, 5))
      return state % n + 1
    end
    local function randomKey()
      local r = rand(10)
      if r <= 3 then return rand(40) end
      if r == 4 then return rand(2000) - 1000 end
      if r == 5 then return (rand(200) - 100) / 8 end
      if r == 6 then return rand(2) == 1 end
      local parts = {}
      for i = 1, rand(4) - 1 do parts[i] = ({ "a", "b", "ab", "\0", "\255", "A", "1" })[rand(7)] end
      return table.concat(parts)
    end
    local function bytesBefore(a, b)
      for i = 1, math.min(#a, #b) do
        local x, y = a:byte(i), b:byte(i)
        if x ~= y then return x < y end
      end
      return #a < #b
    end
    -- The documented order of `keys` (the keys t holds).
    local function expected(t, keys)
      local n = 0
      while rawget(t, n + 1) ~= nil do n = n + 1 end
      local numbers, strings, order = {}, {}, {}
      local hasFalse, hasTrue = false, false
      for _, k in ipairs(keys) do
        if type(k) == "number" then
          if not (k >= 1 and k <= n and k == math.floor(k)) then numbers[#numbers + 1] = k end
        elseif type(k) == "string" then strings[#strings + 1] = k
        elseif k then hasTrue = true else hasFalse = true end
      end
      table.sort(numbers)
      table.sort(strings, bytesBefore)
      for i = 1, n do order[#order + 1] = i end
      for _, k in ipairs(numbers) do order[#order + 1] = k end
      for _, k in ipairs(strings) do order[#order + 1] = k end
      if hasFalse then order[#order + 1] = false end
      if hasTrue then order[#order + 1] = true end
      return order
    end
    local function shown(list)
      local out = {}
      for i, k in ipairs(list) do out[i] = type(k) == "string" and string.format("%q", k) or tostring(k) end
      return table.concat(out, " ")
    end
    local function keysOf(t, universe)
      local keys = {}
      for _, k in ipairs(universe) do if rawget(t, k) ~= nil then keys[#keys + 1] = k end end
      return keys
    end
    local problems = {}
    local function expect(what, got, want)
      if shown(got) ~= shown(want) and #problems < 5 then
        problems[#problems + 1] = what .. ": got " .. shown(got) .. "; want " .. shown(want)
      end
    end
    for round = 1, 300 do
      local t, universe, known = {}, {}, {}
      local function put(k)
        t[k] = round
        if known[k] == nil then
          known[k] = true
          universe[#universe + 1] = k
        end
      end
      for _ = 1, rand(60) - 1 do put(randomKey()) end
      local want = expected(t, keysOf(t, universe))
      local viaPairs, viaNext = {}, {}
      for k in pairs(t) do viaPairs[#viaPairs + 1] = k end
      local k = next(t)
      while k ~= nil do
        viaNext[#viaNext + 1] = k
        k = next(t, k)
      end
      expect("pairs, round " .. round, viaPairs, want)
      expect("next, round " .. round, viaNext, want)
      -- A walk that removes keys: the current one, or one still ahead (never visited then).
      local removed, visited, seen = {}, {}, {}
      k = next(t)
      while k ~= nil do
        visited[#visited + 1] = k
        seen[k] = true
        if rand(3) == 1 then t[k] = nil end
        if rand(4) == 1 then
          local ahead = want[rand(#want)]
          if t[ahead] ~= nil and not seen[ahead] then
            t[ahead] = nil
            removed[ahead] = true
          end
        end
        k = next(t, k)
      end
      local wantVisited = {}
      for _, key in ipairs(want) do if not removed[key] then wantVisited[#wantVisited + 1] = key end end
      expect("removing walk, round " .. round, visited, wantVisited)
      -- Keys added after a walk are seen by the next one.
      for _ = 1, rand(8) do put(randomKey()) end
      want = expected(t, keysOf(t, universe))
      viaNext = {}
      k = next(t)
      while k ~= nil do
        viaNext[#viaNext + 1] = k
        k = next(t, k)
      end
      expect("next after adding, round " .. round, viaNext, want)
      if (next(t)) ~= want[1] then expect("next(t), round " .. round, { (next(t)) }, { want[1] }) end
    end
    assert(#problems == 0, table.concat(problems, "\n"))
  )lua";
  EXPECT_EQ(runSandboxed(check), "");
}

// next(t) is one pass over the keys, not a sort (re-audit N6: each call on 100,000 keys sorted
// them all), and a walk with next costs one sort: a clear loop over 100,000 keys fits in the
// frame's budget (the keys' ordering is charged as work; a sort per call would cost about
// 1.8 million steps, so twelve calls would spend the whole budget).
TEST(PairsAndNext, EmptinessChecksAndClearLoopsFitTheFramesBudget) {
  LuaLimits limits;  // the frame's budget of steps; a deadline no machine meets, so the steps decide
  limits.deadlineNanoseconds = int64_t{3600} * 1'000'000'000;
  limits.unchargedNanoseconds = limits.deadlineNanoseconds;
  LuaHost host(limits);
  EXPECT_EQ(runSandboxed(host,
                         "local t = {} for i = 1, 1e5 do t['key' .. i] = i end\n"
                         "for i = 1, 20 do assert(next(t) == 'key1') end"),
            "");
  EXPECT_EQ(runSandboxed(host,
                         "local t = {} for i = 1, 1e5 do t['key' .. i] = i end\n"
                         "local k = next(t) while k ~= nil do t[k] = nil k = next(t, k) end\n"
                         "assert(next(t) == nil)"),
            "");
  EXPECT_EQ(runSandboxed(host,
                         "local t = {} for i = 1, 1e5 do t[i / 4] = i end\n"
                         "for k in next, t do t[k] = nil end assert(next(t) == nil)"),
            "");
  EXPECT_EQ(
      runSandboxed(host,
                   "local t = {} for i = 1, 1e5 do t['key' .. i] = i end\n"
                   "local n = 0 for k, v in pairs(t) do n = n + 1 t[k] = nil end assert(n == 1e5 and next(t) == nil)"),
      "");
}

// table.insert, remove and sort write raw, past a view's metatable: into the table every sandbox
// is shown (platon[1] was then "x" for every sandbox of the state). They refuse a view.
TEST(ReadOnlyViews, TableFunctionsCannotWriteIntoAView) {
  LuaHost host;
  const char* attempts[][2] = {
      {"table.insert(platon, 'x')", "mod.lua:1: platon is read-only (tried to insert in it)"},
      {"table.insert(platon, 1, 'x')", "mod.lua:1: platon is read-only (tried to insert in it)"},
      {"table.remove(platon)", "mod.lua:1: platon is read-only (tried to remove in it)"},
      {"table.sort(platon)", "mod.lua:1: platon is read-only (tried to sort in it)"},
  };
  for (const auto& [code, message] : attempts) {
    const std::string error = runSandboxed(host, code);
    EXPECT_EQ(error.rfind(message, 0), 0u) << code << "\n" << error;
  }
  EXPECT_EQ(runSandboxed(host, "assert(platon[1] == nil and rawget(platon, 1) == nil)"), "");
  // On other tables they are LuaJIT's, errors at the caller's line included.
  EXPECT_EQ(runSandboxed(host,
                         "local t = {} table.insert(t, 'a') table.insert(t, 1, 'b') table.sort(t)\n"
                         "assert(table.remove(t) == 'b' and #t == 1)"),
            "");
  EXPECT_EQ(runSandboxed(host, "\ntable.insert(nil, 1)")
                .rfind("mod.lua:2: bad argument #1 to 'insert' (table expected, got nil)", 0),
            0u);
}

// table.foreach walked LuaJIT's order, which changes from one process to the next (string hashes
// are seeded at random, other keys hash by address): it walks pairs' order, and refuses what
// pairs refuses.
TEST(PairsAndNext, TableForeachWalksTheFixedOrder) {
  EXPECT_EQ(runSandboxed("local t = {} for i = 1, 12 do t['k' .. i] = i end t[2.5] = 0 t[true] = 0 t[1] = 0\n"
                         "local a, b = {}, {}\n"
                         "table.foreach(t, function(k) a[#a + 1] = tostring(k) end)\n"
                         "for k in pairs(t) do b[#b + 1] = tostring(k) end\n"
                         "assert(table.concat(a, ' ') == table.concat(b, ' '), table.concat(a, ' '))\n"
                         "assert(table.foreach(t, function(k, v) if k == 'k3' then return v end end) == 3)"),
            "");
  EXPECT_EQ(runSandboxed("\ntable.foreach({ [{}] = 1 }, print)")
                .rfind("mod.lua:2: pairs over table keys has no fixed order", 0),
            0u);
}

// --- Lua as modders know it: the sandbox against stock LuaJIT ---

// What `expression` gives under pcall, as text both states write the same way (a message without
// its file:line: the chunks are named differently).
const char* kShow = R"(
local function show(ok, ...)
  local parts = { ok and 'ok' or 'err' }
  for i = 1, select('#', ...) do
    local v = select(i, ...)
    local t = type(v)
    if t == 'string' then v = (string.gsub(v, '^[^:]*:%d+: ', '')) end
    parts[#parts + 1] = t .. '=' .. (t == 'number' and string.format('%.17g', v) or t == 'string' and v
                                     or t == 'boolean' and (v and 'true' or 'false') or '')
  end
  return table.concat(parts, ' ')
end
)";

std::string stockResult(const std::string& expression) {
  lua_State* L = luaL_newstate();
  luaL_openlibs(L);
  const std::string code = std::string(kShow) + "return show(pcall(function() return " + expression + " end))";
  std::string out = luaL_loadstring(L, code.c_str()) != 0 || lua_pcall(L, 0, 1, 0) != 0
                        ? std::string("(harness) ") + lua_tostring(L, -1)
                        : lua_tostring(L, -1);
  lua_close(L);
  return out;
}

std::string sandboxResult(const std::string& expression) {
  const std::string error =
      runSandboxed(std::string(kShow) + "error('RESULT:' .. show(pcall(function() return " + expression + " end)), 0)");
  const size_t at = error.find("RESULT:");
  return at == std::string::npos ? "(harness) " + error : error.substr(at + 7);
}

// Each expression gives the same values, and the same errors, in the sandbox as in a stock LuaJIT
// state (what differs on purpose is in SandboxRefuses and docs/scripting.md, "The sandbox").
TEST(StockLua, TheSandboxGivesWhatStockLuaJITGives) {
  const char* expressions[] = {
      // base
      "(tostring())",
      "tostring(nil)",
      "tostring(true)",
      "tostring(1e100)",
      "tostring(-0.0)",
      "tostring(2^53)",
      "tonumber('0x10')",
      "tonumber('10', 36)",
      "tonumber(' 1e2 ')",
      "tonumber('z', 37)",
      "tonumber('')",
      "select('#', nil, nil)",
      "select(-1, 1, 2)",
      "select(0)",
      "unpack({1, 2, 3}, 2)",
      "unpack({}, 1, 3)",
      "type(print)",
      "rawequal('a', 'a')",
      "next({})",
      "pcall(error)",
      "pcall(error, nil)",
      "pcall(error, 'x', 0)",
      "xpcall(function() error('x') end, function(m) return 'handled' end)",
      "xpcall(function() error('x') end, function(m) error('again') end)",
      "xpcall(function() return 1, 2 end, print)",
      "assert(false)",
      "assert(nil, 'why')",
      "assert(1, 2, 3)",
      "error()",
      "setmetatable({}, nil) ~= nil",
      // string
      "string.format('%5.2f', 1/3)",
      "string.format('%q', 'a\\0b\\n')",
      "string.format('%d', 3.0)",
      "string.format('%s', 1.5)",
      "string.format('%x', 255)",
      "string.format('%5s|%-5s', 'a', 'b')",
      "string.format('%c%c', 72, 105)",
      "string.format('%g', 1e20)",
      "string.format('%i', -7)",
      "string.format('%d', 'x')",
      "string.format('%')",
      "string.rep('ab', 3)",
      "string.rep('x', 0)",
      "string.rep('x', -1)",
      "string.byte('abc', -1)",
      "string.byte('abc', 1, 3)",
      "string.sub('hello', -3, -2)",
      "string.sub('hello', 0)",
      "string.char(104, 105)",
      "string.char(256)",
      "string.upper('aBc')",
      "string.reverse('abc')",
      "string.len('\\0\\0')",
      "('x'):rep(3)",
      // patterns
      "string.find('a.b', '.', 1, true)",
      "string.find('abc', 'b', -1)",
      "string.find('abc', '(b)(c)')",
      "string.match('key = value', '(%w+)%s*=%s*(%w+)')",
      "string.match('  x', '^%s*()')",
      "string.gsub('abc', '', '-')",
      "string.gsub('hello world', '(o)', '[%1]', 1)",
      "string.gsub('abc', '%w', '%0%0')",
      "string.gsub('abc', '%w', {a = 1, b = true})",
      "string.gsub('abc', '%w', function(c) if c == 'b' then return nil end return c:upper() end)",
      "string.gsub('abc', '(', '')",
      "string.gsub('abc', '%', '')",
      "string.find('a', '[a')",
      "string.match('f(a(b)c)', '%b()')",
      "string.match('THE (quick) fox', '%f[%a]%a+')",
      "string.gsub('x', 'x', '%2')",
      "string.find('', '')",
      "string.find('abc', '', 10)",
      "select('#', string.gsub('a b c', '%s', ''))",
      // table
      "table.concat({1, 2, 3}, ',', 2, 3)",
      "table.concat({1, {}, 3})",
      "table.concat({}, 'x')",
      "#table.concat({1, 2}, ', ')",
      "select('#', table.remove({}))",
      "table.remove({1, 2, 3}, 1)",
      "(function() local t = {3, 1, 2} table.sort(t) return t[1], t[2], t[3] end)()",
      "(function() local t = {3, 1, 2} table.sort(t, function(a, b) return a > b end) return t[1], t[3] end)()",
      "table.sort({1, 'x'})",
      "(function() local t = {} table.insert(t, 'a') table.insert(t, 1, 'b') return t[1], #t end)()",
      "table.insert({}, 1, 2, 3)",
      "table.maxn({1, 2, [10] = 3})",
      "#{1, 2, nil, 4}",
      // math
      "math.floor(-0.5)",
      "math.ceil(-0.5)",
      "math.fmod(7, -3)",
      "math.fmod(-7, 3)",
      "math.huge",
      "-math.huge",
      "math.max(1, 5, 3)",
      "math.min()",
      "math.abs(-2^63)",
      "math.sqrt(2)",
      "math.pi",
      "math.modf(-3.7)",
      "math.frexp(8)",
      "math.ldexp(0.5, 4)",
      "math.log10(1000)",
      "math.exp(0)",
      "math.floor(2^53 + 1)",
      "type(math.random(0))",
      "type(math.random(3, 1))",
      "type(math.random())",
      "math.random(1, 2, 3)",
      "7 % -3",
      "-7 % 3",
      "2^0.5",
      "1/0 > 0",
      "0/0 ~= 0/0",
      "'10' + 5",
      "'0x10' * 1",
      "'a' + 1",
      "#'abc'",
      "10 == '10'",
      "({} == {})",
      "'a' < 'b'",
      "'a' < 1",
      "1 < 'x'",
      // bit, coroutine
      "bit.band(6, 3)",
      "bit.bor(1, 2, 4)",
      "bit.lshift(1, 40)",
      "bit.tohex(255)",
      "bit.tobit(2^32 + 1)",
      "coroutine.resume(coroutine.create(function(a) return a * 2 end), 21)",
      "coroutine.resume(coroutine.create(function() error('in co') end))",
      "coroutine.status(coroutine.create(print))",
      "coroutine.wrap(function() coroutine.yield(1, 2) end)()",
      "coroutine.running()",
      "coroutine.yield()",
      "select('#', coroutine.resume(coroutine.create(function() end)))",
  };
  for (const char* e : expressions) EXPECT_EQ(sandboxResult(e), stockResult(e)) << e;
  // What differs on purpose, as docs/scripting.md says (and nothing else in the list above).
  const std::pair<const char*, const char*> documented[] = {
      {"getmetatable('x')", "ok string=locked"},
      {"tostring({}):match('^table: #%d+$') ~= nil", "ok boolean=true"},
      {"string.format('%p', {})", "err string=bad argument #1 to 'format' (%p shows an address"},
      {"collectgarbage('count')", "err string=collectgarbage(\"count\") is not for sandboxes"},
      {"next({}, 'nokey')", "err string=invalid key to 'next'"},
      // The sandbox's resume charges a caught error: its argument errors name it even in a tail call.
      {"coroutine.resume(coroutine.running())", "err string=bad argument #1 to 'resume' (coroutine expected)"},
  };
  for (const auto& [e, result] : documented)
    EXPECT_EQ(sandboxResult(e).substr(0, std::string(result).size()), result) << e;
}

// --- Messages a modder can trust ---

// The place in an error is the sandbox's real line, or none: a message that only looks like
// "file:line:" is never taken for one, and a long message keeps its traceback.
TEST(Messages, ThePlaceIsRealAndTheTracebackSurvives) {
  const std::pair<std::string, std::string> cases[] = {
      {"error('the time is 12:30:45', 0)", "mod.lua:1: the time is 12:30:45"},
      {"error('fake.lua:99: x', 0)", "mod.lua:1: fake.lua:99: x"},
      {"error('mod.lua:99: x', 0)", "mod.lua:1: mod.lua:99: x"},
      {"error('x')", "mod.lua:1: x"},
      {"\nlocal function f() error('deep', 2) end\nf()", "mod.lua:3: deep"},
      {"error({})", "mod.lua:1: (error object is a table value)"},
      {"local t = setmetatable({}, { __index = function() error('in a metamethod') end }) return t.x",
       "mod.lua:1: in a metamethod"},
      // A tail call leaves no frame of the caller: the sandbox's name, once; else the calling line.
      {"return string.rep()", "mod.lua: bad argument #1 to '?' (string expected, got no value)"},
      {"local function f() return string.rep() end\nf()", "mod.lua:2: bad argument #1 to 'f'"},
      {"local function f() error('x', 2) end\nlocal function g() f() end\ng()", "mod.lua:2: x"},
  };
  for (const auto& [code, message] : cases) {
    const std::string error = runSandboxed(code);
    EXPECT_EQ(error.substr(0, message.size()), message) << code << "\n" << error;
  }
  LuaHost host;
  try {
    const int id =
        host.loadString("local function f() error(string.rep('x', 3000000)) end\nf()\n", "@mod.lua", Trust::Sandboxed);
    host.beginFrame();
    host.callSandboxed(id, 0, 0);
    ADD_FAILURE() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("mod.lua:1: xxx", 0), 0u);
    EXPECT_LT(std::string(e.what()).size(), size_t{100000}) << "a 3 MB message is cut";
    EXPECT_NE(e.traceback().find("mod.lua:2"), std::string::npos) << e.traceback();
  }
}

// What a sandbox prints is capped a frame (503 MB of output in 60 frames), and charged.
// A caught error costs microseconds of unwinding and only a few instructions: a loop of them ran
// into the deadline (2 s), not the step budget. Each way of catching one is charged
// (kErrorSteps), so every such loop meets the budget, in every process at the same point.
TEST(CaughtErrors, ALoopOfCaughtErrorsMeetsTheStepBudgetNotTheDeadline) {
  struct Case {
    const char* setup;
    const char* body;  // catches `errors` errors
    int errors;
  };
  const Case loops[] = {
      {"", "pcall(error, 'x')", 1},
      {"", "pcall(error)", 1},
      {"", "pcall(string.rep)", 1},                        // a C function's argument error
      {"", "pcall(function() local x = nil + 1 end)", 1},  // the VM's own error
      {"", "xpcall(error, function(m) return m end)", 1},
      {"", "coroutine.resume(coroutine.create(error))", 1},
      {"", "pcall(coroutine.wrap(error))", 2},
      {"local t = setmetatable({}, { __index = error })", "pcall(function() return t.x end)", 1},
      {"", "pcall(pcall, error) pcall(select, -1)", 2},
      // One error unwound through 40 wrapped coroutines: each level is charged.
      {"local function f(n) if n < 1 then error() end return coroutine.wrap(f)(n-1) end", "pcall(f, 40)", 41},
  };
  for (const Case& c : loops) {
    // Counted, not timed: the budget holds 10 million / 3,000 = 3,333 caught errors, where
    // uncharged it allowed over a million of them (1.5-12 us each: seconds, into the deadline). The
    // deadline is far past what the charged loop takes on any machine.
    LuaLimits limits;
    limits.deadlineNanoseconds = int64_t{60} * 1'000'000'000;
    limits.unchargedNanoseconds = limits.deadlineNanoseconds;
    LuaHost host(limits);
    const auto [error, rounds] = runCounting(
        host, std::string("local t0 = ...\n") + c.setup + "\nwhile true do t0.n = t0.n + 1 " + c.body + " end");
    EXPECT_NE(error.find("past the frame's script budget"), std::string::npos) << c.body << "\n" << error;
    EXPECT_LE(rounds * c.errors, 3'334) << c.body;
  }
}

// What stock Lua 5.1 nests runs: its test suite's pm.lua reverses a string by gsub inside gsub, one
// level a character (60 there); 149 levels run, and the 151st is refused, not a crash.
TEST(Runaway, Lua51sDeepButLegalNestingRuns) {
  const std::string rev =
      "local function rev(s) return (string.gsub(s, '(.)(.+)', function(c, s1) return rev(s1) .. c end)) end\n";
  EXPECT_EQ(runSandboxed(rev + "local x = string.rep('012345', 10)\nassert(rev(rev(x)) == x)"), "");
  EXPECT_EQ(runSandboxed(rev + "local x = string.rep('a', 148) .. 'b'\nassert(rev(x) == 'b' .. string.rep('a', 148))"),
            "");
  const std::string refused = runSandboxed(rev + "rev(string.rep('a', 160))");
  EXPECT_NE(refused.find("callbacks nested more than 150 deep"), std::string::npos) << refused;
}

// Coroutines resumed inside coroutines nest C frames in LuaJIT (deep nesting overflows the C
// stack): they nest at most 150 deep, an error at the script's line, by wrap or by resume.
TEST(CaughtErrors, CoroutinesNestAtMost150Deep) {
  EXPECT_EQ(runSandboxed("local function f() return coroutine.wrap(f)() end\nf()").substr(0, 60),
            "mod.lua:2: coroutines nested more than 150 deep (a coroutine");
  // resume catches the error where it is raised, and each level goes on: it ends, nothing crashed.
  EXPECT_EQ(runSandboxed("local n = 0\nlocal function f() n = n + 1 coroutine.resume(coroutine.create(f)) end\n"
                         "f()\nassert(n == 151, n)"),
            "");
  EXPECT_EQ(runSandboxed("local w = coroutine.wrap(function() end) w()\nassert(select(2, pcall(w)) == "
                         "'cannot resume dead coroutine')\nassert(select('#', coroutine.wrap(function(...) return ... "
                         "end)(1, nil, 3, nil)) == 4)"),
            "");
}

// error(m, level) names the line stock Lua names: the sandbox's counted pcall adds a frame of its
// own that error(m, 3) named ("platon/sandbox:NNN:") before.
TEST(Messages, ErrorLevelsCountTheScriptsFramesAsStockLuaDoes) {
  EXPECT_EQ(runSandboxed("local function f() error('deep', 3) end\nlocal ok, m = pcall(f)\n"
                         "assert(m == 'mod.lua:2: deep', m)"),
            "");
  EXPECT_EQ(runSandboxed("local function f() error('two', 2) end\nlocal ok, m = pcall(f)\n"
                         "assert(m == 'two', m)"),  // level 2 is pcall, a C function: no place
            "");
  EXPECT_EQ(runSandboxed("local ok, m = pcall(error, 'zero', 0)\nassert(m == 'zero', m)"), "");
  EXPECT_EQ(runSandboxed("local ok, m = pcall(function() error('one') end)\nassert(m == 'mod.lua:1: one', m)"), "");
  EXPECT_EQ(runSandboxed("error('x', 'a')").substr(0, 46), "mod.lua:1: bad argument #2 to 'error' (number ");
}

TEST(Messages, PrintIsCappedAFrame) {
  LuaHost host;
  std::string printed;
  size_t lines = 0;
  host.setPrintSink([&](std::string_view, std::string_view text) {
    printed += text;
    ++lines;
  });
  EXPECT_EQ(runSandboxed(host, "for i = 1, 2000 do print(string.rep('x', 1000)) end"), "");
  EXPECT_LT(printed.size(), size_t{20000});
  EXPECT_NE(printed.find("more than 16 KB printed this frame"), std::string::npos);
  printed.clear();
  EXPECT_EQ(runSandboxed(host, "print('a\27[2Jb')"), "");  // a new frame: printing again
  EXPECT_EQ(printed.find('\x1b'), std::string::npos) << "no terminal escape reaches the console";
}

// Weak tables: which entries the collector clears, and when, depends on everything the Lua state
// allocates, so no sandbox table may be weak, by any route to a metatable with __mode.
class WeakTableRoutes : public testing::TestWithParam<const char*> {};

TEST_P(WeakTableRoutes, AreEachRefusedAtTheScriptsLine) {
  const std::string error = runSandboxed(GetParam());
  EXPECT_NE(error.find("weak tables are not for sandboxes"), std::string::npos) << GetParam() << "\n" << error;
  EXPECT_EQ(error.rfind("mod.lua:", 0), 0u) << error;
}

INSTANTIATE_TEST_SUITE_P(
    Each, WeakTableRoutes,
    testing::Values(
        "setmetatable({}, { __mode = 'k' })", "setmetatable({}, { __mode = 'v' })",
        "setmetatable({}, { __mode = 'kv' })", "setmetatable({}, { __mode = 1 })",
        // A placeholder first, the mode later (an existing key is written raw).
        "local mt = { __mode = false } setmetatable({}, mt)",
        // The mode after the metatable is set, by name, by a computed name, inside a coroutine.
        "local mt = {} setmetatable({}, mt) mt.__mode = 'k'",
        "local mt = {} setmetatable({}, mt) mt['__' .. 'mode'] = 'v'",
        "local mt = {} setmetatable({}, mt) coroutine.wrap(function() mt.__mode = 'k' end)()",
        "local mt = {} setmetatable({}, mt) pcall(function() mt.__mode = 'k' end) mt.__mode = 'k'",
        // Taking the seal off: the metatable's own metatable removed, replaced, given a __newindex.
        "local mt = {} setmetatable({}, mt) setmetatable(mt, nil) mt.__mode = 'k'",
        "local mt = {} setmetatable({}, mt) setmetatable(mt, {}) mt.__mode = 'k'",
        "local mt = {} setmetatable({}, mt) setmetatable(mt, { __newindex = function(t, k, v) t[k] = v end }) "
        "mt.__mode = 'k'",
        "local mt = {} setmetatable({}, mt) local other = {} setmetatable(mt, { __newindex = other }) "
        "mt.__mode = 'k'",
        // A class with a base: its own metatable changed after it was set.
        "local Base = {} local U = { __index = Base } local D = setmetatable({}, U) D.__index = D "
        "setmetatable({}, D) U.__newindex = nil D.__mode = 'k'",
        "local U = {} local D = setmetatable({}, U) setmetatable({}, D) "
        "U.__newindex = function(t, k, v) t[k] = v end D.__mode = 'k'",
        "local U = {} local D = setmetatable({}, U) setmetatable({}, D) setmetatable(U, nil) D.__mode = 'k'",
        // The metatable made one after the table it seals is used, in either order.
        "local D = {} setmetatable({}, D) local U = {} setmetatable(D, U) D.__mode = 'k'",
        "local D = {} local U = {} setmetatable(D, U) setmetatable({}, D) D.__mode = 'k'",
        // Reaching what seals it: getmetatable shows nothing of it.
        "local mt = {} setmetatable({}, mt) local s = getmetatable(mt) assert(s == nil) "
        "setmetatable({}, { __mode = 'k' })"));

TEST(WeakTables, WhatAScriptWroteStaysForTheCollector) {
  // Had any route made t weak, a full collection between the two calls would empty it.
  LuaHost host;
  const int id = host.loadString(
      "if not t then mt = {} t = setmetatable({}, mt) "
      "pcall(function() mt.__mode = 'v' end) pcall(function() mt.__mode = 'kv' end) "
      "pcall(setmetatable, mt, nil) pcall(function() mt.__mode = 'v' end) "
      "for i = 1, 100 do t['k' .. i] = {} end return end "
      "local n = 0 for _ in pairs(t) do n = n + 1 end assert(n == 100, n) "
      "assert(next(mt) == nil)",
      "@mod.lua", Trust::Sandboxed);
  const lua::Ref chunk(host.state(), -1);
  lua_pop(host.state(), 1);
  for (int call = 0; call < 2; ++call) {  // the second call counts (an error there throws)
    host.beginFrame();
    chunk.push();
    ASSERT_TRUE(host.callSandboxed(id, 0, 0));
    lua_gc(host.state(), LUA_GCCOLLECT, 0);
    lua_gc(host.state(), LUA_GCCOLLECT, 0);
  }
}

TEST(WeakTables, MetatablesStillWorkAsInStockLua) {
  EXPECT_EQ(
      runSandboxed(
          // A class: methods added after instances, a call metamethod on the class.
          "local Class = {} Class.__index = Class "
          "setmetatable(Class, { __call = function(cls, x) return setmetatable({ x = x }, cls) end }) "
          "local a = Class(1) function Class:get() return self.x end assert(a:get() == 1) "
          "assert(getmetatable(a) == Class) assert(type(getmetatable(Class).__call) == 'function') "
          // Inheritance two deep, each metatable used before and after it got its own.
          "local Base = {} Base.__index = Base function Base:hello() return 'base' end "
          "local Derived = setmetatable({}, { __index = Base }) Derived.__index = Derived "
          "local d = setmetatable({}, Derived) assert(d:hello() == 'base') "
          "function Derived:hello() return 'derived' end assert(d:hello() == 'derived') "
          "local Leaf = setmetatable({}, Derived) setmetatable({}, Leaf) assert(Leaf:hello() == 'derived') "
          // __newindex of a metatable's own metatable, a function and a table.
          "local seen = {} local M = setmetatable({}, { __newindex = function(t, k, v) seen[#seen + 1] = k end }) "
          "setmetatable({}, M) M.x = 1 assert(seen[1] == 'x' and rawget(M, 'x') == nil) "
          "local sink = {} local N = setmetatable({}, { __newindex = sink }) setmetatable({}, N) "
          "N.y = 2 assert(sink.y == 2 and rawget(N, 'y') == nil) "
          // A metatable's own keys, as ever; a protected metatable stays protected.
          "local mt = {} setmetatable({}, mt) mt.count = 1 mt.count = mt.count + 1 assert(mt.count == 2) "
          "assert(getmetatable(mt) == nil) "
          "local P = setmetatable({}, { __metatable = 'mine' }) setmetatable({}, P) "
          "assert(getmetatable(P) == 'mine') assert(not pcall(setmetatable, P, {})) "
          "local q = setmetatable({}, { __metatable = 'locked' }) assert(not pcall(setmetatable, q, nil)) "
          // setmetatable's own argument errors, as stock gives them.
          "assert(select(2, pcall(setmetatable, 1, {})):find('table expected, got number')) "
          "assert(select(2, pcall(setmetatable, {}, 1)):find('nil or table expected')) "
          "assert(select(2, pcall(setmetatable, {})):find('nil or table expected'))"),
      "");
}

}  // namespace
}  // namespace platon::script
