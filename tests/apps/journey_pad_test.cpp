// A pad player's journey through `platon game`, in this process (SDL's virtual gamepad can only be
// pressed by the process that made it; no /dev/uinput is needed): the title -> Y opens the settings
// -> the d-pad down to the Jump row -> A, then X: Jump is pad X (Start while binding keeps it) ->
// Start saves and goes back -> A plays level 1 -> A alone no longer jumps, X does, the d-pad walks to
// the goal -> Start to the title -> Start asks to quit -> A quits. Each step is awaited on what the
// screen says (PLATON_PRINT_SCREEN, read from this process's own stdout) and checked in the files:
// the settings file, and the level's recording, which replays bit for bit.
#include <SDL2/SDL.h>
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "commands.h"
#include "platon/testing/temp_folder.h"

namespace {

using namespace std::chrono_literals;

// This process's stdout, read line by line while the game writes it (and copied to stderr for the
// test's log); restored when it ends.
class StdoutLines {
 public:
  StdoutLines() {
    std::fflush(stdout);
    int fds[2];
    if (pipe(fds) != 0) std::abort();
    readEnd_ = fds[0];
    saved_ = dup(1);
    dup2(fds[1], 1);
    close(fds[1]);
    reader_ = std::thread([this] { readAll(); });
  }
  ~StdoutLines() {
    std::fflush(stdout);
    dup2(saved_, 1);  // the pipe's last writer closed: the reader sees its end
    close(saved_);
    reader_.join();
    close(readEnd_);
  }
  StdoutLines(const StdoutLines&) = delete;
  StdoutLines& operator=(const StdoutLines&) = delete;

  // Waits for the count-th line holding `text` (the budget is the test's own); false on timeout.
  bool await(const std::string& text, size_t count = 1, std::chrono::seconds budget = 60s) {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, budget, [&] { return countLocked(text) >= count; });
  }
  size_t count(const std::string& text) {
    std::lock_guard lock(mutex_);
    return countLocked(text);
  }

 private:
  size_t countLocked(const std::string& text) const {
    return static_cast<size_t>(std::count_if(
        lines_.begin(), lines_.end(), [&](const std::string& line) { return line.find(text) != std::string::npos; }));
  }
  void readAll() {
    char buffer[4096];
    std::string partial;
    for (ssize_t n; (n = read(readEnd_, buffer, sizeof buffer)) > 0;) {
      if (write(2, buffer, static_cast<size_t>(n)) < 0) break;
      partial.append(buffer, static_cast<size_t>(n));
      std::lock_guard lock(mutex_);
      for (size_t end; (end = partial.find('\n')) != std::string::npos; partial.erase(0, end + 1))
        lines_.push_back(partial.substr(0, end));
      changed_.notify_all();
    }
  }

  int readEnd_ = -1, saved_ = -1;
  std::thread reader_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<std::string> lines_;
};

// SDL's virtual gamepad, plugged in before the game starts (the window opens it as it finds it).
// Its buttons change in SDL's own update of the pad (on the game's thread, as the game polls), one
// queued change an update: a press and its release are never both set between two updates, where
// the game would see neither (a loaded machine's slow frame lost presses that way).
class VirtualPad {
 public:
  VirtualPad() {
    if (SDL_InitSubSystem(SDL_INIT_JOYSTICK) != 0) return;
    SDL_VirtualJoystickDesc desc{};
    desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
    desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
    desc.naxes = SDL_CONTROLLER_AXIS_MAX;
    desc.nbuttons = 15;                 // A .. DPAD_RIGHT
    desc.button_mask = (1u << 15) - 1;  // virtual button i is controller button i
    desc.axis_mask = (1u << SDL_CONTROLLER_AXIS_MAX) - 1;
    desc.name = "journey pad";
    desc.userdata = this;
    desc.Update = [](void* self) { static_cast<VirtualPad*>(self)->applyNext(); };
    device_ = SDL_JoystickAttachVirtualEx(&desc);
    if (device_ >= 0) pad_ = SDL_JoystickOpen(device_);
  }
  ~VirtualPad() {
    if (pad_ && SDL_WasInit(SDL_INIT_JOYSTICK)) SDL_JoystickClose(pad_);
  }
  VirtualPad(const VirtualPad&) = delete;
  VirtualPad& operator=(const VirtualPad&) = delete;

  bool ready() const { return pad_ != nullptr; }
  // The button down or up from the pad's next update on; returns once the game's updates took it.
  void hold(SDL_GameControllerButton b, bool down) {
    std::unique_lock lock(mutex_);
    changes_.push_back({b, down});
    taken_.wait_for(lock, 60s, [&] { return changes_.empty(); });
  }
  // A press as a person makes one: down, up, and a tenth of a second before the next.
  void press(SDL_GameControllerButton b, int times = 1) {
    for (int i = 0; i < times; ++i) {
      hold(b, true);
      hold(b, false);
      std::this_thread::sleep_for(100ms);
    }
  }

 private:
  void applyNext() {  // in SDL's update of the pad, on the game's thread
    std::lock_guard lock(mutex_);
    if (changes_.empty()) return;
    SDL_JoystickSetVirtualButton(pad_, changes_.front().first, changes_.front().second ? 1 : 0);
    changes_.pop_front();
    taken_.notify_all();
  }

  int device_ = -1;
  SDL_Joystick* pad_ = nullptr;
  std::mutex mutex_;
  std::condition_variable taken_;
  std::deque<std::pair<SDL_GameControllerButton, bool>> changes_;
};

