// libFuzzer target: Lua programs made of the sandbox's own vocabulary, run as a downloaded level's
// script under the engine's limits. The input's bytes choose statements: calls of every function
// the sandbox exposes (found by asking a sandbox for its globals, so a new one is fuzzed at once)
// and of the level's game, world and draw API, with extreme values (huge and odd numbers, long
// strings, patterns, tables with metamethods that call back), inside loops, sort comparators,
// gsub callbacks, coroutines and recursion. Each program runs as a level (build, then ticks) in
// a scene of its own, twice. Invariants:
//  - the engine survives it (no crash, no sanitizer report);
//  - every stop is the step budget's, not the clock's: a program that runs past the deadline (or
//    has a call skipped because the frame's deadline passed) did work the budget does not charge
//    (checked again once, and only runs that had half the deadline of processor time, so a
//    loaded machine is no finding);
//  - a frame never takes much more processor time than the deadline (libFuzzer's -timeout
//    catches a hang);
//  - memory stays under the Lua state's limit (the allocator's; libFuzzer's -rss_limit_mb);
//  - the two runs give the same errors and the same world state hash, frame by frame (up to a stop
//    by the memory limit, which may come at another instruction).
// Build and run: see CMakeLists.txt. PLATON_FUZZ_PRINT=1 prints each program.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_bug.h"
#include "lua_host.h"
#include "platon/core/input.h"
#include "platon/core/live_scene.h"
#include "platon/script/script_system.h"

using namespace platon;

