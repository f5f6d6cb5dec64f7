// Work-precision: error against run time on scenes with closed-form answers, for Platon (units per
// metre x frame rates) and its peers Box2D 2.4.1 and Chipmunk 7.0.3 (solver iterations x step
// rates), all through the PeerWorld interface (peers/peer.h; Platon by peers/platon_world.h).
//
// Per engine, setting, step rate and scene: the error against the answer for the engine's own
// resting gap (metres, the largest over all frames unless the scene scores otherwise), the deepest
// penetration of any line (long double, on the reported pose against the engine's own geometry),
// the gap left at the end, the frames a runner got stuck, and the run time of the frame loop: a
// median with its spread over several runs, the settings interleaved within each run so that a busy
// neighbour on a shared machine slows them alike. Platon's World::countOverlaps() is checked after
// every frame of the untimed run.
//
// Usage: work_precision [--csv=FILE] [--markdown=FILE] [--runs=N] [--quick]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "peers/platon_world.h"
#include "report.h"
#include "runs.h"
#include "warps.h"

using namespace platon::bench;
using namespace platon::bench::precision;

namespace {

// Fresh worlds run the scene until a timed sample lasts 20 ms (at most 1000 of them).
int repeatsFor(double secondsPerRun) {
  return std::clamp(static_cast<int>(std::ceil(0.02 / std::max(secondsPerRun, 1e-9))), 1, 1000);
}

std::vector<Engine> engines(const std::vector<double>& rates) {
  std::vector<Engine> out;
  for (const double hz : rates) {
    for (const int upm : {64, 256, 1024, 4096})
      out.push_back({"Platon", std::to_string(upm) + "u/m", hz, [=] { return std::make_unique<PlatonWorld>(upm, hz); },
                     1.0 / upm, upm == 1024 && hz == 60});
    for (const auto& iterations : std::vector<std::pair<int, int>>{{1, 1}, {3, 1}, {8, 3}, {20, 8}}) {
      const int v = iterations.first, p = iterations.second;  // plain variables: the lambda captures them
      out.push_back({"Box2D 2.4.1", "v" + std::to_string(v) + "p" + std::to_string(p), hz,
                     [=] { return makeBox2D(v, p); }, 0, v == 8 && hz == 60});
    }
    for (const int it : {1, 5, 10, 30})
      out.push_back(
          {"Chipmunk 7.0.3", "it" + std::to_string(it), hz, [=] { return makeChipmunk(it); }, 0, it == 10 && hz == 60});
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string csv = "docs/work_precision.csv", markdown;
  bool quick = false;
  int runs = 5;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--csv=", 6) == 0)
      csv = argv[i] + 6;
    else if (std::strncmp(argv[i], "--markdown=", 11) == 0)
      markdown = argv[i] + 11;
    else if (std::strncmp(argv[i], "--runs=", 7) == 0)
      runs = std::max(1, std::atoi(argv[i] + 7));
    else if (std::strcmp(argv[i], "--quick") == 0)
      quick = true, runs = 2;
    else {
      std::fprintf(stderr, "usage: %s [--csv=FILE] [--markdown=FILE] [--runs=N] [--quick]\n", argv[0]);
      return 2;
    }
  }
  const std::vector<double> rates{30, 60, 120, 240};
  const std::vector<Engine> all = engines(rates);
  const std::vector<SceneSpec> scenes = allScenes(quick ? 10000 : 1000000);

  std::printf("Work-precision: g = %.2f m/s^2, a %.1f m box; %d timed runs per setting\n", kGravity, 2 * kHalf, runs);
  std::printf("\nOwn resting gaps (a box placed exactly on a floor, after 20 s):\n");
  std::vector<double> gaps;
  for (const Engine& e : all) {
    gaps.push_back(restingGap(e));
    std::printf("  %-15s %-7s %4.0f Hz  %+.4g m\n", e.engine.c_str(), e.setting.c_str(), e.hz, gaps.back());
  }

  std::vector<Row> rows;
  Titles titles;
  for (const SceneSpec& spec : scenes) {
    std::printf("\n%s: %s\n", spec.name.c_str(), spec.title.c_str());
    std::fflush(stdout);
    titles.names.push_back(spec.name), titles.lines.push_back(spec.title);
    const size_t first = rows.size();
    std::vector<Scene> built;
    std::vector<int> repeats;
    for (size_t k = 0; k < all.size(); ++k) {
      rows.push_back(measure(all[k], spec, gaps[k]));
      built.push_back(spec.make(gaps[k]));
      repeats.push_back(repeatsFor(timeScene(all[k], built.back(), 1)));
    }
    for (int run = 0; run < runs; ++run)
      for (size_t k = 0; k < all.size(); ++k)
        rows[first + k].runtimes.push_back(timeScene(all[k], built[k], repeats[k]));
    for (size_t k = first; k < rows.size(); ++k) printRow(rows[k]);
  }
  for (const bool walk : {true, false})
    for (const int degrees : {90, 120, 72 + 180}) {
      const WarpScene scene{degrees, walk};
      std::printf("\n%s (%g s, Platon only)\n", scene.name().c_str(), kWarpSeconds);
      const size_t first = rows.size();
      for (const double hz : rates)
        for (const int upm : {64, 256, 1024, 4096}) rows.push_back(measureWarp(scene, upm, hz));
      for (int run = 0; run < runs; ++run)
        for (size_t k = first; k < rows.size(); ++k) {
          const int upm = std::atoi(rows[k].setting.c_str());
          rows[k].runtimes.push_back(timeWarp(scene, upm, 1 / rows[k].dt));
        }
      for (size_t k = first; k < rows.size(); ++k) printRow(rows[k]);
    }
  writeCsv(rows, csv);
  const std::string summary = summaryMarkdown(rows, titles, runs);
  std::printf("\n%s\nwrote %s (%zu rows)\n", summary.c_str(), csv.c_str(), rows.size());
  if (!markdown.empty()) {
    std::ofstream(markdown) << summary;
    std::printf("wrote %s\n", markdown.c_str());
  }
}
