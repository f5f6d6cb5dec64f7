// Runs scenarios, in parallel worker processes with -j. Each worker runs its share and writes one
// record per scenario to a pipe; a worker that outlives the time limit (a trusted script's
// endless compiled loop cannot be stopped from inside) is killed and its unfinished scenarios
// fail. Results print in the order the scenarios were given: the same output at any -j.
#include "run_command.h"

#include "engine_registry.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "platon/script/scenario.h"

namespace platon::app {
namespace {

struct Outcome {
  bool done = false;
  script::ScenarioResult result;
};

// One record: index, passed, frames, seconds, hash, message length, message.
void writeRecord(int fd, size_t index, const script::ScenarioResult& r) {
  std::string text = std::to_string(index) + " " + (r.passed ? "1" : "0") + " " + std::to_string(r.frames) + " " +
                     std::to_string(r.seconds) + " " + (r.hash.empty() ? "-" : r.hash) + " " +
                     std::to_string(r.message.size()) + "\n" + r.message;
  for (size_t sent = 0; sent < text.size();) {
    const ssize_t n = write(fd, text.data() + sent, text.size() - sent);
    if (n <= 0) return;
    sent += static_cast<size_t>(n);
  }
}

void readRecords(const std::string& data, std::vector<Outcome>& out) {
  size_t pos = 0;
  while (pos < data.size()) {
    const size_t eol = data.find('\n', pos);
    if (eol == std::string::npos) return;
    size_t index = 0, length = 0;
    int passed = 0;
    unsigned long long frames = 0;
    double seconds = 0;
    char hash[32] = {};
    if (std::sscanf(data.c_str() + pos, "%zu %d %llu %lf %31s %zu", &index, &passed, &frames, &seconds, hash, &length) != 6) return;
    if (eol + 1 + length > data.size() || index >= out.size()) return;
    Outcome& o = out[index];
    o.done = true;
    o.result.passed = passed != 0;
    o.result.frames = frames;
    o.result.seconds = seconds;
    o.result.hash = std::strcmp(hash, "-") == 0 ? "" : hash;
    o.result.message = data.substr(eol + 1, length);
    pos = eol + 1 + length;
  }
}

std::string xmlEscape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

void writeJunit(const std::string& path, const std::vector<std::string>& names, const std::vector<Outcome>& outcomes,
                double seconds) {
  std::ofstream out(path);
  size_t failures = 0;
  for (const Outcome& o : outcomes) failures += o.result.passed ? 0 : 1;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuite name=\"platon scenarios\" tests=\"" << names.size()
      << "\" failures=\"" << failures << "\" time=\"" << seconds << "\">\n";
  for (size_t i = 0; i < names.size(); ++i) {
    const script::ScenarioResult& r = outcomes[i].result;
    out << "  <testcase classname=\"scenario\" name=\"" << xmlEscape(names[i]) << "\" time=\"" << r.seconds << "\"";
    if (r.passed) {
      out << "/>\n";
    } else {
      out << ">\n    <failure message=\"" << xmlEscape(r.message.substr(0, r.message.find('\n'))) << "\">"
          << xmlEscape(r.message) << "</failure>\n  </testcase>\n";
    }
  }
  out << "</testsuite>\n";
}

int usage() {
  std::fprintf(stderr,
               "usage: platon run [-j N] [--junit report.xml] [--timeout seconds] [--trace frames]\n"
               "                  [--record dir] [--hash-every frames] scenario.lua|run.replay...\n");
  return 2;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// "tests/scenarios/walk.lua" -> "walk"
std::string stem(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') + 1);
  return name.substr(0, name.find_last_of('.'));
}

// One file: a scenario or a replay; with a record folder, its run is written there as a replay.
script::ScenarioResult runOne(const std::string& file, const script::RunOptions& options, const std::string& recordDir) {
  script::ScenarioResult r = endsWith(file, ".replay") ? script::runReplay(file, options) : script::runScenario(file, options);
  if (!recordDir.empty() && r.recorded) {
    const std::string out = recordDir + "/" + stem(file) + ".replay";
    try {
      core::writeReplay(*r.recorded, out);
      r.message += " (recorded to " + out + ")";
    } catch (const std::exception& e) {
      r.passed = false;
      r.message = e.what();
    }
  }
  return r;
}

}  // namespace

int runCommand(int argc, char** argv) {
  int jobs = 1;
  double timeout = 600;
  std::string junit;
  script::RunOptions options;
  options.pluginFolders = pluginFolders();
  std::string recordDir;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-j" && i + 1 < argc) jobs = std::atoi(argv[++i]);
    else if (a.rfind("-j", 0) == 0 && a.size() > 2) jobs = std::atoi(a.c_str() + 2);
    else if (a == "--junit" && i + 1 < argc) junit = argv[++i];
    else if (a == "--timeout" && i + 1 < argc) timeout = std::atof(argv[++i]);
    else if (a == "--trace" && i + 1 < argc) options.traceEvery = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--record" && i + 1 < argc) recordDir = argv[++i], options.record = true;
    else if (a == "--hash-every" && i + 1 < argc) options.hashEvery = std::strtoull(argv[++i], nullptr, 10);
    else if (!a.empty() && a[0] == '-') return usage();
    else files.push_back(a);
  }
  if (files.empty() || jobs < 1 || jobs > 256 || !(timeout > 0)) return usage();
  const auto start = std::chrono::steady_clock::now();
  std::vector<Outcome> outcomes(files.size());

