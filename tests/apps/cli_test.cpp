// The platon program as CI and a person run it: `platon run` (worker processes, time limits,
// crashes, malformed scenarios, JUnit, result lines, --record names, options), `platon play`
// (exit status after script errors, --frames, a recording written on SIGTERM, a --record path
// checked before playing, a stuck frame ended by a second signal or the grace period) and
// `platon scenario` (any scene path). Each runs the built program in a temporary folder.
// PLATON_EXE in the environment runs another build instead (to see these fail on an old one).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <poll.h>
#include <signal.h>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "platon/testing/temp_folder.h"

namespace {

using Folder = platon::testing::TempFolder;
using Clock = std::chrono::steady_clock;

const std::string kRoot = PLATON_SOURCE_ROOT;

// The platon processes these tests start inherit their environment: a CI runner's sharding
// variables would shard them. Cleared once gtest has read its own (it shards this program by them).
class NoOuterShards : public testing::Environment {
 public:
  void SetUp() override {
    for (const char* v :
         {"TEST_SHARD_INDEX", "TEST_TOTAL_SHARDS", "TEST_SHARD_STATUS_FILE", "GTEST_SHARD_INDEX", "GTEST_TOTAL_SHARDS",
          "GTEST_SHARD_STATUS_FILE", "CI_NODE_INDEX", "CI_NODE_TOTAL", "JOB_COMPLETION_INDEX", "XML_OUTPUT_FILE"})
      unsetenv(v);
  }
};
[[maybe_unused]] testing::Environment* const kNoOuterShards = testing::AddGlobalTestEnvironment(new NoOuterShards);

std::string platonExe() {
  const char* other = std::getenv("PLATON_EXE");
  return other && *other ? other : PLATON_EXE;
}

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct Ran {
  int status = -1;  // the exit status, or 128 + the signal that ended it
  std::string out, err;
  double seconds = 0;
};

// A running platon: its output is collected until it ends.
class Process {
 public:
  Process(const std::vector<std::string>& args, const std::string& cwd) {
    int out[2], err[2];
    if (pipe(out) != 0 || pipe(err) != 0) throw std::runtime_error("pipe");
    pid_ = fork();
    if (pid_ == 0) {
      dup2(out[1], 1), dup2(err[1], 2);
      close(out[0]), close(err[0]), close(out[1]), close(err[1]);
      if (chdir(cwd.c_str()) != 0) _exit(127);
      std::vector<std::string> all{platonExe()};
      all.insert(all.end(), args.begin(), args.end());
      std::vector<char*> argv;
      for (std::string& a : all) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
    close(out[1]), close(err[1]);
    out_ = out[0], err_ = err[0];
  }
  ~Process() {
    if (pid_ > 0 && !ended_) kill(pid_, SIGKILL), finish(1);
  }

  // Reads what is there (waiting up to `ms`); true while the program's output is still open.
  bool pump(int ms) {
    pollfd fds[2] = {{out_, POLLIN, 0}, {err_, POLLIN, 0}};
    if (out_ < 0 && err_ < 0) return false;
    poll(fds, 2, ms);
    const std::pair<int*, std::string*> streams[2] = {{&out_, &ran_.out}, {&err_, &ran_.err}};
    for (int k = 0; k < 2; ++k) {
      auto [fd, text] = streams[k];
      if (*fd < 0 || !(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;  // read only what will not block
      char buffer[65536];
      const ssize_t n = read(*fd, buffer, sizeof buffer);
      if (n > 0)
        text->append(buffer, static_cast<size_t>(n));
      else if (n == 0)
        close(*fd), *fd = -1;
    }
    return out_ >= 0 || err_ >= 0;
  }
  bool awaitOutput(const std::string& text, double seconds) {
    const Clock::time_point end =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    while (ran_.out.find(text) == std::string::npos && Clock::now() < end)
      if (!pump(20)) break;
    return ran_.out.find(text) != std::string::npos;
  }
  void signal(int s) { kill(pid_, s); }
  // The program's child processes now (its workers).
  std::vector<pid_t> children() const {
    std::ifstream in("/proc/" + std::to_string(pid_) + "/task/" + std::to_string(pid_) + "/children");
    std::vector<pid_t> out;
    for (pid_t child; in >> child;) out.push_back(child);
    return out;
  }
  // Waits for the end, killing the program after `seconds`.
  Ran finish(double seconds) {
    const Clock::time_point start = Clock::now();
    const Clock::time_point end =
        start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    while (Clock::now() < end && pump(50)) {}
    if (Clock::now() >= end) kill(pid_, SIGKILL);
    int status = 0;
    waitpid(pid_, &status, 0);
    ended_ = true;
    while (pump(0)) {}
    ran_.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    ran_.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return ran_;
  }

 private:
  pid_t pid_ = -1;
  int out_ = -1, err_ = -1;
  bool ended_ = false;
  Ran ran_;
};

Ran platon(const std::vector<std::string>& args, const std::string& cwd, double seconds = 600) {
  return Process(args, cwd).finish(seconds);
}

// A cube scene of its own in `folder`/`name`: a floor on every face, `tick` as the level's tick.
std::string sceneWith(const Folder& folder, const std::string& name, const std::string& tick = "") {
  folder.write(name + "/scene.lua",
               "return { systems = { 'scripting' }, stage = { solid = 'cube', edge = 4096 },\n"
               "  scripts = { preset = 'game', level = 'level.lua' } }\n");
  folder.write(name + "/level.lua",
               "local level = { start = { face = 0, x = 600, y = 700 } }\n"
               "function level.build(game)\n"
               "  for i = 1, game.world.faceCount() do game.world.line(game.world.face(i), 0, 512, 4096, 512) end\n"
               "end\n"
               "function level.tick(game, frame)\n" +
                   tick + "\nend\nreturn level\n");
  return name + "/scene.lua";
}

std::string scenario(const Folder& folder, const std::string& file, const std::string& scene, int frames = 60) {
  return folder.write(file, "return { scene = '" + scene + "', frames = " + std::to_string(frames) +
                                ", input = { { hold = 'right', from = 1, to = " + std::to_string(frames) + " } } }\n"),
         file;
}

// The output's lines.
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A scenario that would run for minutes (10^8 frames; a scenario's own code runs sandboxed, so a
// hang is work the runner's time limit must stop, not an endless loop of its own).
TEST(Run, ATimeLimitHoldsAtJ1AndTheNextScenarioStillRuns) {
  Folder folder("cli_timeout");
  const std::string scene = sceneWith(folder, "s");
  folder.write("hang.lua", "return { scene = '" + scene + "', frames = 30000000 }\n");
  scenario(folder, "ok.lua", scene);
  const Ran r = platon({"run", "--timeout", "5", "hang.lua", "ok.lua"}, folder.path(), 120);
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "FAIL hang.lua: not finished within the time limit of 5 s (killed)")) << r.out;
  EXPECT_TRUE(contains(r.out, "PASS ok.lua: ")) << r.out;
}

// A worker that dies of a signal (here SIGSEGV sent from outside to the one running the long
// scenario: nothing a scenario can do crashes its worker on purpose, its code is sandboxed).
TEST(Run, ACrashingWorkerFailsOnlyItsScenarioAtAnyJ) {
  Folder folder("cli_crash");
  const std::string scene = sceneWith(folder, "s");
  folder.write("segv.lua", "return { scene = '" + scene + "', frames = 30000000 }\n");
  scenario(folder, "a.lua", scene), scenario(folder, "b.lua", scene), scenario(folder, "c.lua", scene);
  for (const char* jobs : {"1", "2", "3"}) {
    Process run({"run", "-j", jobs, "--timeout", "300", "--junit", "report.xml", "a.lua", "segv.lua", "b.lua", "c.lua"},
                folder.path());
    // The worker still there alone for 3 s is segv.lua's (a, b and c take milliseconds; at -j 1, b
    // and c wait for it).
    std::vector<pid_t> workers;
    for (int alone = 0, tries = 0; alone < 30 && tries < 1200; ++tries) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      run.pump(0);
      const std::vector<pid_t> now = run.children();
      alone = now.size() == 1 && now == workers ? alone + 1 : 0;
      workers = now;
    }
    ASSERT_EQ(workers.size(), 1u) << "-j " << jobs;
    kill(workers[0], SIGSEGV);
    const Ran r = run.finish(120);
    EXPECT_EQ(r.status, 1) << r.out << r.err;
    // signal 11, or 6 where a sanitizer catches the fault and aborts
    EXPECT_TRUE(contains(r.out, "FAIL segv.lua: worker crashed (signal 11) while running segv.lua") ||
                contains(r.out, "FAIL segv.lua: worker crashed (signal 6) while running segv.lua"))
        << "-j " << jobs << "\n"
        << r.out;
    for (const char* ok : {"PASS a.lua", "PASS b.lua", "PASS c.lua"})
      EXPECT_TRUE(contains(r.out, ok)) << "-j " << jobs << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, "4 scenarios, 1 failed")) << r.out;
    EXPECT_TRUE(contains(contents(folder.path("report.xml")), "worker crashed (signal "));
  }
}

