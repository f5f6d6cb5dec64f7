// A scene played in a window, and the tools every window mode has. `platon game`, `platon play`
// and the editor's play-test are each a Session and screens of their own; `shot`, `run` and
// `replay` drive the same core::Run (core/run.h) without a window, so one input plays the same
// frames in all of them.
//
// What a Session owns: the live scene (hot reload) and its Run (the frames, their buttons and
// presses, the console's lines, the recording), the fixed clock and the taps between frames, the
// picture (GameView: the camera and the scripts' drawing stepped with the simulation), and the
// tools: the console (`), the debug view (F2), the frame rate (F3), reload (F5), the editor (F4,
// through the mode's hand-off), a screenshot (F12), and notices that fade.
#pragma once
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "platon/core/display.h"
#include "platon/core/fixed_step.h"
#include "platon/core/live_scene.h"
#include "platon/core/run.h"
#include "platon/script/script_system.h"
#include "platon/session/game_view.h"

namespace platon::session {

class Session {
 public:
  // The scene to play (a window when it names "rendering"; no picture else).
  explicit Session(std::unique_ptr<core::LiveScene> live);
  // Another scene in the same window: a level loaded, a level restarted. Its run starts afresh;
  // the debug view stays as it was.
  void replace(std::unique_ptr<core::LiveScene> live);

  core::LiveScene& live() { return *live_; }
  core::Scene& scene() { return live_->scene(); }
  // The scene's actions (the engine's, then its mods'): what the window binds.
  const std::vector<core::Action>& actions() const { return live_->scene().actions(); }
  core::Run& run() { return *run_; }
  GameView& view() { return view_; }
  // The scene's window, or null (headless, or its scene names no "rendering").
  core::Display* display();
  script::GameStatus status();

  // --- the mode's say on the tools ---
  // F4: the mode's hand-off to the editor on this level; false when the window was closed there.
  // Unset: F4 does nothing. Back from it, the level is reloaded.
  std::function<bool()> edit;
  // After every reload that took (F5, a saved file, back from the editor) or was refused.
  std::function<void(const core::ReloadReport&)> reloaded;
  // Whether the console may open now (the game's menus keep it shut).
  bool consoleAllowed = true;

  // Reads the window once. The tools take their keys, and while the console is open, every key
  // and the text typed; what is left is the mode's (its menus and the player's buttons). A closed
  // window is passed on.
  core::WindowInput poll();
  // Looks for saved files and reloads the scene for them.
  void reloadIfSaved();
  void reload(const std::string& because);
  bool consoleOpen() const { return consoleOpen_; }
  // The player's keys: the scene's actions (the engine's and its mods'), each with the keys and
  // pad buttons the player chose for it, else its own; kept for the scenes that follow (a mod's
  // action is bound when a scene has it). Returns the names the window does not know.
  std::vector<std::string> bindKeys(const core::BindingChoices& choices);
  // Whether a key (SDL's name) is a tool's (F2, F3, F4, F5, F11, F12, `): the tools take it in
  // every mode, so no action may be bound to it.
  static bool isToolKey(const std::string& name);

  // The frames the clock says are due since the last call, at `speedPercent` of real time (`fast`:
  // one, whatever the clock). None while the console is open or a hard event holds the picture.
  int framesDue(int speedPercent = 100, bool fast = false);
  // Buttons tapped between two polls count once, on the next frame played (core/input.h).
  void tap(core::Buttons tapped) { taps_.add(tapped); }
  core::Buttons nextButtons(core::Buttons held) { return taps_.next(held); }
  // The frames due, holding `input`'s buttons, its taps counted once: the window modes' loop.
  // `stopAt(status)`, when given, ends the call after the frame it says. Returns the frames played.
  int playDue(const core::WindowInput& input, int speedPercent = 100, bool fast = false,
              const std::function<bool(const script::GameStatus&)>& stopAt = {});
  // One frame now, with `held` (a replay's buttons, headless play): the run's step and the
  // picture's; a repeated error is printed once. Returns the frame's error.
  std::optional<std::string> playFrame(core::Buttons held);
  // A hard event (a death, the goal) holds the picture a moment; the frames wait with it.
  bool frozen() const { return std::chrono::steady_clock::now() < freezeUntil_; }
  // The window could not open: the scene is played with no picture.
  void withoutWindow() { windowless_ = true; }
  // Time spent elsewhere (a menu, the editor, a load) is not play time: the clock starts from now.
  void hold();
  // The picture goes on without the game (the level-complete screen: the confetti falls).
  void idle();

  // A line under the heads-up text for `noticeSeconds`, then it fades (in one more second).
  void say(const std::string& text);
  double noticeSeconds = 4;
  // Shows the frame: the stage, the scripts' picture, the heads-up lines (when `hud`), `more`
  // lines under them, the notices and the console, `centre` text over it all.
  void draw(const std::vector<std::string>& centre = {}, const std::vector<std::string>& more = {}, bool hud = true);

 private:
  bool toolKey(core::Key key);
  bool consoleKey(core::Key key);
  void runConsoleLine();
  void afterReload(const core::ReloadReport& report);

  void applyBindings();
  void printScreen(const std::vector<std::string>& centre);

  std::unique_ptr<core::LiveScene> live_;
  std::optional<core::Run> run_;
  core::BindingChoices choices_;
  bool rebind_ = true;  // a scene came since the window's keys were bound for its actions
  GameView view_;
  core::FixedStep clock_{60};
  core::TapCarry taps_;
  std::chrono::steady_clock::time_point previous_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point freezeUntil_{};
  bool showFps_ = false;
  bool windowless_ = false;
  bool consoleOpen_ = false;
  std::string consoleLine_;
  // The text typed since the last poll: the console opened by its key in a poll takes what was typed
  // after the key in the same poll (fast typing, or a slow frame, put "`6 * 7" in one poll and lost the 6).
  std::string typedThisPoll_;
  std::vector<std::string> consoleLog_;  // the lines typed and their answers, the latest last
  struct Notice {
    std::string text;
    std::chrono::steady_clock::time_point shown;
  };
  std::vector<Notice> notices_;
  std::vector<std::string> printedScreen_;  // PLATON_PRINT_SCREEN: the text printed last
  std::string lastError_;                   // a frame's error, printed once however many frames repeat it
};

}  // namespace platon::session
