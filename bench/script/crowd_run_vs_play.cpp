// `platon run` against `platon play --headless` on a level of a crowd: 9,900 crates piled on a
// cube's floor by the level's script (100 a frame; the world's cap for scripts is 10,000 bodies
// with the player). `play` steps the scene (core::Run, what every way of playing drives); `run`
// runs it as a scenario, whose runner checks every frame (no overlap, the expectations). Both load
// the same files; a frame's cost is the time of a long run less a short one's over their
// difference, so loading cancels out. Prints each one's ms per frame (median, min-max over the
// runs) and run / play: the runner's own checks must not be the cost (issue 41: at most 1.0).
//   crowd_run_vs_play [--quick]     (CROWD_CHECKS=N: time the check N times, for a profiler)
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "platon/core/live_scene.h"
#include "platon/core/run.h"
#include "platon/script/scenario.h"
#include "platon/script/script_system.h"
#include "spread.h"

namespace {

using Clock = std::chrono::steady_clock;

void write(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

// The level: the cube's first face with a long floor; the player starts on face 2, away from it.
// Crates of 20 units, 100 a frame, in 99 rows of 100 a unit apart, fall a little and pile.
std::filesystem::path makeLevel() {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("platon_crowd_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::string level = "HEXAHEDRON\n2 600 700\n2 3000 700\n4096\n%\n100 400 4000 400\n";
  for (int face = 1; face < 6; ++face) level += "%\n256 512 3840 512\n";
  write(dir / "crowd.level", level);
  write(dir / "level.lua",
        "local level = {}\n"
        "local made = 0\n"
        "function level.tick(game, frame)\n"
        "  if made >= 9900 then return end\n"
        "  local world = game.world\n"
        "  local row = math.floor(made / 100)\n"
        "  for col = 0, 99 do\n"
        "    local e = world.createEntity{ box = { 10, 10 } }\n"
        "    world.setFilter(e, { category = 2, solidWith = 3, overlapWith = 0, pushable = true })\n"
        "    world.insert(e, 0, 300 + col * 21, 420 + row * 21)\n"
        "  end\n"
        "  made = made + 100\n"
        "end\n"
        "return level\n");
  write(dir / "scene.lua",
        "return { name = 'crowd', systems = { 'scripting' }, stage = { level = 'crowd.level' }, gravity = 0.35,\n"
        "  scripts = { preset = 'game', level = 'level.lua' } }\n");
  return dir;
}

double lastCheckMs = 0;  // the runner's check of a frame, World::countOverlaps, on the crowd as play left it

// Seconds to load the scene and play `frames` of it, as `play --headless` does.
double play(const std::string& scene, uint64_t frames) {
  const auto t0 = Clock::now();
  platon::core::SystemRegistry registry;
  registry.add("scripting", platon::script::makeScriptSystem);
  platon::core::LiveScene live(scene, registry, false);
  platon::core::Run run(live);
  for (uint64_t f = 0; f < frames; ++f)
    if (std::optional<std::string> error = run.step(0)) {
      std::fprintf(stderr, "play: frame %llu: %s\n", static_cast<unsigned long long>(f + 1), error->c_str());
      std::exit(1);
    }
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  // The crowd is there, piled, and the level's script ran without an error.
  if (live.scene().world().entityCount() < 9901 || !live.lastError().empty() ||
      live.scene().world().countOverlaps() != 0) {
    std::fprintf(stderr, "play: %zu bodies, %zu overlaps, error: %s\n", live.scene().world().entityCount(),
                 live.scene().world().countOverlaps(), live.lastError().c_str());
    std::exit(1);
  }
  const auto c0 = Clock::now();
  const int checks = std::getenv("CROWD_CHECKS") ? std::atoi(std::getenv("CROWD_CHECKS")) : 10;
  for (int i = 0; i < checks; ++i) live.scene().world().countOverlaps();
  lastCheckMs = std::chrono::duration<double, std::milli>(Clock::now() - c0).count() / checks;
  return seconds;
}

// Seconds to run it as a scenario of `frames` frames, as `platon run` does (in this process).
double runScenario(const std::filesystem::path& dir, uint64_t frames) {
  const std::filesystem::path path = dir / ("crowd_" + std::to_string(frames) + ".lua");
  write(path, "return { scene = 'scene.lua', frames = " + std::to_string(frames) + " }\n");
  const auto t0 = Clock::now();
  const platon::script::ScenarioResult r = platon::script::runScenario(path.string());
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  if (!r.passed) {
    std::fprintf(stderr, "run: %s\n", r.message.c_str());
    std::exit(1);
  }
  return seconds;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const uint64_t shortRun = quick ? 150 : 300, longRun = quick ? 250 : 900;  // both past the 99 frames of making
  const int runs = quick ? 1 : 5;
  const std::filesystem::path dir = makeLevel();
  const std::string scene = (dir / "scene.lua").string();
  std::vector<double> played, ran, ratio, checked;
  for (int i = 0; i < runs; ++i) {
    const double p = (play(scene, longRun) - play(scene, shortRun)) / double(longRun - shortRun) * 1e3;
    const double r = (runScenario(dir, longRun) - runScenario(dir, shortRun)) / double(longRun - shortRun) * 1e3;
    played.push_back(p), ran.push_back(r), ratio.push_back(r / p), checked.push_back(lastCheckMs);
  }
  std::filesystem::remove_all(dir);
  using platon::bench::Spread;
  std::printf("A crowd of 9,900 piled crates and the player, ms per frame over frames %llu-%llu, %d runs:\n",
              static_cast<unsigned long long>(shortRun), static_cast<unsigned long long>(longRun), runs);
  std::printf(
      "| play (core::Run) | run (scenario, checked) | run / play | of which the overlap check |\n|---|---|---|---|\n");
  std::printf("| %s | %s | %s | %s |\n", Spread::of(played).show("%.2f").c_str(), Spread::of(ran).show("%.2f").c_str(),
              Spread::of(ratio).show("%.2f").c_str(), Spread::of(checked).show("%.2f").c_str());
  return 0;
}
