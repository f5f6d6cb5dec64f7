// Runs scenarios, each in a worker process of its own, -j at a time, handed out in the order
// given. A worker writes its one record to a pipe and exits. A worker that outlives the time
// limit (a trusted script's endless compiled loop cannot be stopped from inside) is killed, and
// one that dies without a record (a crash, an exit inside a library) is reported with its
// signal or status: either way only that scenario fails, and the others run in fresh workers.
// Results print in the order the scenarios were given: the same output at any -j.
#include "run_command.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <poll.h>
#include <signal.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "commands.h"
#include "engine_registry.h"
#include "junit.h"
#include "platon/core/visible_text.h"
#include "platon/files/write_file.h"
#include "platon/script/scenario.h"
#include "shard.h"

namespace platon::app {
namespace {

using Clock = std::chrono::steady_clock;

// A message longer than this is cut (a 20 MB error string would otherwise go out whole, twice
// into the JUnit file).
constexpr size_t kMessageLimit = 4096;

struct Outcome {
  bool done = false;
  script::ScenarioResult result;
};

std::string capped(const std::string& message) {
  if (message.size() <= kMessageLimit) return message;
  size_t cut = kMessageLimit;
  while (cut > 0 && (static_cast<unsigned char>(message[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  return message.substr(0, cut) + "... (cut: " + std::to_string(message.size()) + " bytes in all)";
}

// `text` fit for a terminal and an XML file: valid UTF-8, no control bytes but tab and newline.
// Anything else is shown as \xNN, so nothing is lost (a NUL no longer cuts the message short).
std::string printable(const std::string& text) { return core::visibleText(text, true); }

// One record: passed, frames, seconds, hash, message length, message.
std::string recordOf(const script::ScenarioResult& r) {
  const std::string message = capped(r.message);
  return std::string(r.passed ? "1" : "0") + " " + std::to_string(r.frames) + " " + std::to_string(r.seconds) + " " +
         (r.hash.empty() ? "-" : r.hash) + " " + std::to_string(message.size()) + "\n" + message;
}

void writeAll(int fd, const std::string& text) {
  for (size_t sent = 0; sent < text.size();) {
    const ssize_t n = write(fd, text.data() + sent, text.size() - sent);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    sent += static_cast<size_t>(n);
  }
}

bool readRecord(const std::string& data, script::ScenarioResult& r) {
  const size_t eol = data.find('\n');
  if (eol == std::string::npos) return false;
  size_t length = 0;
  int passed = 0;
  unsigned long long frames = 0;
  double seconds = 0;
  char hash[32] = {};
  if (std::sscanf(data.c_str(), "%d %llu %lf %31s %zu", &passed, &frames, &seconds, hash, &length) != 5) return false;
  if (eol + 1 + length > data.size()) return false;
  r.passed = passed != 0;
  r.frames = frames;
  r.seconds = seconds;
  r.hash = std::strcmp(hash, "-") == 0 ? "" : hash;
  r.message = data.substr(eol + 1, length);
  return true;
}

// Why a worker ended without a record.
std::string workerDied(int status, const std::string& file) {
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    return "worker crashed (signal " + std::to_string(signal) + ") while running " + file + ": " + strsignal(signal);
  }
  return "worker exited with status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
         " while running " + file + " and gave no result";
}

// run's or replay's usage, as the command was called.
const char* calledAs = "run";
int runUsage() { return usageError(calledAs); }

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// "tests/scenarios/walk.lua" -> "walk"
std::string stem(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') + 1);
  return name.substr(0, name.find_last_of('.'));
}

// Where each scenario's replay goes with --record: DIR/<stem>.replay, and DIR/<stem>-2.replay,
// -3, ... for later scenarios of the same file name (a/x.lua and b/x.lua).
std::vector<std::string> recordPaths(const std::vector<std::string>& files, const std::string& dir) {
  std::vector<std::string> paths;
  if (dir.empty()) return std::vector<std::string>(files.size());
  std::map<std::string, int> seen;
  for (const std::string& file : files) {
    const std::string name = stem(file);
    const int n = ++seen[name];
    paths.push_back(dir + "/" + name + (n == 1 ? "" : "-" + std::to_string(n)) + ".replay");
  }
  return paths;
}

// One file: a scenario or a replay; with a record path, its run is written there as a replay.
script::ScenarioResult runOne(const std::string& file, const script::RunOptions& options,
                              const std::string& recordPath) {
  script::ScenarioResult r =
      endsWith(file, ".replay") ? script::runReplay(file, options) : script::runScenario(file, options);
  if (!recordPath.empty() && r.recorded) {
    try {
      core::writeReplay(*r.recorded, recordPath);
      r.message += " (recorded to " + recordPath + ")";
    } catch (const std::exception& e) {
      r.passed = false;
      r.message = e.what();
    }
  }
  return r;
}

struct Worker {
  pid_t pid;
  int fd;
  size_t index;  // the scenario it runs
  Clock::time_point deadline;
  std::string data;
};

// Forks a worker for one scenario; it writes its record to a pipe and exits. "" or why it could
// not start.
std::string startWorker(size_t index, const std::string& file, const script::RunOptions& options,
                        const std::string& recordPath, double timeout, std::vector<Worker>& workers) {
  int fds[2];
  if (pipe(fds) != 0) return std::string("cannot start a worker: pipe: ") + std::strerror(errno);
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) {
    std::string error = std::string("cannot start a worker: fork: ") + std::strerror(errno);
    close(fds[0]), close(fds[1]);
    return error;
  }
  if (pid == 0) {
    close(fds[0]);
    writeAll(fds[1], recordOf(runOne(file, options, recordPath)));
    close(fds[1]);
    std::fflush(nullptr);
    _exit(0);
  }
  close(fds[1]);
  const auto limit = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeout));
  workers.push_back({pid, fds[0], index, Clock::now() + limit, {}});
  return "";
}

// Ends a worker whose pipe closed (or that was killed) and turns what it wrote into an outcome.
Outcome finishWorker(Worker& w, const std::string& file, bool killedAfterTimeout, double timeout) {
  close(w.fd);
  int status = 0;
  while (waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {}
  Outcome o;
  o.done = true;
  if (killedAfterTimeout) {
    char limit[32];
    std::snprintf(limit, sizeof limit, "%g", timeout);
    o.result.message = "not finished within the time limit of " + std::string(limit) + " s (killed)";
  } else if (!readRecord(w.data, o.result)) {
    o.result.message = workerDied(status, file);
  }
  return o;
}

// Runs every file in workers, `jobs` at a time, and fills `outcomes`.
void runInWorkers(const std::vector<std::string>& files, const script::RunOptions& options,
                  const std::vector<std::string>& records, int jobs, double timeout, std::vector<Outcome>& outcomes) {
  std::vector<Worker> workers;
  size_t next = 0;
  while (next < files.size() || !workers.empty()) {
    while (next < files.size() && workers.size() < static_cast<size_t>(jobs)) {
      if (std::string error = startWorker(next, files[next], options, records[next], timeout, workers); !error.empty())
        outcomes[next].done = true, outcomes[next].result.message = error;
      ++next;
    }
    std::vector<pollfd> fds;
    auto wait = std::chrono::milliseconds(100);
    const auto now = Clock::now();
    for (const Worker& w : workers) {
      fds.push_back({w.fd, POLLIN, 0});
      wait = std::min(wait, std::chrono::duration_cast<std::chrono::milliseconds>(
                                std::max(w.deadline - now, Clock::duration::zero())) +
                                std::chrono::milliseconds(1));
    }
    if (poll(fds.data(), fds.size(), static_cast<int>(wait.count())) < 0 && errno != EINTR) std::perror("poll");
    for (size_t k = workers.size(); k-- > 0;) {
      Worker& w = workers[k];
      bool ended = false, killed = false;
      if (fds[k].revents & (POLLIN | POLLHUP | POLLERR)) {
        char buffer[65536];
        const ssize_t n = read(w.fd, buffer, sizeof buffer);
        if (n > 0)
          w.data.append(buffer, static_cast<size_t>(n));
        else if (n == 0 || errno != EINTR)
          ended = true;
      }
      if (!ended && Clock::now() > w.deadline) {
        kill(w.pid, SIGKILL);
        ended = killed = true;
      }
      if (!ended) continue;
      outcomes[w.index] = finishWorker(w, files[w.index], killed, timeout);
      workers.erase(workers.begin() + static_cast<std::ptrdiff_t>(k));
    }
  }
}

// The result line, then any further lines of the message indented below it.
void printResult(const std::string& file, const script::ScenarioResult& r) {
  const std::string message = printable(r.message);
  const size_t eol = message.find('\n');
  const std::string first = message.substr(0, eol);
  if (r.passed) {
    std::printf("PASS %s: %s, %llu frames, %.3f s, hash %s\n", printable(file).c_str(), first.c_str(),
                static_cast<unsigned long long>(r.frames), r.seconds, r.hash.c_str());
  } else {
    std::printf("FAIL %s: %s\n", printable(file).c_str(), first.c_str());
  }
  for (size_t at = eol; at != std::string::npos && at + 1 < message.size();) {
    const size_t end = message.find('\n', at + 1);
    std::printf("    %s\n",
                message.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1).c_str());
    at = end;
  }
}

std::string text(const char* value) { return value ? value : ""; }

// The files of `shard`, in the order given, balanced by the durations of report `durationsPath`
// when there is one.
std::vector<std::string> shardFiles(const std::vector<std::string>& suite, const Shard& shard,
                                    const std::string& durationsPath) {
  std::map<std::string, double> durations;
  if (!durationsPath.empty())
    for (const JunitCase& c : readJunit(durationsPath).cases) durations[c.name] = c.seconds;
  const std::vector<uint32_t> of = splitIntoShards(suite, shard.total, durations);
  std::vector<std::string> mine;
  for (size_t i = 0; i < suite.size(); ++i)
    if (of[i] == shard.index) mine.push_back(suite[i]);
  return mine;
}

// A whole number in [low, high] from the whole of `text`.
bool wholeNumber(const char* text, uint64_t low, uint64_t high, uint64_t& out) {
  const char* end = text + std::strlen(text);
  const auto [stop, error] = std::from_chars(text, end, out);
  return error == std::errc() && stop == end && end != text && out >= low && out <= high;
}

// A number of seconds > 0 from the whole of `text`.
bool seconds(const char* text, double& out) {
  char* stop = nullptr;
  out = std::strtod(text, &stop);
  return stop != text && *stop == '\0' && std::isfinite(out) && out > 0;
}

int badValue(const char* option, const char* value, const char* expected) {
  std::fprintf(stderr, "platon %s: %s %s: expected %s\n", calledAs, option, value, expected);
  return runUsage();
}

// What `platon run` (or replay) was asked for: its options and its files, as given.
struct RunArgs {
  uint64_t jobs = 1;
  double timeout = 600;
  std::string junit, shardFlag, shardsFlag, durationsPath;
  bool list = false;
  script::RunOptions options;
  std::string recordDir;
  std::vector<std::string> files;
};

// --record's folder, made if it is missing: nothing, or the exit status once it said why not (the
// option reads the next word, so a scenario given first would be taken for the folder).
std::optional<int> makeRecordFolder(const std::string& recordDir) {
  // `--record a.lua b.lua` would take the first scenario for the folder and fail every run.
  std::error_code error;
  if (endsWith(recordDir, ".lua") || endsWith(recordDir, ".replay") ||
      (std::filesystem::exists(recordDir, error) && !std::filesystem::is_directory(recordDir, error)))
    return badValue("--record", recordDir.c_str(), "a folder for the replays (platon run --record DIR file...)");
  std::filesystem::create_directories(recordDir, error);
  if (error) {
    std::fprintf(stderr, "platon %s: --record %s: cannot make the folder: %s\n", calledAs, recordDir.c_str(),
                 error.message().c_str());
    return 2;
  }
  return std::nullopt;
}

// The options whose value is a word kept as it is: where it goes; null for any other.
std::string* wordOption(const std::string& a, RunArgs& args) {
  if (a == "--junit") return &args.junit;
  if (a == "--shard") return &args.shardFlag;
  if (a == "--shards") return &args.shardsFlag;
  if (a == "--durations") return &args.durationsPath;
  return nullptr;
}

// The options whose value is checked as it is read.
bool isCheckedOption(const std::string& a) {
  return a == "--timeout" || a == "--trace" || a == "--record" || a == "--hash-every";
}

// A checked option's value: nothing, or the exit status once it said why the value is wrong.
std::optional<int> readCheckedOption(const std::string& a, const char* value, RunArgs& args) {
  if (a == "--timeout" && !seconds(value, args.timeout))
    return badValue("--timeout", value, "a number of seconds above 0");
  if (a == "--trace" && !wholeNumber(value, 1, UINT64_MAX, args.options.traceEvery))
    return badValue("--trace", value, "a whole number of frames from 1");
  if (a == "--hash-every" && !wholeNumber(value, 0, UINT64_MAX, args.options.hashEvery))
    return badValue("--hash-every", value, "a whole number of frames (0: only the last frame's hash)");
  if (a != "--record") return std::nullopt;
  args.recordDir = value, args.options.record = true;
  return makeRecordFolder(args.recordDir);
}

// The command line into `args`, in one pass (an option's value is the next word, or -jN's own
// digits): nothing, or the exit status once the first wrong word was said.
std::optional<int> readRunArgs(int argc, char** argv, RunArgs& args) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if ((a == "-j" && hasValue) || (a.rfind("-j", 0) == 0 && a.size() > 2)) {
      const char* value = a == "-j" ? argv[++i] : argv[i] + 2;
      if (!wholeNumber(value, 1, 256, args.jobs)) return badValue("-j", value, "a whole number from 1 to 256");
    } else if (std::string* word = hasValue ? wordOption(a, args) : nullptr) {
      *word = argv[++i];
    } else if (hasValue && isCheckedOption(a)) {
      if (const std::optional<int> status = readCheckedOption(a, argv[++i], args)) return status;
    } else if (a == "--list") {
      args.list = true;
    } else if (!a.empty() && a[0] == '-') {
      return runUsage();
    } else {
      args.files.push_back(a);
    }
  }
  return std::nullopt;
}