TEST(Run, AMalformedScenarioFailsAloneWithItsPlace) {
  Folder folder("cli_malformed");
  const std::string scene = sceneWith(folder, "s");
  folder.write("bad.lua", "return { scene = '" + scene + "', frames = 10,\n  input = { 5 } }\n");
  folder.write("meta.lua", "return setmetatable({}, { __index = function(t, k) error('meta ' .. k) end })\n");
  scenario(folder, "ok.lua", scene);
  const Ran r = platon({"run", "--junit", "report.xml", "bad.lua", "meta.lua", "ok.lua"}, folder.path());
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.out, "FAIL bad.lua: bad.lua:2:13: input[1]: expected")) << r.out;
  EXPECT_TRUE(contains(r.out, "FAIL meta.lua: meta.lua:1: scenario: 'scene' (the manifest's path) is missing"))
      << r.out;
  EXPECT_TRUE(contains(r.out, "PASS ok.lua")) << r.out;
  EXPECT_TRUE(contains(contents(folder.path("report.xml")), "tests=\"3\" failures=\"2\""));
}

// Well-formed XML 1.0 text: valid UTF-8, no control characters but tab and line breaks, and
// every '&' starting one of the five entities.
std::string xmlProblem(const std::string& xml) {
  for (size_t i = 0; i < xml.size(); ++i) {
    const auto b = static_cast<unsigned char>(xml[i]);
    if (b < 0x20 && b != '\t' && b != '\n' && b != '\r') return "control byte at " + std::to_string(i);
    if (b >= 0x80) {
      const size_t length = b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : b >= 0xC2 ? 2 : 0;
      if (length == 0 || i + length > xml.size()) return "invalid UTF-8 at " + std::to_string(i);
      for (size_t k = 1; k < length; ++k)
        if ((static_cast<unsigned char>(xml[i + k]) & 0xC0) != 0x80) return "invalid UTF-8 at " + std::to_string(i);
      i += length - 1;
    }
    if (xml[i] == '&') {
      bool entity = false;
      for (const char* e : {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"})
        entity = entity || xml.compare(i, std::strlen(e), e) == 0;
      if (!entity) return "a bare & at " + std::to_string(i);
    }
  }
  return "";
}

TEST(Run, TheJunitReportIsWellFormedWhateverTheMessagesHold) {
  Folder folder("cli_junit");
  const std::string scene =
      sceneWith(folder, "s", "  if frame == 5 then error('bad \\1\\27[31m <x> & \"q\" \\'s\\' \\255\\254 end') end");
  scenario(folder, "ctrl.lua", scene);
  scenario(folder, "x\xff\"y'.lua", scene);
  const Ran r = platon({"run", "--junit", "report.xml", "ctrl.lua", "x\xff\"y'.lua"}, folder.path());
  EXPECT_EQ(r.status, 1);
  const std::string xml = contents(folder.path("report.xml"));
  EXPECT_EQ(xmlProblem(xml), "") << xml;
  EXPECT_TRUE(contains(xml, "bad \\x01\\x1b[31m &lt;x&gt; &amp; &quot;q&quot; &apos;s&apos; \\xff\\xfe end")) << xml;
  EXPECT_TRUE(contains(xml, "name=\"x\\xff&quot;y&apos;.lua\"")) << xml;
  // The terminal gets the same readable bytes.
  EXPECT_TRUE(contains(
      r.out, "FAIL ctrl.lua: " + std::string("level.lua:6: bad \\x01\\x1b[31m <x> & \"q\" 's' \\xff\\xfe end")))
      << r.out;
}

TEST(Run, AFailureIsOneResultLineWithItsTracebackIndentedBelow) {
  Folder folder("cli_lines");
  const std::string scene = sceneWith(folder, "s", "  if frame == 5 then local t = nil; return t.x end");
  scenario(folder, "tick.lua", scene);
  scenario(folder, "ok.lua", scene, 3);
  const Ran r = platon({"run", "tick.lua", "ok.lua"}, folder.path());
  const std::vector<std::string> out = lines(r.out);
  ASSERT_GE(out.size(), 4u) << r.out;
  EXPECT_EQ(out[0].rfind(std::string("FAIL tick.lua: level.lua:6: attempt to index local 't' (a nil value)"), 0), 0u)
      << r.out;
  EXPECT_EQ(out[1], "    stack traceback:") << r.out;
  size_t i = 1;
  while (i < out.size() && out[i].rfind("    ", 0) == 0) ++i;
  ASSERT_LT(i, out.size());
  EXPECT_EQ(out[i].rfind("PASS ok.lua: ", 0), 0u) << r.out;
}

TEST(Run, AHugeMessageIsCut) {
  Folder folder("cli_huge");
  const std::string scene = sceneWith(folder, "s", "  if frame == 5 then error(string.rep('x', 4 * 1024 * 1024)) end");
  scenario(folder, "huge.lua", scene);
  const Ran r = platon({"run", "--junit", "report.xml", "huge.lua"}, folder.path());
  EXPECT_EQ(r.status, 1);
  EXPECT_LT(r.out.size(), 16u * 1024) << "the whole message went out";
  EXPECT_TRUE(contains(r.out, "bytes in all)")) << r.out.substr(0, 200);
  EXPECT_LT(contents(folder.path("report.xml")).size(), 16u * 1024);
}

TEST(Run, RecordWritesOneReplayPerScenarioEvenForTheSameFileName) {
  Folder folder("cli_record");
  const std::string scene = sceneWith(folder, "s");
  scenario(folder, "a/x.lua", scene, 30);
  scenario(folder, "b/x.lua", scene, 90);
  // The folder is made when missing; a scenario given where the folder goes is refused before
  // anything runs (it used to become the folder, and every run failed to write its replay).
  const Ran wrong = platon({"run", "--record", "a/x.lua", "b/x.lua"}, folder.path());
  EXPECT_EQ(wrong.status, 2) << wrong.out;
  EXPECT_TRUE(contains(wrong.err, "--record a/x.lua: expected a folder for the replays")) << wrong.err;
  EXPECT_FALSE(contains(wrong.out, "PASS") || contains(wrong.out, "FAIL")) << wrong.out;
  std::ofstream(folder.path("file")) << "x";
  EXPECT_EQ(platon({"run", "--record", "file", "b/x.lua"}, folder.path()).status, 2);
  const Ran ok = platon({"run", "-j", "2", "--record", "rec", "a/x.lua", "b/x.lua"}, folder.path());
  ASSERT_EQ(ok.status, 0) << ok.out << ok.err;
  EXPECT_TRUE(contains(ok.out, "(recorded to rec/x.replay)")) << ok.out;
  EXPECT_TRUE(contains(ok.out, "(recorded to rec/x-2.replay)")) << ok.out;
  EXPECT_TRUE(contains(contents(folder.path("rec/x.replay")), "frames 30\n"));
  EXPECT_TRUE(contains(contents(folder.path("rec/x-2.replay")), "frames 90\n"));
  const Ran again = platon({"replay", "rec/x.replay", "rec/x-2.replay"}, folder.path());
  EXPECT_EQ(again.status, 0) << again.out;
}

TEST(Run, BadOptionValuesAreRefused) {
  Folder folder("cli_options");
  scenario(folder, "ok.lua", sceneWith(folder, "s"));
  const std::vector<std::vector<std::string>> bad = {
      {"-j", "x"},
      {"-j0"},
      {"-j", "-3"},
      {"-j", "300"},
      {"--timeout", "0"},
      {"--timeout", "abc"},
      {"--timeout", "nan"},
      {"--trace", "x"},
      {"--hash-every", "-1"},
      {"--hash-every", "ten"},
  };
  for (std::vector<std::string> args : bad) {
    std::string shown;
    for (const std::string& a : args) shown += a + " ";
    args.insert(args.begin(), "run");
    args.push_back("ok.lua");
    const Ran r = platon(args, folder.path());
    EXPECT_EQ(r.status, 2) << shown << r.out;
    EXPECT_TRUE(contains(r.err, "usage: platon run")) << shown << r.err;
    EXPECT_FALSE(contains(r.out, "PASS")) << shown << r.out;
  }
}

// Every command answers --help (and -h) on stdout with its usage, and `platon --help` lists every
// command from the same table; an unknown command is refused with the list.
TEST(Help, EveryCommandAnswersHelpWithItsUsage) {
  Folder folder("cli_help");
  const Ran list = platon({"--help"}, folder.path());
  ASSERT_EQ(list.status, 0) << list.err;
  std::vector<std::string> names;
  for (const std::string& line : lines(list.out))
    if (line.size() > 2 && line.rfind("  ", 0) == 0 && line[2] != '(')
      names.push_back(line.substr(2, line.find(' ', 2) - 2));
  for (const char* expected : {"game", "play", "shot", "run", "replay", "scenario", "merge", "check", "net"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected << " is not listed:\n"
                                                                            << list.out;
  for (const std::string& name : names)
    for (const char* flag : {"--help", "-h"}) {
      const Ran r = platon({name, flag}, folder.path());
      EXPECT_EQ(r.status, 0) << name << " " << flag << r.err;
      EXPECT_EQ(r.out.rfind("usage: platon " + name + " ", 0), 0u) << name << " " << flag << ":\n" << r.out;
      EXPECT_TRUE(r.err.empty()) << name << r.err;
    }
  // check's --help is no file named --help, wherever it stands.
  EXPECT_EQ(platon({"check", "x.level", "--help"}, folder.path()).status, 0);
  for (const char* explained : {"--trace N", "--hash-every N", "--record DIR"})
    EXPECT_TRUE(contains(platon({"replay", "--help"}, folder.path()).out, explained)) << explained;
  const Ran unknown = platon({"bogus"}, folder.path());
  EXPECT_EQ(unknown.status, 2);
  EXPECT_TRUE(contains(unknown.err, "no command 'bogus'") && contains(unknown.err, "  replay ")) << unknown.err;
}

// A level is its folder, its scene.lua, its .level file or its name under levels/, for every
// command that takes one (shot's pictures are checked in the render tests' environment).
TEST(Levels, EveryCommandTakesALevelInEachForm) {
  Folder folder("cli_levels");
  const std::string svg = folder.path("net.svg");
  for (const std::string form : {"levels/tetra_around", "levels/tetra_around/", "levels/tetra_around/scene.lua",
                                 "levels/tetra_around/tetra_around.level", "tetra_around"}) {
    const Ran check = platon({"check", form}, kRoot);
    EXPECT_EQ(check.status, 0) << form << check.out << check.err;
    EXPECT_TRUE(contains(check.out, "tetra_around.level: ok (4 faces)")) << form << check.out;
    EXPECT_EQ(platon({"net", form, "-o", svg}, kRoot).status, 0) << form;
    const Ran play = platon({"play", form, "--headless", "--frames", "5"}, kRoot);
    EXPECT_EQ(play.status, 0) << form << play.err;
    EXPECT_TRUE(contains(play.out, "after 5 frames")) << form << play.out;
  }
  const Ran none = platon({"check", "no_such_level"}, kRoot);
  EXPECT_EQ(none.status, 1);
  EXPECT_TRUE(contains(none.out, "no_such_level: error: no level here")) << none.out;
}

// --trace tells what finding a level's inputs needs: velocity, on the ground or not, deaths, the
// switches on and the checkpoint, every N frames and on the last (here the goal's).
TEST(Run, TraceShowsVelocityGroundSwitchesAndCheckpoint) {
  const Ran r = platon({"run", "--trace", "50", "tests/scenarios/cube_switches_solve.lua"}, kRoot);
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.err, "frame 50: face 0 at (")) << r.err;
  for (const char* part : {"velocity (9.00, 0.00), grounded", "in the air", "deaths 0", "switches on: none",
                           "switches on: 1", "no checkpoint", "checkpoint face 0 (", ", won"})
    EXPECT_TRUE(contains(r.err, part)) << part << " is not in:\n" << r.err;
}

TEST(Play, HeadlessExitsOneAfterAScriptError) {
  Folder folder("cli_play_error");
  const std::string broken = sceneWith(folder, "broken", "  if frame == 5 then local t = nil; return t.x end");
  const std::string clean = sceneWith(folder, "clean");
  const Ran r = platon({"play", broken, "--headless", "--fast", "--frames", "100"}, folder.path());
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "frame 5: error (the game goes on):")) << r.out;
  EXPECT_TRUE(contains(r.out, "1 frame(s) had a script error")) << r.out;
  EXPECT_EQ(platon({"play", clean, "--headless", "--fast", "--frames", "100"}, folder.path()).status, 0);
}

