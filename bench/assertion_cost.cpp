// What the peers' run-time checks cost. Debian builds Box2D 2.4.1 and Chipmunk 7.0.3 without NDEBUG,
// so every b2Assert (assert) and cpAssertSoft/cpAssertWarn runs; the numerics benchmarks link those
// builds, as a Debian user does. tools/peers_ndebug.sh builds the same Debian sources with Debian's
// flags twice, as shipped and with -DNDEBUG; this program runs the same peer workloads against the
// system libraries and both builds (child processes, LD_LIBRARY_PATH), the variants taking turns
// round by round, and prints medians with their spread and the cost of the checks.
//
// Usage: assertion_cost [--rounds=N] [--peers=DIR]   (DIR: tools/peers_ndebug.sh's build-peers/)
#include <algorithm>
#include <box2d/b2_distance.h>
#include <box2d/box2d.h>
#include <chipmunk/chipmunk.h>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <functional>
#include <map>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "peers/peer.h"

namespace {

using namespace platon::bench;
using Clock = std::chrono::steady_clock;

Polygon box(double half) { return {{-half, -half}, {half, -half}, {half, half}, {-half, half}}; }

// 150 boxes dropped in a row of columns into a walled pit, 600 frames at 60 Hz: contacts,
// stacking, islands, sleeping (Box2D).
double pile(PeerWorld& w) {
  w.setGravity(0, -9.81);
  w.addSegment(-10, 0, 10, 0);
  w.addSegment(-10, 0, -10, 30);
  w.addSegment(10, 0, 10, 30);
  for (int i = 0; i < 150; ++i) {
    const int row = i / 15, column = i % 15;
    w.addBody(box(0.25), -7.5 + column * 1.0 + 0.1 * (row % 2), 1 + row * 1.2);
  }
  const auto t0 = Clock::now();
  for (int f = 0; f < 600; ++f) w.step(1.0 / 60);
  return std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / 600;
}

// One box run along 1,000 collinear segments at 10 m/s, 2,700 frames: the broad phase and one
// contact pair at a time.
double chain(PeerWorld& w) {
  w.setGravity(0, -9.81);
  for (int i = 0; i < 1000; ++i) w.addSegment(0.5 * i, 0, 0.5 * (i + 1), 0);
  const int body = w.addBody(box(0.25), 1, 0.26);
  const auto t0 = Clock::now();
  for (int f = 0; f < 2700; ++f) {
    w.setVelocity(body, 10, 0);
    w.step(1.0 / 60);
  }
  return std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / 2700;
}

struct Workload {
  const char* name;
  std::function<double()> run;  // ns per step
};

std::vector<Workload> workloads() {
  return {
      {"Box2D pile of 150", [] { return pile(*makeBox2D(8, 3)); }},
      {"Box2D chain of 1000", [] { return chain(*makeBox2D(8, 3)); }},
      {"Chipmunk pile of 150", [] { return pile(*makeChipmunk(10)); }},
      {"Chipmunk chain of 1000", [] { return chain(*makeChipmunk(10)); }},
  };
}

// Which file a symbol came from: proof of which build a child ran.
std::string libraryOf(const void* symbol) {
  Dl_info info;
  return dladdr(symbol, &info) && info.dli_fname ? info.dli_fname : "?";
}

int child() {
  std::printf("lib %s\nlib %s\n", libraryOf(reinterpret_cast<const void*>(&b2ShapeCast)).c_str(),
              libraryOf(reinterpret_cast<const void*>(&cpSpaceNew)).c_str());
  for (const Workload& w : workloads()) std::printf("%s\t%.1f\n", w.name, w.run());
  return 0;
}

struct Variant {
  std::string name, libraryPath;  // empty path: the system's libraries
  std::map<std::string, std::vector<double>> ns{};
  std::vector<std::string> libraries{};
};

// Runs this program as a child with the variant's libraries and collects its figures.
bool runChild(const char* self, Variant& v) {
  int fds[2];
  if (pipe(fds) != 0) return false;
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(fds[1], 1);
    close(fds[0]);
    if (v.libraryPath.empty())
      unsetenv("LD_LIBRARY_PATH");
    else
      setenv("LD_LIBRARY_PATH", v.libraryPath.c_str(), 1);
    execl(self, self, "--child", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  std::string out;
  char buf[4096];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) out.append(buf, static_cast<size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return false;
  v.libraries.clear();
  size_t start = 0;
  for (size_t end; (end = out.find('\n', start)) != std::string::npos; start = end + 1) {
    const std::string line = out.substr(start, end - start);
    if (line.rfind("lib ", 0) == 0) {
      v.libraries.push_back(line.substr(4));
      continue;
    }
    const size_t tab = line.find('\t');
    if (tab != std::string::npos) v.ns[line.substr(0, tab)].push_back(std::atof(line.c_str() + tab + 1));
  }
  return true;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

}  // namespace

int main(int argc, char** argv) {
  // Debian's Chipmunk greets every new space on stderr ("Debug Enabled"): quiet here.
  if (argc > 1 && std::strcmp(argv[1], "--child") == 0) {
    if (!freopen("/dev/null", "w", stderr)) return 1;
    return child();
  }
  int rounds = 7;
  std::string peers = PLATON_SOURCE_DIR "/build-peers";
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--rounds=", 9) == 0)
      rounds = std::max(1, std::atoi(argv[i] + 9));
    else if (std::strncmp(argv[i], "--peers=", 8) == 0)
      peers = argv[i] + 8;
    else
      return std::fprintf(stderr, "usage: %s [--rounds=N] [--peers=DIR]\n", argv[0]), 2;
  }
  if (access((peers + "/ndebug/lib/libbox2d.so.2").c_str(), R_OK) != 0) {
    std::fprintf(stderr, "no NDEBUG builds in %s: run tools/peers_ndebug.sh first\n", peers.c_str());
    return 1;
  }
  std::vector<Variant> variants{{"Debian's libraries", ""},
                                {"same sources, as shipped", peers + "/asserting/lib"},
                                {"same sources, -DNDEBUG", peers + "/ndebug/lib"}};
  for (int r = 0; r < rounds; ++r)
    for (Variant& v : variants)
      if (!runChild("/proc/self/exe", v)) return std::fprintf(stderr, "child failed (%s)\n", v.name.c_str()), 1;

  std::printf("The peers' run-time checks: ns per step, median [min-max] of %d rounds (the variants take turns)\n",
              rounds);
  for (const Variant& v : variants) {
    std::printf("  %-26s", v.name.c_str());
    for (const std::string& lib : v.libraries) std::printf(" %s", lib.c_str());
    std::printf("\n");
  }
  std::printf("\n%-24s", "workload");
  for (const Variant& v : variants) std::printf(" %30s", v.name.c_str());
  std::printf(" %18s\n", "checks cost");
  for (const Workload& w : workloads()) {
    std::printf("%-24s", w.name);
    for (const Variant& v : variants) {
      const std::vector<double>& ns = v.ns.at(w.name);
      std::printf("   %9.0f [%7.0f-%7.0f]", median(ns), *std::min_element(ns.begin(), ns.end()),
                  *std::max_element(ns.begin(), ns.end()));
    }
    // Rounds where the shipped library was slower than the NDEBUG one, and the ratio of medians.
    const std::vector<double>&shipped = variants[0].ns.at(w.name), &ndebug = variants[2].ns.at(w.name);
    int slower = 0;
    for (size_t r = 0; r < shipped.size(); ++r) slower += shipped[r] > ndebug[r];
    std::printf("   %+6.1f%% (%d/%zu)\n", 100 * (median(shipped) / median(ndebug) - 1), slower, shipped.size());
  }
  std::printf(
      "\nchecks cost: Debian's library against -DNDEBUG, ratio of medians; in brackets the rounds in which "
      "Debian's was the slower.\n");
  return 0;
}
