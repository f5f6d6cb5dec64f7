// Frames per second of the first level played headless with the Lua player, rules, progression and
// level script, beside the same game written in C++ (bench/script/game_in_cpp.cpp), and beside the
// physics alone (the same player body driven by no game at all). Same input in both games, and the
// same state hash at the end, or the comparison is void and the program says so.
//
// Goals (issue 9): >= 100,000 frames/s with Lua; Lua's frame <= 1.5x the C++ frame, in the steady
// state; the warm-up (JIT compiling) is printed beside it. The first level's own script says its
// one line in build(); a third game, the same with a level script that ticks every frame (as a
// level with a timer does: sandboxed, so run with the JIT off and called through engine.call), is
// timed beside them and shows what such a tick adds.
//   build/bench/script_frames [frames] [runs]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "game_in_cpp.h"
#include "platon/core/scene.h"
#include "platon/script/script_system.h"
#include "spread.h"

using namespace platon;

namespace {

// Walk right and left in turns of 300 frames, a jump held 20 frames in every 70: the player runs
// along floors, falls off them, jumps onto platforms and crosses the cube's edges.
core::Buttons heldOn(uint64_t frame) {
  core::Buttons held =
      (frame / 300) % 2 == 0 ? core::InputFrame::bit(core::Button::Right) : core::InputFrame::bit(core::Button::Left);
  if (frame % 70 < 20) held |= core::InputFrame::bit(core::Button::Jump);
  return held;
}

// The first kWarmUpFrames of a fresh scene are timed apart: there LuaJIT interprets the scripts,
// records traces and compiles them (a one-time cost of a few ms), and the caches fill; the rest is
// the steady state a level plays in.
constexpr uint64_t kWarmUpFrames = 2000;

struct Run {
  double warmUpMilliseconds;
  double nanosecondsPerFrame;  // after the warm-up
  uint64_t hash;
};

Run play(core::Scene& scene, uint64_t frames) {
  core::InputEdges edges;
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  for (uint64_t f = 1; f <= kWarmUpFrames; ++f) scene.step(edges.next(heldOn(f)));
  const auto warm = Clock::now();
  for (uint64_t f = kWarmUpFrames + 1; f <= kWarmUpFrames + frames; ++f) scene.step(edges.next(heldOn(f)));
  const double ns = std::chrono::duration<double, std::nano>(Clock::now() - warm).count();
  return {std::chrono::duration<double, std::milli>(warm - start).count(), ns / static_cast<double>(frames),
          scene.world().stateHash()};
}

}  // namespace

