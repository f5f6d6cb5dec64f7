// `platon shot`: a level's picture after N frames, rendered offscreen (SDL's offscreen video driver
// unless SDL_VIDEODRIVER says otherwise), so it works with no display. The input is a replay's
// when given, nothing held otherwise; the camera is stepped with the simulation, so frame N gives
// the same picture on every run and machine with the same GL driver.
#include "shot_command.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/stat.h>

#include "commands.h"
#include "engine_registry.h"
#include "level_argument.h"
#include "platon/core/data_root.h"
#include "platon/core/display.h"
#include "platon/core/error.h"
#include "platon/core/live_scene.h"
#include "platon/core/replay.h"
#include "platon/core/run.h"
#include "platon/script/script_system.h"
#include "platon/session/game_view.h"

namespace platon::app {
namespace {

int shotUsage() { return usageError("shot"); }

struct ShotOptions {
  std::string level, out, inputPath;
  uint64_t frames = 0;
  int width = 1280, height = 720;
  bool debug = false;
};

// One option and its value at argv[i] (i moves past the value): 0, or the exit code of a bad one.
int readShotOption(int argc, char** argv, int& i, ShotOptions& o) {
  const std::string a = argv[i];
  const bool valued = i + 1 < argc;
  if (a == "--frame" && valued) {
    const std::string n = argv[++i];
    if (n.empty() || n.size() > 9 || n.find_first_not_of("0123456789") != std::string::npos) {
      std::fprintf(stderr, "--frame %s: want a frame number, 0 to 999999999\n", n.c_str());
      return 2;
    }
    o.frames = std::stoull(n);
  } else if (a == "--size" && valued) {
    int& w = o.width;
    int& h = o.height;
    if (std::sscanf(argv[++i], "%dx%d", &w, &h) != 2 || std::min(w, h) < 16 || std::max(w, h) > 8192) {
      std::fprintf(stderr, "--size %s: want WxH, 16 to 8192 pixels each way\n", argv[i]);
      return 2;
    }
  } else if (a == "--input" && valued) {
    o.inputPath = argv[++i];
  } else if (a == "--out" && valued) {
    o.out = argv[++i];
  } else if (a == "--debug") {
    o.debug = true;
  } else if (o.level.empty() && !a.empty() && a[0] != '-') {
    o.level = a;
  } else {
    return shotUsage();
  }
  return 0;
}

}  // namespace

int shotCommand(int argc, char** argv) {
  ShotOptions o;
  for (int i = 1; i < argc; ++i)
    if (const int code = readShotOption(argc, argv, i, o)) return code;
  if (o.level.empty() || o.out.empty()) return shotUsage();
  const std::string &level = o.level, &out = o.out, &inputPath = o.inputPath;
  const uint64_t frames = o.frames;
  const int width = o.width, height = o.height;
  const bool debug = o.debug;
  setenv("SDL_VIDEODRIVER", "offscreen", 0);
  try {
    core::Replay input;
    if (!inputPath.empty()) input = core::readReplay(inputPath);
    const core::SystemRegistry registry = engineRegistry(Presentation::Picture);
    const std::string scene = levelArgument(level).scene;
    if (scene.empty()) throw std::runtime_error(level + ": no scene.lua beside it to play it with");
    core::LiveScene live(scene, registry, false);
    if (!session::displayOf(live.scene())) throw std::runtime_error(scene + ": the scene does not name \"rendering\"");
    core::Display& display = *session::displayOf(live.scene());
    display.resize(width, height);
    auto status = [&] { return session::statusOf(live.scene()); };
    session::GameView view;
    view.setDebug(debug);
    view.step(live.scene(), status(), 1.0 / 60);
    // The run every way of playing drives (core/run.h): the replay's console lines too.
    core::Run run(live);
    core::ReplayInput replay(input, live.scene());
    for (uint64_t f = 0; f < frames; ++f) {
      if (std::optional<std::string> error = run.step(replay.next(run)))
        std::fprintf(stderr, "frame %llu: %s\n", static_cast<unsigned long long>(f) + 1, error->c_str());
      view.step(live.scene(), status(), 1.0 / 60);
    }
    core::View v = view.view(live.scene(), 1.0);
    const script::GameStatus st = status();
    v.hud = session::hudLines(live.scene(), st);
    v.error = live.lastError();
    display.present(v, view.drawing(1.0));
    int w = 0, h = 0;
    display.capture(w, h);
    if (w != width || h != height)
      throw std::runtime_error(out + ": the window came out " + std::to_string(w) + "x" + std::to_string(h) + ", not " +
                               std::to_string(width) + "x" + std::to_string(height));
    display.saveScreenshot(out);
    std::printf("%s: %dx%d, frame %llu of %s\n", out.c_str(), w, h, static_cast<unsigned long long>(frames),
                scene.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", core::errorReport(e).c_str());
    return 1;
  }
}

}  // namespace platon::app