TEST(Play, FramesMustBeAWholeNumberFromOne) {
  Folder folder("cli_play_frames");
  const std::string scene = sceneWith(folder, "s");
  for (const char* frames : {"-1", "abc", "0", "10x", ""}) {
    const Ran r = platon({"play", scene, "--headless", "--fast", "--frames", frames}, folder.path(), 120);
    EXPECT_EQ(r.status, 2) << "--frames '" << frames << "': " << r.out;
    EXPECT_TRUE(contains(r.err, "--frames")) << r.err;
  }
}

TEST(Play, ASignalEndsThePlayAndTheRecordingIsWritten) {
  Folder folder("cli_play_signal");
  const std::string scene = sceneWith(folder, "s");
  for (const int s : {SIGTERM, SIGINT}) {
    std::filesystem::remove(folder.path("run.replay"));
    Process play({"play", scene, "--headless", "--record", "run.replay"}, folder.path());  // never ends by itself
    ASSERT_TRUE(play.awaitOutput("playing", 120));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    play.signal(s);
    const Ran r = play.finish(120);
    EXPECT_EQ(r.status, 128 + s) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "stopped by signal " + std::to_string(s))) << r.out;
    ASSERT_TRUE(std::filesystem::exists(folder.path("run.replay"))) << r.out;
    const Ran replay = platon({"replay", "run.replay"}, folder.path());
    EXPECT_EQ(replay.status, 0) << replay.out;
  }
}