int main(int argc, char** argv) {
  const uint64_t frames = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 20000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 7;
  const std::string only = argc > 3 ? argv[3] : "";  // "lua" or "cpp": one side alone, for a profiler
  if (!only.empty()) {
    for (int r = 0; r < runs; ++r) {
      core::SystemRegistry registry;
      registry.add("scripting", script::makeScriptSystem);
      std::unique_ptr<core::Scene> scene =
          only == "lua" ? core::loadScene(std::string(PLATON_SOURCE_ROOT) + "/levels/cube_intro/scene.lua", registry)
                        : bench::cubeIntroInCpp();
      if (const char* code = std::getenv("PLATON_BENCH_LUA"); code && only == "lua")  // an experiment's setup
        dynamic_cast<script::ScriptSystem&>(*scene->findSystem("scripting")).evaluate(code, "=experiment");
      const Run run = play(*scene, frames);
      std::printf("%s: warm-up %.2f ms, then %.0f ns/frame\n", only.c_str(), run.warmUpMilliseconds,
                  run.nanosecondsPerFrame);
    }
    return 0;
  }
  core::SystemRegistry registry;
  registry.add("scripting", script::makeScriptSystem);
  const std::string manifest = std::string(PLATON_SOURCE_ROOT) + "/levels/cube_intro/scene.lua";
  // The ticking variant: the first level's folder copied, its script saying the line on frame 1.
  namespace fs = std::filesystem;
  const fs::path ticking = fs::temp_directory_path() / ("platon_ticking_level_" + std::to_string(::getpid()));
  fs::create_directories(ticking);
  for (const char* file : {"scene.lua", "cube_intro.level"})
    fs::copy_file(fs::path(PLATON_SOURCE_ROOT) / "levels/cube_intro" / file, ticking / file,
                  fs::copy_options::overwrite_existing);
  std::ofstream(ticking / "level.lua")
      << "local level = {}\n"
         "function level.tick(game, frame)\n"
         "  if frame == 1 then game.message(\"walk right: every edge turns the cube\") end\n"
         "end\n"
         "return level\n";

  std::vector<double> lua, cpp, ratio, luaWarm, cppWarm, tick, tickRatio;
  uint64_t luaHash = 0, cppHash = 0, tickHash = 0;
  size_t luaMemory = 0;
  for (int r = 0; r < runs; ++r) {  // interleaved, so a slow moment of the machine hits both
    std::unique_ptr<core::Scene> luaScene = core::loadScene(manifest, registry);
    if (const char* log = std::getenv("PLATON_JIT_LOG"); log && r == 0)  // LuaJIT's trace log: what compiles
      dynamic_cast<script::ScriptSystem&>(*luaScene->findSystem("scripting"))
          .evaluate(std::string("require('jit.v').start('") + log + "')", "=jit log");
    const Run l = play(*luaScene, frames);
    luaMemory = dynamic_cast<script::ScriptSystem&>(*luaScene->findSystem("scripting")).luaMemoryBytes();
    std::unique_ptr<core::Scene> cppScene = bench::cubeIntroInCpp();
    const Run c = play(*cppScene, frames);
    std::unique_ptr<core::Scene> tickScene = core::loadScene((ticking / "scene.lua").string(), registry);
    const Run t = play(*tickScene, frames);
    tick.push_back(t.nanosecondsPerFrame);
    tickRatio.push_back(t.nanosecondsPerFrame / c.nanosecondsPerFrame);
    tickHash = t.hash;
    luaWarm.push_back(l.warmUpMilliseconds);
    cppWarm.push_back(c.warmUpMilliseconds);
    lua.push_back(l.nanosecondsPerFrame);
    cpp.push_back(c.nanosecondsPerFrame);
    ratio.push_back(l.nanosecondsPerFrame / c.nanosecondsPerFrame);
    luaHash = l.hash, cppHash = c.hash;
  }
  const bench::Spread luaNs = bench::Spread::of(lua), cppNs = bench::Spread::of(cpp), ratios = bench::Spread::of(ratio);
  std::vector<double> fps;
  for (double ns : lua) fps.push_back(1e9 / ns);
  std::printf("cube_intro, %llu frames a run after %llu warm-up frames, %d interleaved runs; median (min-max)\n",
              static_cast<unsigned long long>(frames), static_cast<unsigned long long>(kWarmUpFrames), runs);
  std::printf("  warm-up (first %llu frames of a fresh scene, JIT compiling): Lua %s ms, C++ %s ms\n",
              static_cast<unsigned long long>(kWarmUpFrames), bench::Spread::of(luaWarm).show("%.2f").c_str(),
              bench::Spread::of(cppWarm).show("%.2f").c_str());
  std::printf("  game in Lua : %s ns/frame, %s frames/s, Lua heap %.0f KiB\n", luaNs.show("%.0f").c_str(),
              bench::Spread::of(fps).show("%.0f").c_str(), static_cast<double>(luaMemory) / 1024.0);
  std::printf("  game in C++ : %s ns/frame\n", cppNs.show("%.0f").c_str());
  std::printf("  Lua / C++   : %s   (goal <= 1.5: %s)\n", ratios.show("%.2f").c_str(),
              bench::runsMet(ratio.size(), [&](size_t i) { return ratio[i] <= 1.5; }).c_str());
  std::printf("  frames/s >= 100,000: %s\n",
              bench::runsMet(lua.size(), [&](size_t i) { return lua[i] <= 10000; }).c_str());
  std::printf("  same state hash: %s (Lua %016llx, C++ %016llx)\n", luaHash == cppHash ? "yes" : "NO: the games differ",
              static_cast<unsigned long long>(luaHash), static_cast<unsigned long long>(cppHash));
  std::printf("  with a level script that ticks every frame: %s ns/frame, / C++ %s%s\n",
              bench::Spread::of(tick).show("%.0f").c_str(), bench::Spread::of(tickRatio).show("%.2f").c_str(),
              tickHash == cppHash ? "" : "  (NO: its game differs)");
  fs::remove_all(ticking);
  return luaHash == cppHash && tickHash == cppHash ? 0 : 1;
}