// The results in the order given, the summary line, and the JUnit report when one was asked for;
// the command's exit status. `suite`: every file given, before sharding.
int reportRun(const RunArgs& args, const std::vector<std::string>& suite, const std::optional<Shard>& shard,
              const std::vector<Outcome>& outcomes, double elapsed) {
  const std::vector<std::string>& files = args.files;
  int failed = 0;
  JunitReport report;
  report.seconds = elapsed;
  for (size_t i = 0; i < files.size(); ++i) {
    const Outcome& o = outcomes[i];
    failed += o.result.passed ? 0 : 1;
    printResult(files[i], o.result);
    report.cases.push_back({files[i], o.result.seconds, o.result.passed, capped(o.result.message)});
  }
  std::printf("%zu scenarios%s, %d failed, %.2f s with -j %llu\n", files.size(),
              shard ? (" (shard " + std::to_string(shard->index + 1) + "/" + std::to_string(shard->total) + " of " +
                       std::to_string(suite.size()) + ", from " + shard->from + ")")
                          .c_str()
                    : "",
              failed, elapsed, static_cast<unsigned long long>(args.jobs));
  std::fflush(stdout);
  // What `platon merge` checks the shards by: which shard this is, of which suite.
  report.properties["platon.suite"] = suiteIdentity(suite);
  report.properties["platon.shard"] =
      shard ? std::to_string(shard->index + 1) + "/" + std::to_string(shard->total) : "1/1";
  if (!args.junit.empty() && !writeJunit(args.junit, report)) {
    std::fprintf(stderr, "%s: cannot write the JUnit report\n", args.junit.c_str());
    return 1;
  }
  return failed ? 1 : 0;
}

}  // namespace