TEST(Scenario, AnyScenePathReadsBackFromTheScenarioItWrites) {
  Folder folder("cli_scenario_path");
  const std::string scene = sceneWith(folder, "back\\slash", "");
  const std::string replay = folder.write(
      "run.replay", "platon replay 1\nscene \"" + scene + "\"\nframes 30\nhash_every 0\ninput\n30 right\nend\n");
  (void)replay;
  const Ran made = platon({"scenario", "run.replay", "-o", "made.lua"}, folder.path());
  ASSERT_EQ(made.status, 0) << made.err;
  const Ran r = platon({"run", "made.lua"}, folder.path());
  EXPECT_EQ(r.status, 0) << contents(folder.path("made.lua")) << "\n" << r.out;
}

// A scene whose level is a trusted script (an engine script under a PLATON_ROOT of the folder's
// own) that loops without end in frame 3: the JIT compiles the loop, and compiled code runs no
// hook, so the frame never returns to play's loop.
std::string stuckScene(const Folder& folder) {
  std::filesystem::create_directories(folder.path("root"));
  std::filesystem::copy(kRoot + "/scripts", folder.path("root/scripts"), std::filesystem::copy_options::recursive);
  folder.write(
      "root/scripts/stuck.lua",
      "local level = { start = { face = 0, x = 600, y = 700 } }\n"
      "function level.build(game)\n"
      "  for i = 1, game.world.faceCount() do game.world.line(game.world.face(i), 0, 512, 4096, 512) end\n"
      "end\n"
      "function level.tick(game, frame)\n"
      "  if frame == 3 then print('stuck in frame 3') io.stdout:flush() local n = 0 while true do n = n + 1 end end\n"
      "end\n"
      "return level\n");
  folder.write("scene.lua",
               "return { systems = { 'scripting' }, stage = { solid = 'cube', edge = 4096 },\n"
               "  scripts = { preset = 'game', level = 'scripts/stuck.lua' } }\n");
  return "scene.lua";
}

