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
#include "level_argument.h"
#include "platon/core/data_root.h"
#include "platon/core/display.h"
#include "platon/core/live_scene.h"
#include "platon/core/replay.h"
#include "platon/core/run.h"
#include "platon/core/visible_text.h"
#include "platon/script/script_system.h"
#include "platon/session/session.h"
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

// What `platon play` was asked.
struct PlayOptions {
  std::string scenePath, inputPath, recordPath, shotPath;
  uint64_t frames = 0;
  bool watch = false, fast = false, headless = false;
  // Whether `played` frames are all that --frames asked for.
  bool enough(uint64_t played) const { return frames != 0 && played >= frames; }
};

// The option that takes a value, and where it goes (null: none of them).
std::string* valueOf(PlayOptions& o, const std::string& flag) {
  if (flag == "--input") return &o.inputPath;
  if (flag == "--record") return &o.recordPath;
  if (flag == "--shot") return &o.shotPath;
  return nullptr;
}
bool* switchOf(PlayOptions& o, const std::string& flag) {
  if (flag == "--watch") return &o.watch;
  if (flag == "--fast") return &o.fast;
  if (flag == "--headless") return &o.headless;
  return nullptr;
}

// Reads the arguments; false (after saying why, for --frames) when they are wrong.
bool readPlayOptions(int argc, char** argv, PlayOptions& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a == "--frames" && hasValue) {
      if (frameCount(argv[++i], o.frames)) continue;
      std::fprintf(stderr, "platon play: --frames %s: expected a whole number of frames from 1\n", argv[i]);
      return false;
    }
    if (std::string* value = valueOf(o, a); value && hasValue) {
      *value = argv[++i];
    } else if (bool* on = switchOf(o, a)) {
      *on = true;
    } else if (o.scenePath.empty() && !a.empty() && a[0] != '-') {
      o.scenePath = a;  // a level, in any of its forms (level_argument.h): made its scene.lua below
    } else {
      return false;
    }
  }
  return !o.scenePath.empty() || !o.inputPath.empty();
}

// The scene to play: the one named (a level's folder or .level file: its scene.lua, kept
// relative, as a recording names it), or the replay's. "" after saying why when there is none.
std::string sceneToPlay(const PlayOptions& o, const core::Replay& input) {
  if (o.scenePath.empty()) return input.scene;
  if (o.scenePath.size() >= 4 && o.scenePath.compare(o.scenePath.size() - 4, 4, ".lua") == 0) return o.scenePath;
  try {
    std::string scene = levelArgument(o.scenePath).scene;
    if (scene.empty()) std::fprintf(stderr, "platon play: no scene.lua beside the level file\n");
    return scene;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "platon play: %s\n", e.what());
    return "";
  }
}

// What the level said and did, as it happens: its messages, its goal.
class PlayReport {
 public:
  void after(session::Session& s) {
    script::ScriptSystem* scripts = dynamic_cast<script::ScriptSystem*>(s.scene().findSystem("scripting"));
    if (!scripts) return;
    const script::GameStatus status = scripts->status();
    const auto frame = static_cast<unsigned long long>(s.run().frame());
    if (status.message != lastMessage_) {
      std::printf("frame %llu: %s\n", frame, core::visibleText(status.message).c_str());  // no terminal escapes
      lastMessage_ = status.message;
    }
    if (status.won && !won_) {
      won_ = true;
      std::printf("goal reached at frame %llu: %.2f s played, %d deaths\n",
                  static_cast<unsigned long long>(status.wonFrame), static_cast<double>(status.time) / 60.0,
                  status.deaths);
    }
  }
  bool won() const { return won_; }

 private:
  std::string lastMessage_;
  bool won_ = false;
};

// The play: the session's frames until --frames, the goal (unless --watch), Esc, the window's
// close or a signal.
class Play {
 public:
  Play(session::Session& s, const PlayOptions& o, const core::Replay& input, bool window)
      : s_(s), o_(o), replay_(input, s.scene()), fromReplay_(!o.inputPath.empty()), window_(window) {}
  // Returns the frames that had a script error.
  uint64_t run() {
    while (!o_.enough(s_.run().frame()) && !stopSignal && !over()) {
      s_.reloadIfSaved();
      const core::WindowInput in = s_.poll();
      if (in.closed || std::find(in.pressed.begin(), in.pressed.end(), core::Key::Escape) != in.pressed.end()) break;
      if (!fromReplay_) s_.tap(in.tapped);
      playDue(in);
      if (window_) s_.draw();
      std::fflush(stdout);
    }
    return errorFrames_;
  }

 private:
  // The play ends at the goal (--help), unless it watches its files or counts its frames.
  bool over() const { return report_.won() && o_.frames == 0 && !o_.watch; }
  void playDue(const core::WindowInput& in) {
    for (int due = s_.framesDue(100, o_.fast); due > 0 && !o_.enough(s_.run().frame()); --due) {
      if (s_.playFrame(nextButtons(in))) ++errorFrames_;
      report_.after(s_);
      if (s_.frozen() || over()) break;
    }
  }
  // The window's buttons, or the replay's (its console lines before the frame they ran before, as
  // `platon replay` runs them).
  core::Buttons nextButtons(const core::WindowInput& in) {
    if (!fromReplay_) return s_.nextButtons(in.held);
    return replay_.next(s_.run(), [&](const std::string& code, const core::ConsoleAnswer& answer) {
      std::printf("console before frame %llu: %s\n%s\n", static_cast<unsigned long long>(s_.run().frame()) + 1,
                  core::visibleText(code).c_str(), core::visibleText(answer.text, true).c_str());
    });
  }

  session::Session& s_;
  const PlayOptions& o_;
  core::ReplayInput replay_;
  PlayReport report_;
  uint64_t errorFrames_ = 0;
  bool fromReplay_, window_;
};