namespace {

constexpr int kFrames = 3;  // build, then ticks
// The frame's budget of steps and its deadline (the manifest's limits): 1 us a step, five times
// the game's ratio (10 million steps against 2 s), for this build's instrumented allocator (a
// loop that allocates tables costs some 50 ns a step in a release build, 5 times that here).
// Work the budget does not charge shows as a stop by the deadline.
constexpr int64_t kSteps = 1'000'000;
constexpr int kDeadlineMilliseconds = 1000;
constexpr int kMemoryMegabytes = 64;

// The input's bytes, read one choice at a time (zeros once they run out).
struct Choices {
  const uint8_t* data;
  size_t size, at = 0;
  int pick(int n) { return at < size ? data[at++] % n : 0; }
  bool more() const { return at < size; }
};

// Every function a sandbox sees: "name" or "library.name", asked of a sandbox itself.
std::vector<std::string> sandboxVocabulary() {
  script::LuaHost host;
  const int id = host.loadString(R"lua(
    local names = {}
    for k, v in pairs(_G) do
      if type(v) == "function" then
        names[#names + 1] = k
      elseif type(v) == "table" and k ~= "_G" and k ~= "platon" then
        for k2, v2 in pairs(v) do
          if type(v2) == "function" then names[#names + 1] = k .. "." .. k2 end
        end
      end
    end
    table.sort(names)
    return table.concat(names, " ")
  )lua",
                                 "=vocabulary", script::Trust::Sandboxed);
  host.beginFrame();
  host.callSandboxed(id, 0, 1);
  std::istringstream words(lua_tostring(host.state(), -1));
  std::vector<std::string> names;
  for (std::string w; words >> w;) names.push_back(w);
  if (names.size() < 40) bug("the sandbox lists only " + std::to_string(names.size()) + " functions", "");
  return names;
}

// The level's own API (docs/scripting.md): game's functions, the world's and the draw API's.
const char* const kLevelApi[] = {"game.message",
                                 "game.switchOn",
                                 "game.toggle",
                                 "game.kill",
                                 "game.checkpoint",
                                 "game.frame",
                                 "game.player",
                                 "game.won",
                                 "W.createEntity",
                                 "W.destroyEntity",
                                 "W.valid",
                                 "W.insert",
                                 "W.erase",
                                 "W.position",
                                 "W.angle",
                                 "W.velocity",
                                 "W.setVelocity",
                                 "W.setAngularVelocity",
                                 "W.setGravityEnabled",
                                 "W.setFilter",
                                 "W.contactCount",
                                 "W.contact",
                                 "W.instanceCount",
                                 "W.instance",
                                 "W.gravity",
                                 "W.setGravity",
                                 "W.line",
                                 "W.oneWay",
                                 "W.lineCount",
                                 "W.lineAt",
                                 "W.refreshPierce",
                                 "W.createPlatform",
                                 "W.setPlatformMotion",
                                 "W.setPlatformSpin",
                                 "W.platformAngle",
                                 "W.platformOffset",
                                 "W.destroyPlatform",
                                 "W.frame",
                                 "W.stateHash",
                                 "W.countOverlaps",
                                 "W.faceCount",
                                 "W.face",
                                 "W.levelStart",
                                 "D.circle",
                                 "D.line",
                                 "D.polygon",
                                 "D.text",
                                 "D.enabled",
                                 "D.look",
                                 "platon.sound.play",
                                 "platon.sound.music",
                                 "platon.sound.has",
                                 "platon.sound.playing"};

const char* const kValues[] = {"'jump'",
                               "'orbit'",
                               "0",
                               "1",
                               "-1",
                               "0.5",
                               "1/0",
                               "-1/0",
                               "0/0",
                               "2^31",
                               "2^53",
                               "-2^63",
                               "1e308",
                               "7",
                               "4095",
                               "1e9",
                               "-1e9",
                               "'a'",
                               "''",
                               "'%d'",
                               "'%s%s%q'",
                               "'(.-)%1'",
                               "'%f[%w]%w+'",
                               "'[^%z]'",
                               "'%b()'",
                               "'((((((((((a))))))))))'",
                               "'.-.-.-.-b'",
                               "string.rep('ab', 5000)",
                               "('x'):rep(2^20)",
                               "'\\0'",
                               "{}",
                               "{1, 2, 3}",
                               "{a = 1, 'b'}",
                               "{circle = 50}",
                               "{box = {40, 30}}",
                               "{polygon = {0, 0, 100, 0, 0, 100}}",
                               "{category = 1, solidWith = -1}",
                               "{0, 0, 300, 0, 300, 40}",
                               "nil",
                               "true",
                               "false",
                               "print",
                               "V[1]",
                               "V[2]",
                               "V[3]",
                               "game",
                               "W",
                               "D",
                               "frame",
                               "math.huge",
                               "e",
                               "p",
                               "'screen'",
                               "0xFFFFFF",
                               "1000000",
                               "-0",
                               "{n = -1}",
                               "setmetatable({}, M)"};

struct Program {
  Choices& c;
  const std::vector<std::string>& vocabulary;
  std::string out;
  int depth = 0;

  std::string value() { return kValues[c.pick(static_cast<int>(std::size(kValues)))]; }
  std::string function() {
    const int n = static_cast<int>(vocabulary.size() + std::size(kLevelApi));
    const int k = (c.pick(256) * 256 + c.pick(256)) % n;  // two bytes reach every name
    return k < static_cast<int>(vocabulary.size()) ? vocabulary[static_cast<size_t>(k)]
                                                   : kLevelApi[static_cast<size_t>(k) - vocabulary.size()];
  }
  std::string args() {
    std::string a;
    for (int i = c.pick(5); i > 0; --i) a += ", " + value();
    return a;
  }
  std::string count() {
    static const char* const kCounts[] = {"1", "3", "100", "10000", "1e9"};
    return kCounts[c.pick(5)];
  }
  // A statement, nesting blocks at most 4 deep.
  std::string statement() {
    if (!c.more()) return "";
    if (depth >= 4) return "pcall(" + function() + args() + ")\n";
    ++depth;
    std::string s;
    switch (c.pick(14)) {
      case 0:
      case 1:
      case 2:
        s = "pcall(" + function() + args() + ")\n";
        break;
      case 3:
        s = "do local r = {pcall(" + function() + args() + ")} V[#V % 8 + 1] = r[2] end\n";
        break;
      case 4:
        s = "for i = 1, " + count() + " do\n" + statement() + "end\n";
        break;
      case 5:
        s = "while true do\n" + statement() + "end\n";
        break;
      case 6:
        s = "M = { __index = function(t, k) " + statement() + " return " + value() + " end, __add = function(a, b) " +
            statement() + " return " + value() + " end, __lt = function(a, b) " + statement() +
            " return true end, __concat = function(a, b) return " + value() + " end, __call = function(...) " +
            statement() + " end, __len = function() return " + value() + " end }\n";
        break;
      case 7:
        s = "pcall(table.sort, {" + value() + ", " + value() + ", 3, 2, 1, 'z'}, function(a, b) " + statement() +
            " return " + value() + " end)\n";
        break;
      case 8:
        s = "pcall(string.gsub, " + value() + ", " + value() + ", function(...) " + statement() + " return " + value() +
            " end)\n";
        break;
      case 9:
        s = "do local co = coroutine.wrap(function(...) " + statement() + " coroutine.yield(" + value() + ") " +
            statement() + " end) pcall(co) pcall(co) pcall(co) end\n";
        break;
      case 10:
        // Recursion, plain or through wrapped coroutines (each level a coroutine resumed in another).
        s = std::string("do local function f(n) ") + statement() + " if n > 0 then return " +
            (c.pick(2) ? "f(n - 1)" : "coroutine.wrap(f)(n - 1)") + " end end pcall(f, " + count() + ") end\n";
        break;
      case 11:
        s = "do local s = " + value() + " for i = 1, " + count() + " do s = s .. s end end\n";
        break;
      case 12:
        s = "pcall(error, " + value() + (c.pick(2) ? ", 0" : "") + ")\n";
        break;
      default:
        s = "V[" + std::to_string(c.pick(8) + 1) + "] = " + value() + "\n";
    }
    --depth;
    return s;
  }

  // Lines for the game's console, typed after each frame (made by make()).
  std::vector<std::string> console;

  std::string make() {
    std::string build, tick;
    for (int i = 0; i < 6 && c.more(); ++i) build += statement();
    for (int i = 0; i < 2 && c.more(); ++i) console.push_back("local W, D = game.world, platon.draw " + statement());
    while (c.more()) tick += statement();
    return "local level = {}\nV = {1, 'x', {}}\nM = {}\nlocal e, p\n"
           "function level.build(game)\nlocal W, D, frame = game.world, platon.draw, 0\n"
           "pcall(function() e = W.createEntity{circle = 50} W.insert(e, 0, 600, 700) end)\n"
           "pcall(function() p = W.createPlatform(0, {100, 100, 400, 100, 400, 140, 100, 140}) end)\n" +
           build + "end\nfunction level.tick(game, frame)\nlocal W, D = game.world, platon.draw\n" + tick +
           "end\nreturn level\n";
  }
};

struct Folder {
  std::string path;
  Folder() {
    path = (std::filesystem::temp_directory_path() / ("platon_sandbox_fuzz_" + std::to_string(getpid()))).string();
    std::filesystem::create_directories(path);
    std::filesystem::copy_file(std::string(PLATON_SOURCE_ROOT) + "/levels/cube_intro/cube_intro.level",
                               path + "/cube_intro.level", std::filesystem::copy_options::overwrite_existing);
    std::ofstream(path + "/scene.lua")
        << "return { name = 'fuzz', systems = { 'scripting' }, stage = { level = 'cube_intro.level' },\n"
        << "  scripts = { level = 'level.lua' },\n"
        << "  limits = { steps = " << kSteps << ", deadline_ms = " << kDeadlineMilliseconds
        << ", memory_mb = " << kMemoryMegabytes << " } }\n";
  }
  ~Folder() {
    std::error_code error;
    std::filesystem::remove_all(path, error);
  }
};

// Whether an error is the machine's clock speaking: a stop past the frame's deadline, a call
// skipped because an earlier call of the frame ran it out (that call may have been stopped by the
// budget, or not stopped at all, and still have taken the deadline's time on a loaded machine),
// or a call of the engine's own scripts that ran past twice the deadline. Two runs may differ
// there and nowhere else.
bool byTheClock(const std::string& error) {
  return error.find("past the deadline") != std::string::npos ||
         (error.find("deadline of") != std::string::npos && error.find("has passed") != std::string::npos) ||
         error.find("one call from the engine ran longer than") != std::string::npos;
}

struct Run {
  std::vector<std::string> trace;  // per frame: the error (if any) and the world's state hash
  bool deadline = false;           // a stop by the clock (byTheClock)
  // The first entry of the trace with a stop by the memory limit (or the trace's size): where the
  // Lua state's memory reaches a limit may differ between two runs (LuaJIT seeds its string hashes
  // per state, and tables resize, and the collector runs, at other moments; docs/scripting.md,
  // Limits), so the runs are compared up to it.
  size_t memory = SIZE_MAX;
  // Seconds of this thread's processor time (not the wall clock's: a loaded machine stretches
  // that, not this): the slowest frame's (the load counts as one), and the whole run's.
  double slowest = 0;
  double processor = 0;
  bool addressShown = false;  // a console answer showed an address
};

// An address in a text: "0x" and eight hex digits or more (it differs from run to run).
bool hasAddress(const std::string& text) {
  for (size_t at = text.find("0x"); at != std::string::npos; at = text.find("0x", at + 1)) {
    size_t end = at + 2;
    while (end < text.size() && std::isxdigit(static_cast<unsigned char>(text[end]))) ++end;
    if (end - at - 2 >= 8) return true;
  }
  return false;
}

double threadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

Run run(const Folder& folder, const std::string& program, const std::vector<std::string>& console) {
  std::ofstream(folder.path + "/level.lua", std::ios::trunc) << program;
  core::SystemRegistry registry;
  registry.add("scripting", script::makeScriptSystem);
  Run r;
  const double began = threadSeconds();
  std::optional<core::LiveScene> live;
  try {
    live.emplace(folder.path + "/scene.lua", registry, false);
  } catch (const std::exception& e) {
    r.trace.push_back(std::string("load: ") + e.what());
    r.deadline = byTheClock(r.trace.back());
    if (r.trace.back().find("memory limit") != std::string::npos) r.memory = 0;
    r.slowest = r.processor = threadSeconds() - began;
    return r;
  }
  r.slowest = threadSeconds() - began;
  for (int f = 0; f < kFrames; ++f) {
    const double start = threadSeconds();
    const std::optional<std::string> error = live->step(core::InputFrame{});
    r.slowest = std::max(r.slowest, threadSeconds() - start);
    std::string line = error ? *error : "";
    if (byTheClock(line)) r.deadline = true;
    if (line.find("memory limit") != std::string::npos) r.memory = std::min(r.memory, r.trace.size());
    char hash[24];
    std::snprintf(hash, sizeof hash, " %016llx", static_cast<unsigned long long>(live->scene().world().stateHash()));
    r.trace.push_back(line + hash);
    // The console's lines, typed after the frame: their answers are part of what two runs share.
    auto* scripts = dynamic_cast<script::ScriptSystem*>(live->scene().findSystem("scripting"));
    for (const std::string& code : console) {
      if (!scripts) break;
      const double typed = threadSeconds();
      const script::ScriptSystem::ConsoleAnswer answer = scripts->console(code);
      r.slowest = std::max(r.slowest, threadSeconds() - typed);
      if (byTheClock(answer.text)) r.deadline = true;
      if (answer.text.find("memory limit") != std::string::npos) r.memory = std::min(r.memory, r.trace.size());
      if (hasAddress(answer.text)) r.addressShown = true;
      r.trace.push_back("console: " + answer.text);
    }
  }
  r.processor = threadSeconds() - began;
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool rooted = [] { return setenv("PLATON_ROOT", PLATON_SOURCE_ROOT, 1) == 0; }();
  static const std::vector<std::string> vocabulary = sandboxVocabulary();
  static const Folder folder;
  (void)rooted;
  if (size > 4096) return 0;  // a program of some hundreds of statements is enough
  Choices choices{data, size};
  Program program{choices, vocabulary, "", 0, {}};
  const std::string text = program.make();
  if (std::getenv("PLATON_FUZZ_PRINT")) {
    std::fprintf(stderr, "%s\n", text.c_str());
    for (const std::string& line : program.console) std::fprintf(stderr, "console: %s\n", line.c_str());
  }
  const Run first = run(folder, text, program.console);
  const Run second = run(folder, text, program.console);
  if (std::getenv("PLATON_FUZZ_PRINT"))
    for (const Run* r : {&first, &second})
      for (const std::string& line : r->trace) std::fprintf(stderr, "trace: %s\n", line.c_str());
  if (first.addressShown) bug("a console answer shows an address", text);
  // A run stopped by the clock that had half the deadline of processor time or less waited for
  // the machine (other programs had it), not for work the budget does not charge.
  const double deadline = kDeadlineMilliseconds / 1000.0;
  const auto busy = [deadline](const Run& r) { return r.deadline && r.processor >= 0.5 * deadline; };
  if (busy(first) && busy(second))
    bug("stopped by the deadline twice: work the step budget does not charge\n" + first.trace.back(), text);
  if (first.slowest > 3 * deadline && second.slowest > 3 * deadline)
    bug("a frame took " + std::to_string(first.slowest) + " s of processor time, past three times the deadline", text);
  const size_t upTo = std::min(first.memory, second.memory);  // SIZE_MAX: the whole trace
  const auto head = [upTo](const Run& r) {
    return std::vector<std::string>(r.trace.begin(), r.trace.begin() + std::min(upTo, r.trace.size()));
  };
  if (!first.deadline && !second.deadline && head(first) != head(second)) {
    std::string both;
    for (size_t i = 0; i < std::max(first.trace.size(), second.trace.size()); ++i)
      both += (i < first.trace.size() ? first.trace[i] : "-") + "\n    vs " +
              (i < second.trace.size() ? second.trace[i] : "-") + "\n";
    bug("two runs of the same program differ:\n" + both, text);
  }
  return 0;
}