// Plays stuckScene until it is stuck, with a grace period of `grace` seconds after one signal.
std::unique_ptr<Process> playStuck(const Folder& folder, int grace) {
  const std::string scene = stuckScene(folder);
  setenv("PLATON_ROOT", folder.path("root").c_str(), 1);
  setenv("PLATON_STOP_GRACE", std::to_string(grace).c_str(), 1);
  auto play = std::make_unique<Process>(
      std::vector<std::string>{"play", scene, "--headless", "--fast", "--record", "run.replay"}, folder.path());
  unsetenv("PLATON_ROOT");
  unsetenv("PLATON_STOP_GRACE");
  return play;
}

// Re-audit N3: SIGTERM and SIGINT only set a flag the loop reads between frames, so a stuck frame
// could not be stopped (not by `timeout`, not by Ctrl-C). A second signal ends it at once: here
// the grace period is an hour, so ending by SIGINT at all (before finish kills it) is that.
TEST(Play, ASecondSignalEndsAStuckFrameAtOnce) {
  Folder folder("cli_play_stuck_twice");
  std::unique_ptr<Process> play = playStuck(folder, 3600);
  ASSERT_TRUE(play->awaitOutput("stuck in frame 3", 60));
  play->signal(SIGTERM);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  play->signal(SIGINT);
  const Ran r = play->finish(120);
  EXPECT_EQ(r.status, 128 + SIGINT) << r.out << r.err;
  EXPECT_TRUE(contains(r.err, "platon play: the frame did not end: stopped at once, without writing a recording"))
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(folder.path("run.replay")));
}

// One signal (what `timeout` sends) ends a stuck frame after the grace period (1 s here; 3 s unless
// $PLATON_STOP_GRACE says otherwise): by SIGTERM's own default action, not before the grace.
TEST(Play, OneSignalEndsAStuckFrameAfterTheGracePeriod) {
  Folder folder("cli_play_stuck_once");
  std::unique_ptr<Process> play = playStuck(folder, 1);
  ASSERT_TRUE(play->awaitOutput("stuck in frame 3", 60));
  play->signal(SIGTERM);
  const Ran r = play->finish(120);
  EXPECT_EQ(r.status, 128 + SIGTERM) << r.out << r.err;
  EXPECT_GE(r.seconds, 0.9);  // a lower bound: no machine makes it shorter
  EXPECT_TRUE(contains(r.err, "stopped at once, without writing a recording")) << r.err;
}

// Re-audit N4: a --record path that cannot take the replay aborted play at the very end (exit
// 134, the session lost). It is refused before anything is played.
TEST(Play, ARecordPathThatCannotBeWrittenIsRefusedBeforePlaying) {
  Folder folder("cli_play_record_path");
  const std::string scene = sceneWith(folder, "s");
  const std::string quoted = sceneWith(folder, "say \"hi\"");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"play", scene, "--headless", "--fast", "--frames", "5", "--record", "missing/x.replay"},
       "platon play: --record missing/x.replay: cannot write missing/x.replay.partial: No such file or directory"},
      {{"play", scene, "--headless", "--fast", "--frames", "5", "--record", "s"},
       "platon play: --record s: is a folder"},
      {{"play", quoted, "--headless", "--fast", "--frames", "5", "--record", "x.replay"},
       "platon play: --record x.replay: a scene path with '\"' or a line break cannot be written in a replay"},
  };
  for (const auto& [args, message] : cases) {
    const Ran r = platon(args, folder.path(), 120);
    EXPECT_EQ(r.status, 2) << args.back() << "\n" << r.out << r.err;
    EXPECT_TRUE(contains(r.err, message)) << r.err;
    EXPECT_FALSE(contains(r.out, "playing")) << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(folder.path("x.replay.partial")));
}

// A recording that still cannot be written at the end (here a folder took its place while the
// game ran) is reported with where the written replay was left, and play exits 1: no abort.
TEST(Play, ARecordingThatCannotBeWrittenAtTheEndIsReportedNotAnAbort) {
  Folder folder("cli_play_record_lost");
  const std::string scene = sceneWith(folder, "s");
  Process play({"play", scene, "--headless", "--record", "run.replay"}, folder.path());
  ASSERT_TRUE(play.awaitOutput("playing", 120));
  std::filesystem::create_directories(folder.path("run.replay/in_the_way"));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  play.signal(SIGTERM);
  const Ran r = play.finish(120);
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_TRUE(contains(r.err,
                       "platon play: run.replay: cannot write the replay: it is not a regular file (a folder, a FIFO "
                       "or a device); this run's recording is left in run.replay.partial"))
      << r.err;
  EXPECT_EQ(contents(folder.path("run.replay.partial")).rfind("platon replay 1\n", 0), 0u);
}