int runCommand(int argc, char** argv) {
  calledAs = std::strcmp(argv[0], "replay") == 0 ? "replay" : "run";
  RunArgs args;
  args.options.pluginFolders = pluginFolders();
  if (const std::optional<int> status = readRunArgs(argc, argv, args)) return *status;
  if (args.files.empty()) return runUsage();
  // Bazel names the report it wants, and a file to touch that says sharding is understood.
  if (args.junit.empty()) args.junit = text(std::getenv("XML_OUTPUT_FILE"));
  for (const char* status : {"TEST_SHARD_STATUS_FILE", "GTEST_SHARD_STATUS_FILE"})
    if (const char* path = std::getenv(status); path && *path) std::ofstream(path, std::ios::app);
  const std::vector<std::string> suite = args.files;
  std::optional<Shard> shard;
  try {
    shard = askedShard(args.shardFlag, args.shardsFlag, [](const char* name) { return std::getenv(name); });
    if (shard) args.files = shardFiles(suite, *shard, args.durationsPath);
    if (!shard && !args.durationsPath.empty())
      std::fprintf(stderr, "platon run: --durations %s: no shard was asked for, so every scenario runs\n",
                   args.durationsPath.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "platon run: %s\n", e.what());
    return 2;
  }
  if (args.list) {
    for (const std::string& f : args.files) std::printf("%s\n", f.c_str());
    return 0;
  }
  const auto start = Clock::now();
  std::vector<Outcome> outcomes(args.files.size());
  runInWorkers(args.files, args.options, recordPaths(args.files, args.recordDir), static_cast<int>(args.jobs),
               args.timeout, outcomes);
  const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  return reportRun(args, suite, shard, outcomes, elapsed);
}

