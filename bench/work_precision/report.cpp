// Output of work_precision (report.h).
#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>

namespace platon::bench::precision {
namespace {

constexpr const char* kPeers[] = {"Box2D 2.4.1", "Chipmunk 7.0.3"};
constexpr const char* kEngines[] = {"Platon", "Box2D 2.4.1", "Chipmunk 7.0.3"};

std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

// A length for people: 0, 4.2 µm, 1.4 mm, 12.3 cm, 3.1 m; below 1 µm in scientific notation.
std::string length(double m) {
  if (std::isnan(m)) return "-";
  const double a = std::fabs(m);
  if (a == 0) return "0";
  if (a < 1e-6) return format("%.2g m", m);
  if (a < 1e-3) return format("%.3g µm", m * 1e6);
  if (a < 1e-2) return format("%.2g mm", m * 1e3);
  if (a < 1) return format("%.3g cm", m * 1e2);
  return format("%.3g m", m);
}

std::string duration(double s) {
  if (s < 1e-3) return format("%.3g µs", s * 1e6);
  if (s < 1) return format("%.3g ms", s * 1e3);
  return format("%.3g s", s);
}

// "28.1 µs [27.9-31.0]": the median and the spread over the runs, in the median's unit.
std::string timing(const Row& r) {
  const double m = r.median(), scale = m < 1e-3 ? 1e6 : m < 1 ? 1e3 : 1;
  return duration(m) + format(" [%.3g", r.low() * scale) + format("-%.3g]", r.high() * scale);
}

// How Platon fares against one peer setting in one run: Platon's best error among its settings
// that ran in no more time in that run.
enum class Outcome { Met, Tie, Better, Worse, Slower };

// Two errors tie when they agree within 10% or within 1 µm: nothing to choose between them.
bool tie(double a, double b) { return std::fabs(a - b) <= std::max(1e-6, 0.1 * std::max(a, b)); }

Outcome judge(double best, double peer) {
  if (std::isinf(best)) return Outcome::Slower;
  if (tie(best, peer)) return Outcome::Tie;
  if (best <= 0.1 * peer) return Outcome::Met;
  return best < peer ? Outcome::Better : Outcome::Worse;
}

double bestPlaton(const std::vector<const Row*>& platon, double runtime, size_t run) {
  double best = std::numeric_limits<double>::infinity();
  for (const Row* q : platon)
    if (q->runtimes[run] <= runtime) best = std::min(best, q->error);
  return best;
}

// "16 of 16" when every run agrees, "14-16 of 16" otherwise.
std::string countRange(const std::vector<int>& perRun, size_t of) {
  const auto [lo, hi] = std::minmax_element(perRun.begin(), perRun.end());
  if (*lo == *hi) return std::to_string(*lo) + " of " + std::to_string(of);
  return std::to_string(*lo) + "-" + std::to_string(*hi) + " of " + std::to_string(of);
}

std::map<std::string, std::vector<const Row*>> byScene(const std::vector<Row>& rows, const char* engine) {
  std::map<std::string, std::vector<const Row*>> out;
  for (const Row& r : rows)
    if (r.engine == engine) out[r.scene].push_back(&r);
  return out;
}

const Row* usualRow(const std::vector<Row>& rows, const char* engine, const std::string& scene) {
  for (const Row& r : rows)
    if (r.engine == engine && r.scene == scene && r.usual) return &r;
  return nullptr;
}

void goalTable(std::ostringstream& md, const std::vector<Row>& rows, const Titles& titles, const char* peer, int runs) {
  const auto platon = byScene(rows, "Platon"), other = byScene(rows, peer);
  md << "\n### Against " << peer << "\n\n"
     << "For each of the peer's settings and each of the " << runs
     << " runs, Platon's best error among its settings that ran in no more time in that run. A cell "
        "counts settings; where runs disagree, it gives the range over the runs.\n\n"
     << "| scene | goal met (<= 1/10) | tie | better, short of the goal | worse | no Platon setting as fast | "
        "goal met for every setting | at the usual settings |\n|---|---|---|---|---|---|---|---|\n";
  int scenesMet = 0, scenes = 0;
  for (const std::string& scene : titles.names) {
    const auto it = other.find(scene);
    if (it == other.end() || !platon.count(scene)) continue;
    const std::vector<const Row*>& peerRows = it->second;
    std::map<Outcome, std::vector<int>> counts;
    for (const Outcome o : {Outcome::Met, Outcome::Tie, Outcome::Better, Outcome::Worse, Outcome::Slower})
      counts[o].assign(static_cast<size_t>(runs), 0);
    int runsAllMet = 0;
    for (size_t run = 0; run < static_cast<size_t>(runs); ++run) {
      bool allMet = true;
      for (const Row* p : peerRows) {
        const Outcome o = judge(bestPlaton(platon.at(scene), p->runtimes[run], run), p->error);
        ++counts[o][run];
        allMet = allMet && o == Outcome::Met;
      }
      runsAllMet += allMet;
    }
    // At the usual settings (60 Hz), by the median run times.
    std::string atUsual = "-";
    const Row *p = usualRow(rows, peer, scene), *q = usualRow(rows, "Platon", scene);
    if (p && q) {
      const Outcome o = judge(q->error, p->error);
      atUsual = length(q->error) + " vs " + length(p->error) +
                (o == Outcome::Tie ? " (tie)"
                 : p->error > 0    ? format(" (%.2g)", q->error / p->error)
                                   : "");
    }
    ++scenes;
    scenesMet += runsAllMet == runs;
    md << "| " << scene << " | " << countRange(counts[Outcome::Met], peerRows.size()) << " | "
       << countRange(counts[Outcome::Tie], peerRows.size()) << " | "
       << countRange(counts[Outcome::Better], peerRows.size()) << " | "
       << countRange(counts[Outcome::Worse], peerRows.size()) << " | "
       << countRange(counts[Outcome::Slower], peerRows.size()) << " | " << runsAllMet << " of " << runs << " runs | "
       << atUsual << " |\n";
  }
  md << "\nThe goal met for every setting in every run (ties and losses excluded): " << scenesMet << " of " << scenes
     << " scenes.\n";
}

// Platon alone: per edge, the settings that got stuck and the largest error of the others.
void warpTable(std::ostringstream& md, const std::vector<Row>& rows) {
  std::map<std::string, std::vector<const Row*>> warps;
  std::vector<std::string> order;
  for (const Row& r : rows)
    if (r.scene.starts_with("warp")) {
      if (!warps.count(r.scene)) order.push_back(r.scene);
      warps[r.scene].push_back(&r);
    }
  if (order.empty()) return;
  md << "\n### Warps (Platon only)\n\n"
     << "| scene | settings with stuck frames | largest error of the others | at 1024 units/m, 60 Hz |\n"
        "|---|---|---|---|\n";
  for (const std::string& scene : order) {
    int stuck = 0;
    double worst = 0;
    std::string usual = "-";
    for (const Row* r : warps[scene]) {
      if (r->stuck > 0)
        ++stuck;
      else
        worst = std::max(worst, r->error);
      if (r->setting == "1024u/m" && std::lround(1 / r->dt) == 60) usual = length(r->error) + "; " + timing(*r);
    }
    md << "| " << scene << " | " << stuck << " of " << warps[scene].size() << " | " << length(worst) << " | " << usual
       << " |\n";
  }
}

}  // namespace

void printRow(const Row& r) {
  std::printf(
      "  %-15s %-7s %4.0f Hz  error %10.3e m  pen %9.3e m  gap %9.3e m  rest gap %9.3e m  stuck %5ld  "
      "%9.3e s [%9.3e-%9.3e]",
      r.engine.c_str(), r.setting.c_str(), 1 / r.dt, r.error, r.penetration, r.gap, r.restGap, r.stuck, r.median(),
      r.low(), r.high());
  if (!std::isnan(r.extra)) std::printf("  extra %+.4f s", r.extra);
  std::printf("\n");
}

void writeCsv(const std::vector<Row>& rows, const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) {
    std::perror(path.c_str());
    std::exit(1);
  }
  // The first nine columns are the plot's (tools/work_precision.gp).
  std::fprintf(f,
               "engine,setting,scene,dt,error_m,penetration_m,gap_m,stuck_frames,runtime_s,runtime_min_s,"
               "runtime_max_s,rest_gap_m,extra\n");
  for (const Row& r : rows)
    std::fprintf(f, "%s,%s,%s,%.9g,%.6g,%.6g,%.6g,%ld,%.6g,%.6g,%.6g,%.6g,%.6g\n", r.engine.c_str(), r.setting.c_str(),
                 r.scene.c_str(), r.dt, r.error, r.penetration, r.gap, r.stuck, r.median(), r.low(), r.high(),
                 r.restGap, r.extra);
  std::fclose(f);
}