  if (jobs == 1) {
    for (size_t i = 0; i < files.size(); ++i) outcomes[i] = {true, runOne(files[i], options, recordDir)};
  } else {
    struct Worker {
      pid_t pid;
      int fd;
      std::string data;
      bool open = true;
    };
    std::vector<Worker> workers;
    std::fflush(nullptr);
    for (int w = 0; w < jobs && static_cast<size_t>(w) < files.size(); ++w) {
      int fds[2];
      if (pipe(fds) != 0) return std::perror("pipe"), 1;
      const pid_t pid = fork();
      if (pid < 0) return std::perror("fork"), 1;
      if (pid == 0) {
        close(fds[0]);
        for (size_t i = static_cast<size_t>(w); i < files.size(); i += static_cast<size_t>(jobs))
          writeRecord(fds[1], i, runOne(files[i], options, recordDir));
        close(fds[1]);
        _exit(0);
      }
      close(fds[1]);
      workers.push_back({pid, fds[0], {}});
    }
    // Read every worker's pipe until all close or the time limit passes.
    for (;;) {
      bool anyOpen = false;
      for (Worker& w : workers) {
        if (!w.open) continue;
        char buffer[65536];
        fd_set set;
        FD_ZERO(&set);
        FD_SET(w.fd, &set);
        timeval zero{0, 20000};
        if (select(w.fd + 1, &set, nullptr, nullptr, &zero) > 0) {
          const ssize_t n = read(w.fd, buffer, sizeof buffer);
          if (n > 0) w.data.append(buffer, static_cast<size_t>(n));
          else w.open = false;
        }
        anyOpen = anyOpen || w.open;
      }
      if (!anyOpen) break;
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeout) {
        for (Worker& w : workers)
          if (w.open) kill(w.pid, SIGKILL);
        break;
      }
    }
    for (Worker& w : workers) {
      close(w.fd);
      int status = 0;
      waitpid(w.pid, &status, 0);
      readRecords(w.data, outcomes);
    }
  }

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int failed = 0;
  for (size_t i = 0; i < files.size(); ++i) {
    Outcome& o = outcomes[i];
    if (!o.done) {
      o.result = {};
      o.result.message = "not finished within the time limit of " + std::to_string(timeout) + " s (killed)";
    }
    const script::ScenarioResult& r = o.result;
    if (r.passed) {
      std::printf("PASS %s: %s, %llu frames, %.3f s, hash %s\n", files[i].c_str(), r.message.c_str(),
                  static_cast<unsigned long long>(r.frames), r.seconds, r.hash.c_str());
    } else {
      ++failed;
      std::printf("FAIL %s: %s\n", files[i].c_str(), r.message.c_str());
    }
  }
  std::printf("%zu scenarios, %d failed, %.2f s with -j %d\n", files.size(), failed, seconds, jobs);
  if (!junit.empty()) writeJunit(junit, files, outcomes, seconds);
  return failed ? 1 : 0;
}

int scenarioCommand(int argc, char** argv) {
  std::string replayPath, out;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "-o" || a == "--out") && i + 1 < argc) out = argv[++i];
    else if (replayPath.empty() && !a.empty() && a[0] != '-') replayPath = a;
    else return std::fprintf(stderr, "usage: platon scenario run.replay [-o scenario.lua]\n"), 2;
  }
  if (replayPath.empty()) return std::fprintf(stderr, "usage: platon scenario run.replay [-o scenario.lua]\n"), 2;
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
      std::ofstream file(out, std::ios::binary | std::ios::trunc);
      if (!(file << text).flush()) return std::fprintf(stderr, "%s: cannot write\n", out.c_str()), 1;
      std::fprintf(stderr, "wrote %s (%llu frames, %s)\n", out.c_str(), static_cast<unsigned long long>(replay.frames()),
                   outcome.message.c_str());
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}

}  // namespace platon::app
