// Plays a scene headless (the window comes with the renderer): in real time at 60 frames a second
// or as fast as it goes, with input from a replay or none, printing the level's messages, errors
// and results as they happen. With --watch, saving the level, its manifest or a script reloads it
// while it runs; a broken edit is reported and the last good version goes on.
#include "play_command.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>

#include "platon/core/fixed_step.h"
#include "platon/core/live_scene.h"
#include "platon/core/replay.h"
#include "platon/script/script_system.h"

namespace platon::app {
namespace {

int usage() {
  std::fprintf(stderr,
               "usage: platon play scene.lua [--frames N] [--input run.replay] [--record out.replay]\n"
               "                             [--watch] [--fast]\n"
               "  --frames N   stop after N frames (default: at the goal, or never with --watch)\n"
               "  --input F    the buttons of a recorded run (nothing held without it)\n"
               "  --record F   write this run's input and hashes to F as a replay\n"
               "  --watch      reload the scene when its files are saved\n"
               "  --fast       do not wait for real time\n");
  return 2;
}

script::ScriptSystem* scriptsOf(core::Scene& scene) {
  return dynamic_cast<script::ScriptSystem*>(scene.findSystem("scripting"));
}

}  // namespace

int playCommand(int argc, char** argv) {
  std::string scenePath, inputPath, recordPath;
  uint64_t frames = 0;
  bool watch = false, fast = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--frames" && i + 1 < argc) frames = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--input" && i + 1 < argc) inputPath = argv[++i];
    else if (a == "--record" && i + 1 < argc) recordPath = argv[++i];
    else if (a == "--watch") watch = true;
    else if (a == "--fast") fast = true;
    else if (scenePath.empty() && !a.empty() && a[0] != '-') scenePath = a;
    else return usage();
  }
  core::Replay input;
  try {
    if (!inputPath.empty()) input = core::readReplay(inputPath);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  if (scenePath.empty()) {
    if (inputPath.empty()) return usage();
    scenePath = input.scene;
  }

  core::SystemRegistry registry;
  registry.add("scripting", script::makeScriptSystem);
  std::optional<core::LiveScene> live;
  try {
    live.emplace(scenePath, registry, watch);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", core::errorReport(e).c_str());
    return 1;
  }
  std::printf("playing %s%s\n", live->scene().manifest().name.c_str(), watch ? " (watching its files: save one to reload)" : "");
  std::fflush(stdout);

  std::optional<core::ReplayRecorder> recorder;
  if (!recordPath.empty()) recorder.emplace(scenePath, 60);
  core::FixedStep clock(60);
  core::InputEdges edges;
  std::string lastMessage, lastError;
  uint64_t frame = 0;
  bool won = false;
  auto previous = std::chrono::steady_clock::now();
  while (frames == 0 || frame < frames) {
    int due = 1;
    if (!fast) {
      const auto now = std::chrono::steady_clock::now();
      due = clock.advance(std::chrono::duration_cast<std::chrono::nanoseconds>(now - previous).count());
      previous = now;
    }
    if (std::optional<core::ReloadReport> r = live->poll(0)) {
      if (r->ok) {
        std::printf("reloaded in %.1f ms (%s)\n", r->milliseconds, r->files.empty() ? "" : r->files.front().c_str());
        if (recorder) {
          std::printf("recording stops at frame %llu: the reload changed the scene\n", static_cast<unsigned long long>(frame));
          core::writeReplay(recorder->replay(), recordPath);
          recorder.reset();
        }
      } else {
        std::printf("reload refused, the last good version goes on:\n%s\n", r->error.c_str());
      }
    }
    for (int s = 0; s < due && (frames == 0 || frame < frames); ++s) {
      const uint8_t held = frame < input.held.size() ? input.held[frame] : 0;
      ++frame;
      if (std::optional<std::string> error = live->step(edges.next(held)); error && *error != lastError) {
        std::printf("frame %llu: error (the game goes on):\n%s\n", static_cast<unsigned long long>(frame), error->c_str());
        lastError = *error;
      }
      if (recorder) recorder->frame(held, live->scene().world().stateHash());
      script::ScriptSystem* scripts = scriptsOf(live->scene());
      if (!scripts) continue;
      const script::GameStatus status = scripts->status();
      if (status.message != lastMessage) {
        std::printf("frame %llu: %s\n", static_cast<unsigned long long>(frame), status.message.c_str());
        lastMessage = status.message;
      }
      if (status.won && !won) {
        won = true;
        std::printf("goal reached at frame %llu: %.2f s played, %d deaths\n", static_cast<unsigned long long>(status.wonFrame),
                    static_cast<double>(status.time) / 60.0, status.deaths);
      }
    }
    std::fflush(stdout);
    if (won && frames == 0 && !watch) break;
    if (!fast && due == 0) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (recorder) {
    core::writeReplay(recorder->replay(), recordPath);
    std::printf("recorded %llu frames to %s\n", static_cast<unsigned long long>(frame), recordPath.c_str());
  }
  std::printf("state hash %016llx after %llu frames\n", static_cast<unsigned long long>(live->scene().world().stateHash()),
              static_cast<unsigned long long>(frame));
  return 0;
}

}  // namespace platon::app
