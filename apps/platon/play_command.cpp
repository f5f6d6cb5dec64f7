// Plays a scene in real time at 60 frames a second (or as fast as it goes), printing the level's
// messages, errors and results as they happen. When the scene names "rendering" it is shown in a
// window (the renderer plugin, loaded only then) and played from the keyboard; --headless, or no
// display, plays it without one. Input can also come from a replay. With --watch, saving the
// level, its manifest or a script reloads it while it runs; a broken edit is reported (on screen
// too) and the last good version goes on.
#include "play_command.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <signal.h>
#include <string>
#include <thread>
#include <unistd.h>

#include "commands.h"
#include "edit_command.h"
#include "engine_registry.h"
#include "game_view.h"
#include "level_argument.h"
#include "platon/core/data_root.h"
#include "platon/core/display.h"
#include "platon/core/fixed_step.h"
#include "platon/core/live_scene.h"
#include "platon/core/replay.h"
#include "platon/core/visible_text.h"
#include "platon/script/script_system.h"
#include "save_file.h"

namespace platon::app {
namespace {

// The one piece of global state: the signal (SIGINT or SIGTERM) that asked play to stop, set by
// its handler, read once a loop. A signal handler can only reach a global; it ends the loop so
// that a recording is still written (an endless headless play is stopped by a signal).
volatile sig_atomic_t stopSignal = 0;

// A frame that never ends (a trusted script's compiled endless loop, a C call that runs for hours)
// never gets back to the loop that reads stopSignal. So a second signal, or stopGraceSeconds
// after the first (`timeout` sends one), ends the process at once by the signal's default action.
// No recording is written then: the frame may be changing it, and a signal handler cannot safely
// write a file from it. The grace is 3 s; $PLATON_STOP_GRACE (whole seconds, 1 to 3600) changes it.
unsigned stopGraceSeconds = 3;

void endNow(int signal) {
  constexpr char kNote[] = "platon play: the frame did not end: stopped at once, without writing a recording\n";
  (void)!write(STDERR_FILENO, kNote, sizeof kNote - 1);
  struct sigaction action {};
  action.sa_handler = SIG_DFL;
  sigemptyset(&action.sa_mask);
  sigaction(signal, &action, nullptr);
  raise(signal);  // delivered when this handler returns (or at once, from the grace alarm)
}

void onStopSignal(int signal) {
  if (stopSignal) return endNow(signal);
  stopSignal = signal;
  alarm(stopGraceSeconds);
}

void onGraceOver(int) { endNow(stopSignal); }

void stopOnSignals() {
  if (const char* grace = std::getenv("PLATON_STOP_GRACE")) {
    char* end = nullptr;
    const long seconds = std::strtol(grace, &end, 10);
    if (end != grace && *end == '\0' && seconds >= 1 && seconds <= 3600)
      stopGraceSeconds = static_cast<unsigned>(seconds);
  }
  struct sigaction action {};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  action.sa_handler = onGraceOver;
  sigaction(SIGALRM, &action, nullptr);
}

// Why `path` cannot take a replay of the scene at `scenePath`, or "" if it can: checked before
// playing, so a session is not played to the end and then lost. The file is written next to
// `path` (path.partial, then renamed), so that is what is tried.
std::string whyUnrecordable(const std::string& scenePath, const std::string& path) {
  if (scenePath.find_first_of("\"\n\r") != std::string::npos)
    return "a scene path with '\"' or a line break cannot be written in a replay (rename its folder)";
  if (!core::portableScenePath(scenePath))
    return "the scene " + scenePath +
           " is in neither the current folder nor the game's data folder: a replay names its scene by a path from "
           "one of them (replays are shared), so play it from a folder that holds it";
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return "is a folder";
  const std::string partial = path + ".partial";
  const bool existed = std::filesystem::exists(partial, error);
  // O_NOFOLLOW: a link of the partial file's name is not written through.
  const int probe = ::open(partial.c_str(), O_WRONLY | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
  if (probe < 0) return "cannot write " + partial + ": " + std::strerror(errno);
  ::close(probe);
  if (!existed) std::remove(partial.c_str());
  return "";
}

// Writes the recording; false (after saying why, and where what was written is) if it cannot.
bool writeRecording(const core::Replay& replay, const std::string& path) {
  try {
    core::writeReplay(replay, path);
    return true;
  } catch (const std::exception& e) {
    std::error_code error;
    const std::string partial = path + ".partial";
    if (std::filesystem::file_size(partial, error) > 0 && !error)
      std::fprintf(stderr, "platon play: %s; this run's recording is left in %s\n", e.what(), partial.c_str());
    else
      std::fprintf(stderr, "platon play: %s; this run's recording is lost\n", e.what());
    return false;
  }
}

// --frames N: a whole number from 1 (strtoull took "-1" as 2^64 - 1 and "abc" as 0, unlimited).
bool frameCount(const char* text, uint64_t& out) {
  const char* end = text + std::strlen(text);
  const auto [stop, error] = std::from_chars(text, end, out);
  return error == std::errc() && stop == end && end != text && out >= 1;
}

int playUsage() { return usageError("play"); }

script::ScriptSystem* scriptsOf(core::Scene& scene) {
  return dynamic_cast<script::ScriptSystem*>(scene.findSystem("scripting"));
}

// One picture: the stage from the camera, the scripts' shapes, the heads-up lines and the last error.
void show(core::Display& display, core::LiveScene& live, const GameView& gameView, double alpha, bool showFps = false) {
  core::Scene& scene = live.scene();
  const script::GameStatus status = statusOf(scene);
  core::View view = gameView.view(scene, alpha);
  view.hud = hudLines(scene, status);
  view.error = live.lastError();
  view.showFps = showFps;
  display.present(view, gameView.drawing(alpha));
}

}  // namespace

int playCommand(int argc, char** argv) {
  std::string scenePath, inputPath, recordPath, shotPath;
  uint64_t frames = 0;
  bool watch = false, fast = false, headless = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--frames" && i + 1 < argc) {
      if (!frameCount(argv[++i], frames))
        return std::fprintf(stderr, "platon play: --frames %s: expected a whole number of frames from 1\n", argv[i]),
               playUsage();
    } else if (a == "--input" && i + 1 < argc)
      inputPath = argv[++i];
    else if (a == "--record" && i + 1 < argc)
      recordPath = argv[++i];
    else if (a == "--watch")
      watch = true;
    else if (a == "--fast")
      fast = true;
    else if (a == "--headless")
      headless = true;
    else if (a == "--shot" && i + 1 < argc)
      shotPath = argv[++i];
    else if (scenePath.empty() && !a.empty() && a[0] != '-')
      scenePath = a;  // a level, in any of its forms (level_argument.h): made its scene.lua below
    else
      return playUsage();
  }
  core::Replay input;
  size_t nextConsole = 0;  // the next of input's console lines to run
  try {
    if (!inputPath.empty()) input = core::readReplay(inputPath);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  if (scenePath.empty()) {
    if (inputPath.empty()) return playUsage();
    scenePath = input.scene;
  } else if (scenePath.size() < 4 || scenePath.compare(scenePath.size() - 4, 4, ".lua") != 0) {
    try {  // a level's folder or .level file: its scene.lua (kept relative, as a recording names it)
      scenePath = levelArgument(scenePath).scene;
    } catch (const std::exception& e) {
      return std::fprintf(stderr, "platon play: %s\n", e.what()), 2;
    }
    if (scenePath.empty()) return std::fprintf(stderr, "platon play: no scene.lua beside the level file\n"), 2;
  }
  if (!recordPath.empty()) {
    if (const std::string why = whyUnrecordable(scenePath, recordPath); !why.empty())
      return std::fprintf(stderr, "platon play: --record %s: %s\n", recordPath.c_str(), why.c_str()), 2;
  }

  core::SystemRegistry registry = engineRegistry(headless ? Presentation::Headless : Presentation::Window);
  std::optional<core::LiveScene> live;
  try {
    live.emplace(core::resolveDataPath(scenePath), registry, watch);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", core::visibleText(core::errorReport(e), true).c_str());
    return 1;
  }
  core::Display* display = displayOf(live->scene());
  if (display) {
    try {
      display->pollEvents();  // opens the window: no display shows here, in one line
    } catch (const std::exception& e) {
      std::printf("%s: playing headless\n", e.what());
      display = nullptr;
    }
  }
  if (!display && !shotPath.empty()) {
    std::fprintf(stderr, "--shot needs a window: the scene names no \"rendering\", or there is no display\n");
    return 1;
  }
  std::printf("playing %s%s\n", core::visibleText(live->scene().manifest().name).c_str(),
              watch ? " (watching its files: save one to reload)" : "");
  std::fflush(stdout);

  std::optional<core::ReplayRecorder> recorder;
  bool recordFailed = false;
  if (!recordPath.empty())
    recorder.emplace(*core::portableScenePath(scenePath), 60,
                     core::sceneFilesHash(core::sceneSourceFiles(live->scene())));
  stopOnSignals();
  uint64_t frameErrors = 0;  // frames whose scripts raised an error
  core::FixedStep clock(60);
  core::InputEdges edges;
  core::TapCarry taps;  // taps between frames, played on the next
  GameView gameView;
  bool showFps = false;
  if (display) gameView.step(live->scene(), statusOf(live->scene()), 1.0 / clock.hz());  // headless: no picture to keep
  std::string lastMessage, lastError;
  uint64_t frame = 0;
  bool won = false;
  auto previous = std::chrono::steady_clock::now();
  while ((frames == 0 || frame < frames) && !stopSignal) {
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
          std::printf("recording stops at frame %llu: the reload changed the scene\n",
                      static_cast<unsigned long long>(frame));
          std::fflush(stdout);
          if (!writeRecording(recorder->replay(), recordPath)) recordFailed = true;
          recorder.reset();
        }
      } else {
        std::printf("reload refused, the last good version goes on:\n%s\n", core::visibleText(r->error, true).c_str());
      }
    }
    uint8_t keys = 0;
    display = displayOf(live->scene()) && display ? displayOf(live->scene()) : nullptr;  // a reload replaces it
    if (display) {
      const core::WindowInput events = display->pollEvents();
      auto pressed = [&](core::Key k) {
        return std::find(events.pressed.begin(), events.pressed.end(), k) != events.pressed.end();
      };
      if (events.closed || pressed(core::Key::Escape)) break;
      if (pressed(core::Key::ShowFps)) showFps = !showFps;
      if (pressed(core::Key::Debug)) gameView.setDebug(!gameView.debug());
      if (pressed(core::Key::Screenshot)) std::printf("%s\n", saveScreenshot(*display).c_str());
      const bool edit =
          std::any_of(events.keys.begin(), events.keys.end(), [](const core::KeyPress& k) { return k.name == "F4"; });
      if (edit && inputPath.empty()) {  // the editor in this window; back here, the level reloaded
        std::printf("editing %s (F4)\n", scenePath.c_str());
        std::fflush(stdout);
        try {
          if (editLevel(levelArgument(scenePath), registry, live->scene().findSystem("rendering")) == kWindowClosed)
            break;
        } catch (const std::exception& e) {
          std::printf("%s\n", e.what());
        }
        const core::ReloadReport r = live->reload({"the editor"});
        if (recorder && r.ok) {  // as any reload: the run recorded so far is written, and recording stops
          if (!writeRecording(recorder->replay(), recordPath)) recordFailed = true;
          recorder.reset();
        }
        std::printf(r.ok ? "reloaded after the editor\n" : "reload refused, the last good version goes on:\n%s\n",
                    core::visibleText(r.error, true).c_str());
        previous = std::chrono::steady_clock::now();
        continue;
      }
      keys = events.held;
      taps.add(events.tapped);
    }
    for (int s = 0; s < due && (frames == 0 || frame < frames); ++s) {
      const uint8_t held = inputPath.empty() ? taps.next(keys) : frame < input.held.size() ? input.held[frame] : 0;
      // The replay's console lines before the frame they ran before, as `platon replay` runs them.
      for (; nextConsole < input.console.size() && input.console[nextConsole].frame <= frame + 1; ++nextConsole) {
        const std::string& code = input.console[nextConsole].code;
        if (script::ScriptSystem* scripts = scriptsOf(live->scene())) {
          const script::ScriptSystem::ConsoleAnswer answer = scripts->console(code);
          std::printf("console before frame %llu: %s\n%s\n", static_cast<unsigned long long>(frame) + 1,
                      core::visibleText(code).c_str(), core::visibleText(answer.text, true).c_str());
        }
        if (recorder) recorder->console(code);
      }
      ++frame;
      if (std::optional<std::string> error = live->step(edges.next(held))) {
        ++frameErrors;
        if (*error != lastError)
          std::printf("frame %llu: error (the game goes on):\n%s\n", static_cast<unsigned long long>(frame),
                      core::visibleText(*error, true).c_str());
        lastError = *error;
      }
      if (recorder) recorder->frame(held, live->scene().world().stateHash());
      if (display) gameView.step(live->scene(), statusOf(live->scene()), 1.0 / clock.hz());
      script::ScriptSystem* scripts = scriptsOf(live->scene());
      if (!scripts) continue;
      const script::GameStatus status = scripts->status();
      if (status.message != lastMessage) {
        std::printf("frame %llu: %s\n", static_cast<unsigned long long>(frame),
                    core::visibleText(status.message).c_str());  // a script's text: no terminal escapes
        lastMessage = status.message;
      }
      if (status.won && !won) {
        won = true;
        std::printf("goal reached at frame %llu: %.2f s played, %d deaths\n",
                    static_cast<unsigned long long>(status.wonFrame), static_cast<double>(status.time) / 60.0,
                    status.deaths);
      }
    }
    if (display) show(*display, *live, gameView, fast ? 1.0 : clock.alpha(), showFps);
    std::fflush(stdout);
    if (won && frames == 0 && !watch && !display) break;
    if (!fast && due == 0) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  alarm(0);  // the loop ended: no grace period runs out while the recording is written
  if (stopSignal)
    std::printf("stopped by signal %d at frame %llu\n", static_cast<int>(stopSignal),
                static_cast<unsigned long long>(frame));
  if (recorder) {
    std::fflush(stdout);
    if (writeRecording(recorder->replay(), recordPath))
      std::printf("recorded %llu frames to %s\n", static_cast<unsigned long long>(recorder->replay().frames()),
                  recordPath.c_str());
    else
      recordFailed = true;
  }
  if (display && !shotPath.empty()) {
    try {
      show(*display, *live, gameView, 1.0);
      display->saveScreenshot(shotPath);
      std::printf("screenshot: %s\n", shotPath.c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 1;
    }
  }
  std::printf("state hash %016llx after %llu frames\n",
              static_cast<unsigned long long>(live->scene().world().stateHash()),
              static_cast<unsigned long long>(frame));
  if (!display && frameErrors > 0) {  // headless is how CI plays: a script error must fail it
    std::printf("%llu frame(s) had a script error\n", static_cast<unsigned long long>(frameErrors));
    return 1;
  }
  if (recordFailed) return 1;
  return stopSignal ? 128 + stopSignal : 0;
}

}  // namespace platon::app