namespace shards {

// A suite of `n` small scenarios in `folder` (s1.lua ...), all on one scene; returns their names.
std::vector<std::string> suite(const Folder& folder, int n) {
  const std::string scene = sceneWith(folder, "s");
  std::vector<std::string> files;
  for (int i = 1; i <= n; ++i) files.push_back(scenario(folder, "s" + std::to_string(i) + ".lua", scene, 10));
  return files;
}

std::vector<std::string> withArgs(std::vector<std::string> args, const std::vector<std::string>& files) {
  args.insert(args.end(), files.begin(), files.end());
  return args;
}

// `platon run ARGS --list FILES` with the environment variables `env` set: the files it would run.
std::vector<std::string> listed(const Folder& folder, const std::vector<std::string>& files,
                                const std::vector<std::string>& args,
                                const std::vector<std::pair<std::string, std::string>>& env) {
  for (const auto& [name, value] : env) setenv(name.c_str(), value.c_str(), 1);
  std::vector<std::string> all{"run", "--list"};
  all.insert(all.end(), args.begin(), args.end());
  const Ran r = platon(withArgs(all, files), folder.path());
  for (const auto& [name, value] : env) unsetenv(name.c_str());
  EXPECT_EQ(r.status, 0) << r.err;
  return lines(r.out);
}

// Each way of asking for N shards (our flag, Bazel's, GoogleTest's and GitLab's variables, a
// Kubernetes indexed job), for several N: the shards together run every scenario exactly once, and
// every way gives the same shards.
TEST(Shards, EveryWayOfAskingForNShardsCoversEachScenarioOnce) {
  Folder folder("cli_shards");
  const std::vector<std::string> files = suite(folder, 13);
  for (const int n : {1, 2, 4, 5}) {
    std::vector<std::vector<std::string>> byFlag;
    for (int i = 0; i < n; ++i) {
      const std::string i0 = std::to_string(i), i1 = std::to_string(i + 1), total = std::to_string(n);
      const std::vector<std::vector<std::string>> ways = {
          listed(folder, files, {"--shard", i1 + "/" + total}, {}),
          listed(folder, files, {}, {{"TEST_SHARD_INDEX", i0}, {"TEST_TOTAL_SHARDS", total}}),
          listed(folder, files, {}, {{"GTEST_SHARD_INDEX", i0}, {"GTEST_TOTAL_SHARDS", total}}),
          listed(folder, files, {}, {{"CI_NODE_INDEX", i1}, {"CI_NODE_TOTAL", total}}),
          listed(folder, files, {"--shards", total}, {{"JOB_COMPLETION_INDEX", i0}}),
      };
      for (const auto& way : ways) EXPECT_EQ(way, ways[0]) << "shard " << i1 << "/" << n;
      byFlag.push_back(ways[0]);
    }
    std::map<std::string, int> runs;
    for (const auto& shard : byFlag)
      for (const std::string& f : shard) ++runs[f];
    EXPECT_EQ(runs.size(), files.size()) << n << " shards";
    for (const std::string& f : files) EXPECT_EQ(runs[f], 1) << f << " in " << n << " shards";
  }
}

// With the last run's durations, the shards balance time, not counts: one scenario that took as
// long as the rest together gets a shard of its own.
TEST(Shards, DurationsBalanceTheShards) {
  Folder folder("cli_shards_durations");
  const std::vector<std::string> files = suite(folder, 9);
  std::string report = "<?xml version=\"1.0\"?>\n<testsuite name=\"x\" tests=\"9\">\n";
  for (const std::string& f : files)
    report += "  <testcase name=\"" + f + "\" time=\"" + (f == "s5.lua" ? "80" : "10") + "\"/>\n";
  folder.write("last.xml", report + "</testsuite>\n");
  const auto first = listed(folder, files, {"--shard", "1/2", "--durations", "last.xml"}, {});
  const auto second = listed(folder, files, {"--shard", "2/2", "--durations", "last.xml"}, {});
  const auto& alone = std::find(first.begin(), first.end(), "s5.lua") != first.end() ? first : second;
  EXPECT_EQ(alone, std::vector<std::string>{"s5.lua"});
  EXPECT_EQ(first.size() + second.size(), files.size());
  // A report that is not one is refused by name, before anything runs.
  folder.write("bad.xml", "<html>");
  const Ran r = platon(withArgs({"run", "--shard", "1/2", "--durations", "bad.xml"}, files), folder.path());
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "bad.xml:1: not XML")) << r.err;
}

