// Loading levels. (1) A level of 10^5 segments on an icosahedron (every face full of random
// segments): reading, parsing, checking and building it, against the physics library's own
// work for the same lines (the map parts, their warps, MapPart::lines in bulk and initialize(),
// from segments already in memory): the loader must not dominate. Time: median (min-max) of the
// runs, interleaved; memory: the peak heap each needs (C++ allocations counted).
// (2) Every shipped level, as the game loads it (file to built world; mesh levels through the
// meshes system's reader): goal <= 10 ms.
// (3) `platon check` (parse, stage, checkLevel with its reachability search) of cube levels of
// 10^5 and 10^6 segments at face sizes 4,096 and 2^24: one-unit posts on a lattice, random short
// segments, and floors drawn in one-unit pieces (each piece twice); the start on face 0, the
// goal on face 2, so that the search runs. Goal: well under a second each.
//
// Usage: level_load [--runs=N] [--segments=N] [--check-only]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <malloc.h>
#include <new>
#include <string>
#include <unistd.h>

#include "mesh_system.h"
#include "platon/core/scene.h"
#include "platon/stage/level.h"
#include "platon/stage/level_check.h"
#include "platon/testing/rng.h"
#include "spread.h"

using namespace platon;
using Clock = std::chrono::steady_clock;

namespace {

// Heap bytes in use, and their peak, counted by the global operator new and delete below.
size_t heapNow = 0, heapPeak = 0;

}  // namespace

void* operator new(size_t size) {
  void* p = std::malloc(size);
  if (!p) throw std::bad_alloc();
  heapNow += malloc_usable_size(p);
  heapPeak = std::max(heapPeak, heapNow);
  return p;
}
void operator delete(void* p) noexcept {
  if (p) heapNow -= malloc_usable_size(p);
  std::free(p);
}
void operator delete(void* p, size_t) noexcept { operator delete(p); }