int scenarioCommand(int argc, char** argv) {
  std::string replayPath, out;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "-o" || a == "--out") && i + 1 < argc)
      out = argv[++i];
    else if (replayPath.empty() && !a.empty() && a[0] != '-')
      replayPath = a;
    else
      return usageError("scenario");
  }
  if (replayPath.empty()) return usageError("scenario");
  try {
    const core::Replay replay = core::readReplay(replayPath);
    script::RunOptions options;
    options.pluginFolders = pluginFolders();
    const script::ScenarioResult outcome = script::runReplay(replayPath, options);
    if (!outcome.passed) {
      std::fprintf(stderr, "%s: the replay does not reproduce, so it makes no scenario: %s\n", replayPath.c_str(),
                   outcome.message.c_str());
      return 1;
    }
    const std::string text = script::scenarioFromReplay(replay, outcome, stem(replayPath) + ".replay");
    if (out.empty()) {
      std::fputs(text.c_str(), stdout);
    } else {
      if (const std::string why = files::saveWhole(out, text, "the scenario"); !why.empty())
        return std::fprintf(stderr, "%s\n", why.c_str()), 1;
      std::fprintf(stderr, "wrote %s (%llu frames, %s)\n", out.c_str(),
                   static_cast<unsigned long long>(replay.frames()), outcome.message.c_str());
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}

script::ScenarioResult runIsolated(const std::string& file, double timeout) {
  script::RunOptions options;
  options.pluginFolders = pluginFolders();
  std::vector<Outcome> outcomes(1);
  runInWorkers({file}, options, {""}, 1, timeout, outcomes);
  return outcomes[0].result;
}

}  // namespace platon::app