// Four shards run with their reports; the merge joins them, and refuses a missing shard, a shard
// given twice and a shard of another suite, naming each.
TEST(Shards, TheMergeChecksEveryScenarioRanOnce) {
  Folder folder("cli_shards_merge");
  const std::vector<std::string> files = suite(folder, 10);
  for (int i = 1; i <= 4; ++i) {
    const Ran r = platon(
        withArgs({"run", "--shard", std::to_string(i) + "/4", "--junit", "shard" + std::to_string(i) + ".xml"}, files),
        folder.path());
    ASSERT_EQ(r.status, 0) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "(shard " + std::to_string(i) + "/4 of 10, from --shard)")) << r.out;
  }
  const Ran merged =
      platon({"merge", "-o", "all.xml", "shard1.xml", "shard2.xml", "shard3.xml", "shard4.xml"}, folder.path());
  EXPECT_EQ(merged.status, 0) << merged.err;
  EXPECT_TRUE(contains(merged.out, "10 scenarios from 4 shards, each run once, 0 failed")) << merged.out;
  const std::string all = contents(folder.path("all.xml"));
  for (const std::string& f : files) EXPECT_TRUE(contains(all, "name=\"" + f + "\"")) << f;

  const Ran missing = platon({"merge", "-o", "x.xml", "shard1.xml", "shard2.xml", "shard4.xml"}, folder.path());
  EXPECT_EQ(missing.status, 1);
  EXPECT_TRUE(contains(missing.err, "platon merge: shard(s) 3/4 missing")) << missing.err;
  const Ran doubled = platon(
      {"merge", "-o", "x.xml", "shard1.xml", "shard2.xml", "shard3.xml", "shard4.xml", "shard2.xml"}, folder.path());
  EXPECT_EQ(doubled.status, 1);
  EXPECT_TRUE(contains(doubled.err, "platon merge: shard 2/4 is given twice: shard2.xml and shard2.xml"))
      << doubled.err;
  // A shard of a suite with one scenario fewer (a runner that globbed another set of files).
  std::vector<std::string> fewer(files.begin(), files.end() - 1);
  ASSERT_EQ(platon(withArgs({"run", "--shard", "3/4", "--junit", "other3.xml"}, fewer), folder.path()).status, 0);
  const Ran other =
      platon({"merge", "-o", "x.xml", "shard1.xml", "shard2.xml", "other3.xml", "shard4.xml"}, folder.path());
  EXPECT_EQ(other.status, 1);
  EXPECT_TRUE(contains(other.err, "other3.xml and shard1.xml are shards of different suites")) << other.err;
  EXPECT_FALSE(std::filesystem::exists(folder.path("x.xml")));
}

// Bazel: the status file is touched (sharding understood) and the report goes to XML_OUTPUT_FILE.
TEST(Shards, BazelsFilesAreWritten) {
  Folder folder("cli_shards_bazel");
  const std::vector<std::string> files = suite(folder, 3);
  setenv("TEST_SHARD_INDEX", "0", 1), setenv("TEST_TOTAL_SHARDS", "2", 1);
  setenv("TEST_SHARD_STATUS_FILE", folder.path("status").c_str(), 1);
  setenv("XML_OUTPUT_FILE", folder.path("bazel.xml").c_str(), 1);
  const Ran r = platon(withArgs({"run"}, files), folder.path());
  for (const char* v : {"TEST_SHARD_INDEX", "TEST_TOTAL_SHARDS", "TEST_SHARD_STATUS_FILE", "XML_OUTPUT_FILE"})
    unsetenv(v);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "(shard 1/2 of 3, from Bazel)")) << r.out;
  EXPECT_TRUE(std::filesystem::exists(folder.path("status")));
  EXPECT_TRUE(contains(contents(folder.path("bazel.xml")), "<property name=\"platon.shard\" value=\"1/2\"/>"));
}

}  // namespace shards

}  // namespace

namespace {

// A budget stop is the same in every process (where LuaJIT's hot counters and address layout
// differ): a level that walks tables, sorts, formats and calls the level API in a loop until the
// frame's budget stops it says how far it got, and three processes say the same.
TEST(Budget, AStopComesAtTheSameIterationInEveryProcess) {
  Folder folder("cli_budget_processes");
  const std::string scene =
      sceneWith(folder, "s",
                "  local t = {}\n"
                "  for i = 1, 200 do t['k' .. i] = i end\n"
                "  local n = 0\n"
                "  while true do\n"
                "    n = n + 1\n"
                "    for k, v in pairs(t) do end\n"
                "    local k = next(t) while k do k = next(t, k) end\n"
                "    local a = {} for i = 1, 60 do a[i] = (i * 7919) % 61 end table.sort(a)\n"
                "    local s = tostring({}) .. string.format('%d', n) .. (('ab'):rep(20)):gsub('a', 'c')\n"
                "    game.message(n)\n"
                "  end");
  std::vector<std::string> said;
  for (int run = 0; run < 3; ++run) {
    const Ran r = platon({"play", scene, "--headless", "--fast", "--frames", "1"}, folder.path());
    EXPECT_EQ(r.status, 1) << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "script stopped: it ran past the frame's script budget")) << r.out;
    std::string message;  // "frame 1: N", the level's last message (the error has a line of its own)
    for (const std::string& line : lines(r.out))
      if (line.rfind("frame 1: ", 0) == 0 && line.size() > 9 && std::isdigit(static_cast<unsigned char>(line[9])))
        message = line;
    ASSERT_FALSE(message.empty()) << r.out;
    said.push_back(message);
  }
  EXPECT_GT(std::atoi(said[0].substr(9).c_str()), 100) << said[0];
  EXPECT_EQ(said[1], said[0]);
  EXPECT_EQ(said[2], said[0]);
}