// The scene played, in its window when it has one and a display shows it; null (after saying
// why) when it does not load.
std::unique_ptr<session::Session> openSession(const std::string& scenePath, const core::SystemRegistry& registry,
                                              const PlayOptions& o, bool& window) {
  std::unique_ptr<core::LiveScene> live;
  try {
    live = std::make_unique<core::LiveScene>(core::resolveDataPath(scenePath), registry, o.watch);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", core::visibleText(core::errorReport(e), true).c_str());
    return nullptr;
  }
  auto s = std::make_unique<session::Session>(std::move(live));
  window = s->display() != nullptr;
  if (!window) return s;
  try {
    s->display()->pollEvents();  // opens the window: no display shows here, in one line
  } catch (const std::exception& e) {
    std::printf("%s: playing headless\n", e.what());
    s->withoutWindow();
    window = false;
  }
  return s;
}

// Writes what the run recorded, if it was recording; false when that failed (it said why).
bool keepRecording(session::Session& s, const std::string& path) {
  const std::optional<core::Replay> recorded = s.run().stopRecording();
  if (!recorded) return true;
  std::fflush(stdout);
  if (!writeRecording(*recorded, path)) return false;
  std::printf("recorded %llu frames to %s\n", static_cast<unsigned long long>(recorded->frames()), path.c_str());
  return true;
}

// A reload ends the recording: the new version starts from a state no replay reproduces.
void sayReload(session::Session& s, const core::ReloadReport& r, const std::string& recordPath, bool& recordFailed) {
  if (!r.ok) {
    std::printf("reload refused, the last good version goes on:\n%s\n", core::visibleText(r.error, true).c_str());
  } else {
    std::printf("reloaded in %.1f ms (%s)\n", r.milliseconds, r.files.empty() ? "" : r.files.front().c_str());
    if (s.run().recording()) {
      std::printf("recording stops at frame %llu: the reload changed the scene\n",
                  static_cast<unsigned long long>(s.run().frame()));
      if (!keepRecording(s, recordPath)) recordFailed = true;
    }
  }
  std::fflush(stdout);
}

// The end: the screenshot asked for, the state hash, and the exit code.
int finishPlay(session::Session& s, const PlayOptions& o, bool window, uint64_t frameErrors, bool recordFailed) {
  if (window && !o.shotPath.empty()) {
    try {
      s.draw();
      s.display()->saveScreenshot(o.shotPath);
      std::printf("screenshot: %s\n", o.shotPath.c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 1;
    }
  }
  std::printf("state hash %016llx after %llu frames\n", static_cast<unsigned long long>(s.scene().world().stateHash()),
              static_cast<unsigned long long>(s.run().frame()));
  if (!window && frameErrors > 0) {  // headless is how CI plays: a script error must fail it
    std::printf("%llu frame(s) had a script error\n", static_cast<unsigned long long>(frameErrors));
    return 1;
  }
  if (recordFailed) return 1;
  return stopSignal ? 128 + stopSignal : 0;
}

// The input replay (empty without --input) and the scene to play: 0, or the exit code after
// saying why (1: a replay that does not read, 2: no scene).
int readInputAndScene(const PlayOptions& o, core::Replay& input, std::string& scenePath) {
  try {
    if (!o.inputPath.empty()) input = core::readReplay(o.inputPath);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  scenePath = sceneToPlay(o, input);
  return scenePath.empty() ? 2 : 0;
}

}  // namespace

int playCommand(int argc, char** argv) {
  PlayOptions o;
  if (!readPlayOptions(argc, argv, o)) return playUsage();
  core::Replay input;
  std::string scenePath;
  if (const int failed = readInputAndScene(o, input, scenePath)) return failed;
  if (!o.recordPath.empty()) {
    if (const std::string why = whyUnrecordable(scenePath, o.recordPath); !why.empty())
      return std::fprintf(stderr, "platon play: --record %s: %s\n", o.recordPath.c_str(), why.c_str()), 2;
  }
  core::SystemRegistry registry = engineRegistry(o.headless ? Presentation::Headless : Presentation::Window);
  bool window = false;
  const std::unique_ptr<session::Session> s = openSession(scenePath, registry, o, window);
  if (!s) return 1;
  if (!window && !o.shotPath.empty()) {
    std::fprintf(stderr, "--shot needs a window: the scene names no \"rendering\", or there is no display\n");
    return 1;
  }
  std::printf("playing %s%s\n", core::visibleText(s->scene().manifest().name).c_str(),
              o.watch ? " (watching its files: save one to reload)" : "");
  std::fflush(stdout);
  bool recordFailed = false;
  if (!o.recordPath.empty())
    s->run().record({*core::portableScenePath(scenePath), 60, core::sceneFilesHash(core::sceneSourceFiles(s->scene())),
                     std::nullopt, 100});
  s->reloaded = [&](const core::ReloadReport& r) { sayReload(*s, r, o.recordPath, recordFailed); };
  if (o.inputPath.empty())  // the editor in this window; back here, the level reloaded
    s->edit = [&] {
      return editLevel(levelArgument(scenePath), registry, s->scene().findSystem("rendering")) != kWindowClosed;
    };
  stopOnSignals();
  const uint64_t frameErrors = Play(*s, o, input, window).run();
  alarm(0);  // the loop ended: no grace period runs out while the recording is written
  if (stopSignal)
    std::printf("stopped by signal %d at frame %llu\n", static_cast<int>(stopSignal),
                static_cast<unsigned long long>(s->run().frame()));
  if (!keepRecording(*s, o.recordPath)) recordFailed = true;
  return finishPlay(*s, o, window, frameErrors, recordFailed);
}

}  // namespace platon::app