namespace {

// The peak heap growth while `work` runs, in kB (every C++ allocation counted; assimp's and the
// C library's own malloc calls are not, and the big level uses neither).
long memoryOf(const std::function<void()>& work) {
  const size_t before = heapNow;
  heapPeak = heapNow;
  work();
  return static_cast<long>((heapPeak - before) / 1024);
}

double millisecondsOf(const std::function<void()>& work) {
  const auto start = Clock::now();
  work();
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// An icosahedron level with `count` random segments spread over its faces (inside each face).
std::string bigLevel(int count) {
  const int32_t edge = 1 << 16;
  const stage::Stage s = stage::platonicStage(stage::Solid::Icosahedron, edge);
  testing::Rng rng{11};
  std::string text = "ICOSAHEDRON\n0 32768 20000\n1 32768 20000\n" + std::to_string(edge) + "\n";
  const int perFace = count / static_cast<int>(s.faceCount());
  for (size_t f = 0; f < s.faceCount(); ++f) {
    text += "%\n";
    const int here = perFace + (f < static_cast<size_t>(count) % s.faceCount() ? 1 : 0);
    for (int i = 0; i < here; ++i) {
      // A short segment around a random point inside the triangle (away from start and goal).
      double u = 1, v = 1;
      while (u + v > 0.9) u = rng.uniform(0.05, 0.9), v = rng.uniform(0.05, 0.9);
      const auto& c = s.faces[f].corners;
      const double x = c[0].x + u * (c[1].x - c[0].x) + v * (c[2].x - c[0].x);
      const double y = c[0].y + u * (c[1].y - c[0].y) + v * (c[2].y - c[0].y);
      if (f <= 1 && std::hypot(x - 32768, y - 20000) < 3000) {
        --i;
        continue;
      }
      const double a = rng.uniform(0, 6.283), len = rng.uniform(20, 120);
      text += std::to_string(std::lround(x)) + " " + std::to_string(std::lround(y)) + " " +
              std::to_string(std::lround(x + len * std::cos(a))) + " " +
              std::to_string(std::lround(y + len * std::sin(a))) + "\n";
    }
  }
  return text;
}

// The loader's phases, in ms, of the latest loadFile.
struct Phases {
  double read = 0, parse = 0, stage = 0, check = 0, build = 0;
};
Phases phases;

void loadFile(const std::string& path) {
  // As the engine does (core::loadScene): the text lives only while it is parsed.
  auto t0 = Clock::now(), t1 = t0;
  const stage::Level level = [&] {
    const std::string text = stage::readLevelFile(path);
    t1 = Clock::now();
    return stage::parseLevel(text, path);
  }();
  auto t2 = Clock::now();
  stage::Stage s = stage::platonicStageOf(level);
  auto t3 = Clock::now();
  stage::checkLevelOnStage(level, s);
  auto t4 = Clock::now();
  physics::World world;
  stage::buildLevel(level, s, world, 0, 22938);
  for (size_t f = 0; f < s.faceCount(); ++f) world.mapPart(s.part(f)).initialize();
  auto t5 = Clock::now();
  auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  phases = {ms(t0, t1), ms(t1, t2), ms(t2, t3), ms(t3, t4), ms(t4, t5)};
}

struct Lines {
  stage::Stage stage;
  std::vector<std::vector<physics::Segment>> perFace;
};

void physicsOnly(const Lines& in) {
  physics::World world;
  stage::Stage s = in.stage;
  stage::addStageToWorld(s, world, 0);
  for (size_t f = 0; f < s.faceCount(); ++f) {
    physics::MapPart& part = world.mapPart(s.part(f));
    part.reserve(part.lines().size() + in.perFace[f].size());
    part.lines(in.perFace[f]);
    part.initialize();
  }
}

// A cube level of `count` segments of one kind spread over its six faces (inside [400, size -
// 400] on each, clear of the start at (150, 150) on face 0 and the goal at (size - 200, size -
// 200) on face 2, which the border strips join).
std::string checkLevelText(const std::string& kind, int count, int32_t size) {
  testing::Rng rng{7};
  std::string text = "HEXAHEDRON\n0 150 150\n2 " + std::to_string(size - 200) + " " + std::to_string(size - 200) +
                     "\n" + std::to_string(size) + "\n";
  auto segment = [&](long x0, long y0, long x1, long y1) {
    text += std::to_string(x0) + " " + std::to_string(y0) + " " + std::to_string(x1) + " " + std::to_string(y1) + "\n";
  };
  const int perFace = count / 6;
  const long lo = 400, span = size - 800;
  for (int f = 0; f < 6; ++f) {
    text += "%\n";
    if (kind == "posts") {  // one unit each, on a square lattice
      const long k = static_cast<long>(std::sqrt(perFace)) + 1;
      for (long c = 0; c < perFace; ++c)
        segment(lo + (c / k) * span / k, lo + (c % k) * span / k, lo + (c / k) * span / k + 1, lo + (c % k) * span / k);
    } else if (kind == "random") {  // 10 to 400 units long, any way
      for (int c = 0; c < perFace; ++c) {
        const double a = rng.uniform(0, 6.283), length = rng.uniform(10, 400);
        const long x0 = lo + long(rng.uniform(0, double(span - 400))) + 200,
                   y0 = lo + long(rng.uniform(0, double(span - 400))) + 200;
        const long x1 = x0 + std::lround(length * std::cos(a)), y1 = y0 + std::lround(length * std::sin(a));
        if (x1 == x0 && y1 == y0)
          segment(x0, y0, x0 + 1, y0);
        else
          segment(x0, y0, x1, y1);
      }
    } else {  // "pieces": floors across the face, 400 units apart at most, drawn in one-unit pieces, each twice
      const long rows = std::max(1L, std::min(span / 400, long(perFace / 2) / std::max(1L, span) + 1));
      const long perRow = perFace / 2 / rows + 1;
      for (long r = 0, c = 0; r < rows && c < perFace; ++r)
        for (long i = 0; i < perRow && c < perFace; ++i, c += 2) {
          const long x = lo + i % span, y = lo + r * (span / rows);
          segment(x, y, x + 1, y);
          segment(x, y, x + 1, y);
        }
    }
  }
  return text;
}

// What `platon check` takes for the levels of (3), in ms, and what it says.
void checkSpeed(int runs) {
  std::printf(
      "platon check of cube levels (parse, stage, check with the reachability search), %d runs, median (min-max):\n",
      runs);
  for (const int count : {100000, 1000000})
    for (const int32_t size : {4096, 1 << 24})
      for (const std::string kind : {"posts", "random", "pieces"}) {
        const std::string text = checkLevelText(kind, count, size);
        std::vector<double> times;
        std::string said;
        for (int r = 0; r < runs; ++r)
          times.push_back(millisecondsOf([&] {
            const stage::Level level = stage::parseLevel(text, "check.level");
            const stage::CheckReport report = stage::checkLevel(level, stage::platonicStageOf(level));
            said = !report.errors.empty() ? "error: " + report.errors[0].message.substr(0, 40) : "ok";
            for (const auto& w : report.warnings)
              if (w.message.find("could not decide") != std::string::npos) said = "undecided";
          }));
        std::printf("  %7d %-6s at size %8d: %s ms  (%s)\n", count, kind.c_str(), size,
                    bench::Spread::of(times).show("%.0f").c_str(), said.c_str());
      }
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 9, segments = 100000;
  bool checkOnly = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--runs=", 7) == 0) runs = std::atoi(argv[i] + 7);
    if (std::strncmp(argv[i], "--segments=", 11) == 0) segments = std::atoi(argv[i] + 11);
    if (std::strcmp(argv[i], "--check-only") == 0) checkOnly = true;
  }
  if (checkOnly) {
    checkSpeed(runs);
    return 0;
  }
  const std::string path = "/tmp/platon_level_load_" + std::to_string(getpid()) + ".level";
  std::ofstream(path) << bigLevel(segments);
  const stage::Level level = stage::parseLevel(stage::readLevelFile(path), path);
  Lines lines{stage::platonicStageOf(level), {}};
  for (const auto& face : level.faces) {
    lines.perFace.emplace_back();
    for (const auto& l : face.lines) lines.perFace.back().push_back({l.a, l.b});
  }
  std::vector<double> loader, physics, parse;
  std::vector<double> readMs, parseMs, stageMs, checkMs, buildMs;
  for (int r = 0; r < runs; ++r) {
    loader.push_back(millisecondsOf([&] { loadFile(path); }));
    readMs.push_back(phases.read), parseMs.push_back(phases.parse), stageMs.push_back(phases.stage);
    checkMs.push_back(phases.check), buildMs.push_back(phases.build);
    physics.push_back(millisecondsOf([&] { physicsOnly(lines); }));
    parse.push_back(millisecondsOf([&] { (void)stage::parseLevel(stage::readLevelFile(path), path); }));
  }
  std::vector<double> ratio;
  for (int r = 0; r < runs; ++r) ratio.push_back(loader[static_cast<size_t>(r)] / physics[static_cast<size_t>(r)]);
  const long loaderKb = memoryOf([&] { loadFile(path); });
  const long physicsKb = memoryOf([&] { physicsOnly(lines); });
  std::printf("level of %d segments on an icosahedron (%zu bytes), %d runs, median (min-max):\n", segments,
              static_cast<size_t>(std::filesystem::file_size(path)), runs);
  std::printf("  file -> built world (read, parse, check, build, initialize): %s ms, peak heap %ld kB\n",
              bench::Spread::of(loader).show("%.1f").c_str(), loaderKb);
  std::printf("    read %s, parse %s, stage %s, check %s, build + initialize %s ms\n",
              bench::Spread::of(readMs).show("%.2f").c_str(), bench::Spread::of(parseMs).show("%.2f").c_str(),
              bench::Spread::of(stageMs).show("%.2f").c_str(), bench::Spread::of(checkMs).show("%.2f").c_str(),
              bench::Spread::of(buildMs).show("%.2f").c_str());
  std::printf("    read + parse on their own:                               %s ms\n",
              bench::Spread::of(parse).show("%.1f").c_str());
  std::printf("  physics alone (parts, warps, lines in bulk, initialize):   %s ms, peak heap %ld kB\n",
              bench::Spread::of(physics).show("%.1f").c_str(), physicsKb);
  std::printf("  ratio loader / physics: %s (time), %.2f (memory)\n", bench::Spread::of(ratio).show("%.2f").c_str(),
              physicsKb > 0 ? double(loaderKb) / double(physicsKb) : 0.0);
  std::remove(path.c_str());

  // Every shipped level, as the game loads it: file to a built, initialized world.
  std::printf("\nshipped levels, file to built world, %d runs (goal <= 10 ms):\n", runs);
  mesh::MeshSystem reader;
  bool allMet = true;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(PLATON_SOURCE_ROOT) + "/levels")) {
    if (entry.path().extension() != ".level") continue;
    const std::string file = entry.path().string();
    std::vector<double> times;
    for (int r = 0; r < runs; ++r)
      times.push_back(millisecondsOf([&] {
        const stage::Level l = stage::parseLevel(stage::readLevelFile(file), file);
        stage::Stage s = l.solid ? stage::platonicStageOf(l) : core::meshStageOf(l, reader);
        stage::checkLevelOnStage(l, s);
        physics::World world;
        stage::buildLevel(l, s, world, 0, 22938);
        for (size_t f = 0; f < s.faceCount(); ++f) world.mapPart(s.part(f)).initialize();
      }));
    const bench::Spread t = bench::Spread::of(times);
    allMet = allMet && t.high <= 10;
    std::printf("  %-45s %s ms\n", std::filesystem::relative(entry.path(), PLATON_SOURCE_ROOT).c_str(),
                t.show("%.2f").c_str());
  }
  std::printf("goal <= 10 ms per shipped level: %s\n\n", allMet ? "met in every run" : "MISSED in some run");
  checkSpeed(std::min(runs, 5));
  return 0;
}