std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// What the pad does, step by step, each awaited on the screen: "" when the journey ends at the quit,
// else the step that did not come.
std::string padJourney(StdoutLines& out, VirtualPad& pad, const std::string& settingsFile) {
  if (!out.await("screen> > 1. ")) return "the title with level 1 chosen";
  pad.press(SDL_CONTROLLER_BUTTON_Y);
  if (!out.await("screen> Settings")) return "Y on the title: the settings";
  pad.press(SDL_CONTROLLER_BUTTON_DPAD_DOWN, 11);
  if (!out.await("screen> > Jump   Space   pad a, b <")) return "the d-pad down to the Jump row (keys Space, pad a, b)";
  pad.press(SDL_CONTROLLER_BUTTON_A);
  if (!out.await("screen> > Jump   press a key or pad button")) return "A on the Jump row: it asks for the button";
  pad.press(SDL_CONTROLLER_BUTTON_X);
  if (!out.await("settings: Jump is pad x")) return "X bound to Jump";
  if (!out.await("screen> > Jump   Space   pad x <")) return "the Jump row showing pad x";
  // Start while binding is the pad's Esc: the binding is kept, and Start is not bound.
  pad.press(SDL_CONTROLLER_BUTTON_A);
  if (!out.await("screen> > Jump   press a key or pad button", 2)) return "A again: asking again";
  pad.press(SDL_CONTROLLER_BUTTON_START);
  if (!out.await("screen> > Jump   Space   pad x <", 2)) return "Start while binding: the binding kept";
  if (out.count("Jump is pad start") != 0) return "Start was bound to Jump";
  pad.press(SDL_CONTROLLER_BUTTON_START);  // back to the title: saved
  if (!out.await("settings: music")) return "Start in the settings: saved and back";
  if (fileText(settingsFile).find("pad_jump x\n") == std::string::npos)
    return "pad_jump x in the settings file: " + fileText(settingsFile);
  pad.press(SDL_CONTROLLER_BUTTON_A);
  if (!out.await("playing cube_intro")) return "A on the title: level 1";
  pad.hold(SDL_CONTROLLER_BUTTON_A, true);  // A alone: no longer Jump
  std::this_thread::sleep_for(400ms);
  pad.hold(SDL_CONTROLLER_BUTTON_A, false);
  pad.hold(SDL_CONTROLLER_BUTTON_DPAD_RIGHT, true);
  std::this_thread::sleep_for(500ms);
  pad.press(SDL_CONTROLLER_BUTTON_X, 3);  // X while walking: jumps
  const bool finished = out.await("level complete: cube_intro", 1, 120s);
  pad.hold(SDL_CONTROLLER_BUTTON_DPAD_RIGHT, false);
  if (!finished) return "the d-pad held right to level 1's goal";
  if (!out.await("screen> Level complete!")) return "the level-complete screen";
  pad.press(SDL_CONTROLLER_BUTTON_START);
  if (!out.await("screen> > 2. ")) return "Start on the complete screen: the title, level 2 chosen";
  pad.press(SDL_CONTROLLER_BUTTON_START);
  if (!out.await("screen> Quit the game?")) return "Start on the title: the quit question";
  pad.hold(SDL_CONTROLLER_BUTTON_A,
           true);  // yes: the game ends (its release would wait for an update that never comes)
  return "";
}

TEST(Journey, APadPlayerBindsJumpToXInTheSettingsAndJumpsWithIt) {
  platon::testing::TempFolder data("journey_pad");
  setenv("SDL_VIDEODRIVER", "offscreen", 1);
  setenv("SDL_JOYSTICK_ALLOW_BACKGROUND_EVENTS", "1", 1);  // an offscreen window never has the focus
  setenv("SDL_AUDIODRIVER", "dummy", 1);
  setenv("PLATON_PRINT_SCREEN", "1", 1);
  setenv("XDG_DATA_HOME", data.path().c_str(), 1);
  setenv("XDG_CONFIG_HOME", data.path("config").c_str(), 1);
  VirtualPad pad;
  ASSERT_TRUE(pad.ready()) << SDL_GetError();
  const std::string runs = data.path("runs"), settingsFile = data.path("config/platon/settings.txt");
  int status = -1;
  std::string failed;
  {
    StdoutLines out;
    std::thread driver([&] {
      failed = padJourney(out, pad, settingsFile);
      if (failed.empty()) return;
      SDL_Event quit{};  // the window closed: the game ends, and the test with it
      quit.type = SDL_QUIT;
      SDL_PushEvent(&quit);
    });
    std::vector<std::string> words{"game", "--record", runs};
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    status = platon::app::findCommand("game")->run(static_cast<int>(argv.size()), argv.data());
    driver.join();
  }
  ASSERT_EQ(failed, "") << "the journey stopped at: " << failed;
  EXPECT_EQ(status, 0);

  // The recording: X's jumps in it, all while walking (A alone, before the walk, jumped not), and it
  // replays bit for bit.
  const std::string replay = runs + "/cube_intro.replay";
  const std::string text = fileText(replay);
  ASSERT_NE(text, "") << "no recording of level 1 in " << runs;
  std::istringstream lines(text);
  int jumps = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.empty() || line[0] < '0' || line[0] > '9' || line.find("jump") == std::string::npos) continue;
    ++jumps;
    EXPECT_NE(line.find("right"), std::string::npos) << "a jump without the walk (A still jumps?): " << line;
  }
  EXPECT_GT(jumps, 0) << "X held no jump:\n" << text;
  std::vector<std::string> words{"replay", replay};
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  EXPECT_EQ(platon::app::findCommand("replay")->run(static_cast<int>(argv.size()), argv.data()), 0)
      << "level 1's recording does not replay";
}

}  // namespace