// Every file content names is opened only if it is a regular file of bounded size: a FIFO (a tar
// archive can carry one) blocked the load for ever, /dev/zero was read until memory ran out. Each
// file a scenario run opens (the scenario, its scene's manifest, the level file, the level's
// scripts, a mod, the replay and its scene) is replaced in turn by each kind of file that is not
// one, and the run must end, refuse it by name with the reason, and name the line that named it.
TEST(ContentFiles, EveryNamedFileIsARegularFileOfBoundedSize) {
  namespace fs = std::filesystem;
  struct Named {
    std::string file;     // in the folder
    std::string command;  // "run sc.lua" or "replay r.replay"
    std::string namedAt;  // the naming file and line ("" for the file given on the command line)
  };
  const Named named[] = {
      {"sc.lua", "run", ""},
      {"lvl/scene.lua", "run", "sc.lua:1:"},
      {"lvl/l.level", "run", "scene.lua:2:"},
      {"lvl/level.lua", "run", "scene.lua:3:"},
      {"lvl/mod.lua", "run", "scene.lua:3:"},
      {"r.replay", "replay", ""},
      {"lvl/scene.lua", "replay", "r.replay:2:"},
  };
  struct Kind {
    std::string name, reason;
  };
  const Kind kinds[] = {{"fifo", "not a regular file (a FIFO)"},
                        {"folder", "not a regular file (a folder)"},
                        {"device", "/dev/zero"},
                        {"huge", "MB, more than the"}};
  for (const Named& n : named)
    for (const Kind& k : kinds) {
      Folder folder("cli_content_files");
      std::ifstream level(kRoot + "/levels/cube_intro/cube_intro.level", std::ios::binary);
      std::stringstream levelText;
      levelText << level.rdbuf();
      folder.write("lvl/l.level", levelText.str());
      folder.write("lvl/scene.lua",
                   "return { systems = { 'scripting' },\n  stage = { level = 'l.level' },\n"
                   "  scripts = { preset = 'game', level = 'level.lua', mods = { 'mod.lua' } } }\n");
      folder.write("lvl/level.lua", "return { start = { face = 0, x = 600, y = 700 } }\n");
      folder.write("lvl/mod.lua", "return {}\n");
      folder.write("sc.lua", "return { scene = 'lvl/scene.lua', frames = 5 }\n");
      folder.write("r.replay", "platon replay 1\nscene \"lvl/scene.lua\"\nframes 5\nhash_every 0\ninput\n5 -\nend\n");
      const std::string target = folder.path(n.file);
      fs::remove(target);
      if (k.name == "fifo") {
        ASSERT_EQ(mkfifo(target.c_str(), 0600), 0);
      } else if (k.name == "folder") {
        fs::create_directories(target);
      } else if (k.name == "device") {
        fs::create_symlink("/dev/zero", target);
      } else {
        std::ofstream(target) << "-- huge\n";
        fs::resize_file(target, size_t{300} << 20);  // sparse: over every cap, nothing written
      }
      const std::string given = n.command == "run" ? "sc.lua" : "r.replay";
      const Ran r = platon({n.command, "--shard", "1/1", given}, folder.path(), 120);
      const std::string said = r.out + r.err;
      const std::string what = n.file + " as a " + k.name + " (" + n.command + "):\n" + said;
      EXPECT_NE(r.status, 0) << what;
      EXPECT_LT(r.status, 128) << what;  // ended by itself: no crash, no time limit
      EXPECT_TRUE(contains(said, fs::path(n.file).filename().string())) << what;
      EXPECT_TRUE(contains(said, k.reason) || (k.name == "device" && contains(said, "(a device)"))) << what;
      if (!n.namedAt.empty()) {
        EXPECT_TRUE(contains(said, n.namedAt)) << what;
      }
    }
}

// check, net and shot read a level with its scene's tag words: a mod's word is known through the
// level's folder or scene.lua, and unknown in a level file given alone (which has no mods).
TEST(Check, AModsTagWordsAreKnownThroughItsScene) {
  Folder folder("cli_mod_words");
  folder.write("lvl/cube.level",
               "HEXAHEDRON\n0 600 700\n2 2000 800\n4096\n%\n256 512 4096 512 spring\n"
               "%\n0 512 4096 512\n%\n0 512 4096 512\n%\n0 512 4096 512\n%\n%\n");
  folder.write("lvl/springs.lua", "return { tags = { spring = { color = '#cc79a7' } } }\n");
  folder.write("lvl/scene.lua",
               "return { systems = { 'scripting' }, stage = { level = 'cube.level' }, scripts = "
               "{ preset = 'game', mods = { 'springs.lua' } } }\n");
  for (const char* given : {"lvl", "lvl/scene.lua"}) {
    const Ran r = platon({"check", given}, folder.path());
    EXPECT_EQ(r.status, 0) << given << ": " << r.out << r.err;
    EXPECT_TRUE(contains(r.out, "cube.level: ok (6 faces)")) << r.out;
  }
  EXPECT_EQ(platon({"net", "lvl", "-o", "net.svg"}, folder.path()).status, 0);
  // The level file has its scene beside it; a copy with none knows the game's words only.
  EXPECT_EQ(platon({"check", "lvl/cube.level"}, folder.path()).status, 0);
  std::filesystem::create_directories(folder.path("alone"));
  std::filesystem::copy_file(folder.path("lvl/cube.level"), folder.path("alone/cube.level"));
  EXPECT_TRUE(contains(platon({"check", "alone/cube.level"}, folder.path()).out, "unknown segment word 'spring'"));
  folder.write("lvl/springs.lua", "return { tags = { spring = { color = 'pink' } } }\n");
  const Ran broken = platon({"check", "lvl"}, folder.path());
  EXPECT_EQ(broken.status, 1);
  EXPECT_TRUE(contains(broken.out, "springs.lua: tags.spring.color: expected a colour")) << broken.out;
}

// `platon play --input` runs a replay's console lines where `platon replay` runs them (before the
// frame they were typed before), and records them: a line that throws the player up changes every
// hash after it, and the recording replays.
TEST(Play, InputRunsTheReplaysConsoleLines) {
  Folder folder("cli_play_console");
  sceneWith(folder, "s");
  const std::string head = "platon replay 1\nscene \"s/scene.lua\"\nframes 60\nhash_every 10\ninput\n60 right\nend\n";
  folder.write("with.replay", head + "console 5 \"game.world.setVelocity(game.player(), 0, 20)\"\n");
  folder.write("without.replay", head);
  for (const char* name : {"with", "without"}) {
    const Ran r = platon({"play", "s", "--headless", "--fast", "--frames", "60", "--input",
                          std::string(name) + ".replay", "--record", std::string(name) + "_played.replay"},
                         folder.path(), 120);
    EXPECT_EQ(r.status, 0) << r.out << r.err;
  }
  const std::string with = contents(folder.path("with_played.replay")),
                    without = contents(folder.path("without_played.replay"));
  EXPECT_TRUE(contains(with, "console 5 \"game.world.setVelocity(game.player(), 0, 20)\"")) << with;
  const auto hashes = [](const std::string& text) { return text.substr(text.find("\nhash ")); };
  EXPECT_NE(hashes(with), hashes(without)) << "the console line changed nothing";
  const Ran replayed = platon({"replay", "with_played.replay"}, folder.path(), 120);
  EXPECT_EQ(replayed.status, 0) << replayed.out << replayed.err;
}

}  // namespace