std::string summaryMarkdown(const std::vector<Row>& rows, const Titles& titles, int runs) {
  std::ostringstream md;
  md << "<!-- generated by build/bench/work_precision --markdown; do not edit -->\n";
  md << "### Each engine's own rest pose\n\n"
     << "A box placed exactly on a floor and left for 20 s ends this far above it: the resting gap each "
        "engine is designed to keep. Contact scenes start every engine at its own rest pose and score it "
        "against the answer for its own contact height.\n\n"
     << "| engine | at the usual setting, 60 Hz | over all settings and rates |\n|---|---|---|\n";
  for (const char* engine : kEngines) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, usual = std::nan("");
    for (const Row& r : rows)
      if (r.engine == engine && r.scene == "rest") {
        lo = std::min(lo, r.restGap), hi = std::max(hi, r.restGap);
        if (r.usual) usual = r.restGap;
      }
    md << "| " << engine << " | " << length(usual) << " | " << length(lo) << " to " << length(hi) << " |\n";
  }

  md << "\n### Key figures at the usual settings\n\n"
     << "60 Hz; Platon 1024 units/m, Box2D v8p3 (its default), Chipmunk 10 iterations (its default). Each "
        "cell: error; run time of the scene, median [min-max] over "
     << runs << " runs; deepest penetration (pen.) and gap to the nearest line at the end where there are lines.\n\n"
     << "| scene | Platon | Box2D 2.4.1 | Chipmunk 7.0.3 |\n|---|---|---|---|\n";
  for (size_t i = 0; i < titles.names.size(); ++i) {
    const std::string& scene = titles.names[i];
    md << "| " << titles.lines[i];
    for (const char* engine : kEngines) {
      const Row* r = usualRow(rows, engine, scene);
      if (!r) {
        md << " | -";
        continue;
      }
      md << " | " << length(r->error) << "; " << timing(*r);
      if (!std::isnan(r->gap)) md << "; pen. " << length(r->penetration) << ", gap " << length(r->gap);
      if (!std::isnan(r->extra))
        md << "; " << (scene == "landing" ? "lands " : "apex time ") << format("%+.3g s", r->extra);
      if (r->stuck > 0) md << "; stuck " << r->stuck << " frames";
    }
    md << " |\n";
  }

  md << "\n### The goal: at equal run time, Platon's error at most 1/10 of the peer's\n";
  for (const char* peer : kPeers) goalTable(md, rows, titles, peer, runs);

  warpTable(md, rows);

  size_t overlaps = 0;
  std::map<std::string, double> deepest;
  for (const Row& r : rows) {
    deepest[r.engine] = std::max(deepest[r.engine], r.penetration);
    if (r.engine == "Platon") overlaps += r.overlaps;
  }
  md << "\nDeepest penetration over all scenes and settings:";
  for (const char* engine : kEngines) md << " " << engine << " " << length(deepest[engine]) << ";";
  md << " Platon's World::countOverlaps() summed over every frame of every run: " << overlaps << ".\n";
  return md.str();
}

}  // namespace platon::bench::precision
