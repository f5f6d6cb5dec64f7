// The game: a title screen with the level select (levels done are ticked, read from the player's
// progress file), the levels played in a window with a pause menu, and on each finish the record
// saved and the next level. One window for the whole session: each level's scene takes over the
// previous one's rendering system (System::carryOver), as a hot reload does.
#include "game_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "campaign.h"
#include "commands.h"
#include "edit_command.h"
#include "engine_registry.h"
#include "pack_command.h"
#include "platon/core/audio.h"
#include "platon/core/data_root.h"
#include "platon/core/display.h"
#include "platon/core/live_scene.h"
#include "platon/core/manifest.h"
#include "platon/core/replay.h"
#include "platon/core/run.h"
#include "platon/core/visible_text.h"
#include "platon/script/script_system.h"
#include "platon/session/session.h"
#include "save_file.h"
#include "settings.h"

namespace platon::app {
namespace {

enum class Screen { Title, Playing, Paused, Complete, Settings, QuitAsked };

constexpr int kFirstKeyItem = 7;  // the settings screen's rows: 7 settings, the actions' keys, Back

const char* const kPauseItems[] = {"Resume", "Restart the level", "Level select", "Settings", "Quit"};

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}
constexpr int kPauseCount = 5;

// With --record DIR: one replay per level played, DIR/<folder>.replay (then <folder>-2.replay,
// ... : an existing file is never overwritten). A recording starts with the level's first frame
// and is written when the level is complete, left (another level, a restart, the title), the
// game quits, or the scene reloads. A reload changes the scene under the recording, and the new
// version starts from the carried-over state, which no replay (a fresh load) reproduces: so the
// recording ends there, as in `platon play`, and the next start of a level records again.
class LevelRecorder {
 public:
  explicit LevelRecorder(std::string folder) : folder_(std::move(folder)) {}
  bool on() const { return !folder_.empty(); }
  // Records `run` of `level` from its next frame on.
  void start(const CampaignLevel& level, core::Run& run, int speed) {
    if (!on()) return;
    level_ = level.folder;
    // Named from the game's data folder or the current one (a replay names no absolute path); a
    // campaign elsewhere is not recorded, and says so.
    const std::optional<std::string> scene = core::portableScenePath(level.scene);
    if (!scene) {
      std::fprintf(stderr, "not recording %s: %s is in neither the current folder nor the game's data folder\n",
                   level.folder.c_str(), level.scene.c_str());
      return;
    }
    run.record({*scene, 60, core::sceneFilesHash(core::sceneSourceFiles(run.scene())), std::nullopt, speed});
  }
  // Writes what `run` recorded since start() (nothing when no frame was); "" or what went wrong.
  std::string finish(core::Run& run) {
    const std::optional<core::Replay> replay = run.stopRecording();
    if (!replay || replay->frames() == 0) return "";
    std::string path;
    for (int n = 1; path.empty() || std::filesystem::exists(path); ++n)
      path = folder_ + "/" + level_ + (n == 1 ? "" : "-" + std::to_string(n)) + ".replay";
    try {
      std::filesystem::create_directories(folder_);
      core::writeReplay(*replay, path);
    } catch (const std::exception& e) {
      return std::string("recording not written: ") + e.what();
    }
    std::printf("recorded %s: %llu frames to %s\n", level_.c_str(), static_cast<unsigned long long>(replay->frames()),
                path.c_str());
    std::fflush(stdout);
    return "";
  }

 private:
  std::string folder_;
  std::string level_;
};

class Game {
 public:
  Game(std::vector<CampaignLevel> levels, Progress progress, std::string recordFolder, std::string settingsPath)
      : levels_(std::move(levels)),
        progress_(std::move(progress)),
        registry_(engineRegistry(Presentation::Window)),
        recording_(std::move(recordFolder)),
        settingsPath_(std::move(settingsPath)) {
    // A damaged settings file costs its lines, never the game: each says why, once, on the HUD too.
    std::vector<std::string> problems;
    settings_ = Settings::load(settingsPath_, problems);
    for (const std::string& p : problems) std::fprintf(stderr, "%s\n", core::visibleText(p, true).c_str());
    for (const std::string& p : problems) say(p);
    for (const CampaignLevel& l : levels_) {  // the names players see; a broken manifest shows its folder
      try {
        names_.push_back(core::loadManifest(l.scene).name);
      } catch (const std::exception&) {
        names_.push_back(l.folder);
      }
      if (names_.back().empty()) names_.back() = l.folder;
    }
  }

  int run(bool quitAfterFirstFrame = false, const std::string& firstFrameShot = "");

 private:
  bool load(size_t level);
  core::Display* display() { return session_ ? session_->display() : nullptr; }
  // The scene's audio controls, when it names "audio" (else the game is silent and nothing asks).
  core::AudioControls* audio() {
    core::System* system = session_ ? session_->scene().findSystem("audio") : nullptr;
    return system ? system->audio() : nullptr;
  }
  void sound(const char* name) {
    if (core::AudioControls* a = audio()) a->playNow(name);
  }
  // A line under the heads-up text that fades (session.h); kept until the first level is loaded.
  void say(const std::string& text) {
    if (session_)
      session_->say(text);
    else
      pending_.push_back(text);
  }
  // The title has its own tune; the pause menu holds effects and music; play and the level-complete
  // screen (whose goal sound is still ringing) go on.
  void holdSound() {
    core::AudioControls* a = audio();
    if (!a) return;
    a->setPaused(screen_ == Screen::Paused);
    if (screen_ == Screen::Title) a->playTune("title");
  }
  script::GameStatus status() { return session_->status(); }
  // Played slowed (the assist mode): the level is done, the time is no par run (campaign.h).
  bool assisted() const { return settings_.gameSpeed < 100; }
  void handle(const core::WindowInput& input);
  void menuKey(core::Key key);
  void titleKey(core::Key key);
  void pausedKey(core::Key key);
  void completeKey(core::Key key);
  void play() {
    screen_ = Screen::Playing;
    std::printf("playing %s\n", levels_[level_].folder.c_str());
    std::fflush(stdout);
    recording_.start(levels_[level_], session_->run(), settings_.gameSpeed);
  }
  void finishRecording() {
    if (!session_) return;
    if (std::string error = recording_.finish(session_->run()); !error.empty()) {
      say(error);
      std::fprintf(stderr, "%s\n", error.c_str());
    }
  }
  // After every reload (a saved file, F5, back from the editor): the frames recorded so far were
  // played on the version before.
  void afterReload(const core::ReloadReport& r) {
    if (!r.ok) return;
    std::printf("reloaded %s\n", levels_[level_].folder.c_str());
    std::fflush(stdout);
    finishRecording();
  }
  // F4 while playing: the editor on this level in the same window; back here, the session reloads
  // the level (the game's hot reload, which keeps the player where it was when the level allows it).
  bool editThisLevel() {
    const bool open = editLevel(levelArgument(levels_[level_].scene), registry_,
                                session_->scene().findSystem("rendering")) != kWindowClosed;
    std::printf("back from the editor\n");
    std::fflush(stdout);
    return open;
  }
  void stepSimulation(const core::WindowInput& input);
  // The settings screen (from the title and the pause menu): volumes and screen shake, applied at
  // once and saved as the screen is left.
  // Quitting asks first (Up from Resume is Quit, and Esc on the title is a key pressed often).
  void askToQuit() {
    quitFrom_ = screen_, screen_ = Screen::QuitAsked;
    sound("menu_select");
    std::printf("quit asked\n");
    std::fflush(stdout);
  }
  void openSettings() {
    settingsFrom_ = screen_, screen_ = Screen::Settings, settingsItem_ = 0;
    sound("menu_select");
  }
  void settingsKey(core::Key key);
  bool changeSetting(int item, int step, bool enter);
  void leaveSettings();
  bool bindKey(const core::WindowInput& input);
  std::vector<std::string> settingsLines() const;
  void applySettings() {
    if (core::AudioControls* a = audio())
      a->setVolumes(static_cast<float>(settings_.musicVolume) / 100, static_cast<float>(settings_.effectsVolume) / 100);
    session_->view().feedback().setShake(settings_.screenShake);
    if (core::Display* d = display()) {
      try {
        if (const std::vector<std::string> unknown = session_->bindKeys(settings_.keys); !unknown.empty())
          session_->bindKeys(withoutUnknownKeys(unknown));
        // Only what changed: a window made full screen again, or its swap interval set again,
        // costs a reconfiguration (and start-up time) for nothing.
        if (applied_.fullscreen != settings_.fullscreen) d->setFullscreen(settings_.fullscreen);
        if (applied_.vsync != settings_.vsync) d->setVsync(settings_.vsync);
        if (applied_.multisamples != settings_.multisamples) d->setMultisamples(settings_.multisamples);
        applied_ = settings_;
      } catch (const std::exception& e) {  // no display: the game says so when it opens
        say(e.what());
      }
    }
  }
  // The settings' keys without the names no key or pad button has, each said; an action left with
  // none keeps its default (README: a line the game cannot read keeps its default).
  const core::BindingChoices& withoutUnknownKeys(const std::vector<std::string>& unknown) {
    const std::vector<core::Action>& actions = session_->actions();
    for (const std::string& name : unknown) {
      std::string message = "settings: no key or pad button is named '" + core::visibleText(name, false) + "'";
      for (const bool pad : {false, true}) {
        auto& chosen = pad ? settings_.keys.pad : settings_.keys.keys;
        for (auto it = chosen.begin(); it != chosen.end();) {
          std::vector<std::string>& list = it->second;
          const auto gone = std::remove(list.begin(), list.end(), name);
          if (gone == list.end() || (list.erase(gone, list.end()), !list.empty())) {
            ++it;
            continue;
          }
          const std::optional<int> i = core::actionIndex(actions, it->first);
          const core::Action* a = i ? &actions[static_cast<size_t>(*i)] : nullptr;
          message += "; " + (a ? a->label : it->first) + " keeps its default (" +
                     (a ? joined(pad ? a->pad : a->keys) : std::string("none")) + ")";
          it = chosen.erase(it);
        }
      }
      std::fprintf(stderr, "%s\n", message.c_str());
      say(message);
    }
    return settings_.keys;
  }
  // The settings screen's key rows: the scene's actions a player binds (a mod's too).
  std::vector<const core::Action*> keyRows() const {
    std::vector<const core::Action*> rows;
    for (const core::Action& a : session_->actions())
      if (a.bindable) rows.push_back(&a);
    return rows;
  }
  int settingsItems() const { return kFirstKeyItem + static_cast<int>(keyRows().size()) + 1; }  // then Back
  void draw();
  std::vector<std::string> titleLines() const;
  std::string levelLine(size_t i) const;

  std::vector<CampaignLevel> levels_;
  std::vector<std::string> names_;
  Progress progress_;
  core::SystemRegistry registry_;
  std::optional<session::Session> session_;  // the level loaded, its run, picture and tools
  std::vector<std::string> pending_;         // notices from before the first level loaded
  Screen screen_ = Screen::Title;
  size_t level_ = 0;     // the level loaded (playing, or shown behind the title)
  size_t selected_ = 0;  // the title screen's cursor
  bool loaded_ = false;  // a load happened this loop: its time is not play time
  int menuItem_ = 0;
  bool quit_ = false;
  LevelRecorder recording_;
  Settings settings_;
  Settings applied_;  // what the window was last told (full screen, vsync, samples): at first, how it opens
  std::string settingsPath_;
  Screen settingsFrom_ = Screen::Title;
  Screen quitFrom_ = Screen::Title;
  bool saidSilent_ = false;  // the game said once, on screen, why it plays silent
  int settingsItem_ = 0;
  int binding_ = -1;  // the button whose key the settings screen waits for
};

bool Game::load(size_t level) {
  finishRecording();  // the level played so far ends here, whether or not the next one loads
  std::unique_ptr<core::LiveScene> next;
  try {
    next = std::make_unique<core::LiveScene>(levels_[level].scene, registry_, true);
  } catch (const std::exception& e) {
    const std::string why = core::errorReport(e);
    std::fprintf(stderr, "%s\n", core::visibleText(why, true).c_str());
    say(why);
    return false;
  }
  if (!next->scene().findSystem("rendering")) {
    say(levels_[level].scene + ": the scene does not name \"rendering\"");
    return false;
  }
  if (session_) {
    session_->replace(std::move(next));  // the same window
  } else {
    session_.emplace(std::move(next));
    session_->edit = [this] { return editThisLevel(); };
    session_->reloaded = [this](const core::ReloadReport& r) { afterReload(r); };
    for (const std::string& notice : pending_) session_->say(notice);
    pending_.clear();
  }
  level_ = level;
  loaded_ = true;
  applySettings();
  if (core::AudioControls* a = audio(); a && !saidSilent_ && !a->silentBecause().empty()) {
    say(a->silentBecause() + "; the game plays silent");  // on screen: stderr is not where a player looks
    saidSilent_ = true;
  }
  return true;
}

// A level's line on the title: its number and name, and done (best time, deaths, par), locked, or
// its par.
std::string Game::levelLine(size_t i) const {
  std::string line = (i == selected_ ? "> " : "  ") + std::to_string(i + 1) + ". " + names_[i];
  const uint64_t par = levels_[i].parFrames;
  if (const LevelRecord* r = progress_.record(levels_[i].folder)) {
    line += "   done " + session::clockText(r->bestFrames) + ", " + std::to_string(r->fewestDeaths) +
            (r->fewestDeaths == 1 ? " death" : " deaths") + (r->assisted ? " (assist)" : "");
    if (par && !r->assisted && r->bestFrames <= par) line += "  * par";
  } else if (!progress_.open(levels_, i)) {
    line += "   (locked)";
  } else if (par) {
    line += "   par " + session::clockText(par, false);
  }
  return i == selected_ ? line + " <" : line;
}

std::vector<std::string> Game::titleLines() const {
  std::vector<std::string> lines{"PLATON", "a platformer on the faces of the solids", ""};
  for (size_t i = 0; i < levels_.size(); ++i) {
    if (levels_[i].yours && (i == 0 || !levels_[i - 1].yours)) lines.push_back("your levels:");
    lines.push_back(levelLine(i));
  }
  lines.push_back("");
  lines.push_back(progress_.open(levels_, selected_)
                      ? "Up/Down choose, Enter play, Tab settings, Esc quit (pad: A, Y, Start)"
                      : "Finish the level before it to open this one");
  return lines;
}

void Game::handle(const core::WindowInput& input) {
  if (input.closed) quit_ = true;
  if (bindKey(input)) return;
  // Another window took the keyboard: the game waits in its pause menu (keys held then never come up).
  if (input.focusLost && screen_ == Screen::Playing) {
    screen_ = Screen::Paused, menuItem_ = 0;
    std::printf("paused: the window lost the focus\n");
    std::fflush(stdout);
  }
  for (const core::Key key : input.pressed) menuKey(key);
  holdSound();
}

void Game::menuKey(core::Key key) {
  switch (screen_) {
    case Screen::Title:
      titleKey(key);
      break;
    case Screen::Playing:
      if (key == core::Key::Escape) screen_ = Screen::Paused, menuItem_ = 0;
      break;
    case Screen::Paused:
      pausedKey(key);
      break;
    case Screen::Settings:
      settingsKey(key);
      break;
    case Screen::QuitAsked:  // Enter quits; Esc goes back where the question came from
      if (key == core::Key::Enter) quit_ = true;
      if (key == core::Key::Escape) screen_ = quitFrom_, sound("menu_move");
      break;
    case Screen::Complete:
      completeKey(key);
      break;
  }
}

void Game::titleKey(core::Key key) {
  if (key == core::Key::Escape) askToQuit();
  if (key == core::Key::Settings) openSettings();
  if ((key == core::Key::Up || key == core::Key::Down) && levels_.size() > 1) {
    // The cursor moves whether or not the level loads (a broken one says why on the HUD);
    // behind the title, the chosen level's stage when it does.
    const size_t n = levels_.size();
    selected_ = key == core::Key::Up ? (selected_ + n - 1) % n : (selected_ + 1) % n;
    load(selected_);
    sound("menu_move");
  }
  if (key != core::Key::Enter) return;
  if (!progress_.open(levels_, selected_))
    sound("menu_move");  // locked
  else if (load(selected_))
    sound("menu_select"), play();
}

void Game::pausedKey(core::Key key) {
  if (key == core::Key::Escape) screen_ = Screen::Playing, session_->hold();
  if (key == core::Key::Up) menuItem_ = (menuItem_ + kPauseCount - 1) % kPauseCount, sound("menu_move");
  if (key == core::Key::Down) menuItem_ = (menuItem_ + 1) % kPauseCount, sound("menu_move");
  if (key != core::Key::Enter) return;
  sound("menu_select");
  if (menuItem_ == 0) screen_ = Screen::Playing, session_->hold();
  if (menuItem_ == 1 && load(level_)) play();
  if (menuItem_ == 2) finishRecording(), screen_ = Screen::Title, selected_ = level_;
  if (menuItem_ == 3) openSettings();
  if (menuItem_ == 4) askToQuit();
}

void Game::completeKey(core::Key key) {
  if (key != core::Key::Enter && key != core::Key::Escape) return;
  if (level_ + 1 < levels_.size() && key == core::Key::Enter) {
    if (load(level_ + 1)) play();
    return;
  }
  // The level select, its cursor on the next level (now open).
  screen_ = Screen::Title;
  selected_ = level_ + 1 < levels_.size() ? level_ + 1 : level_;
  load(selected_);
}

// Changes the settings row `item` by `step` (Left -1, Right 1) or Enter; whether it changed.
bool Game::changeSetting(int item, int step, bool enter) {
  const bool flip = step != 0 || enter;
  switch (item) {
    case 0:
      settings_.musicVolume = std::clamp(settings_.musicVolume + 10 * step, 0, 100);
      return step != 0;
    case 1:
      settings_.effectsVolume = std::clamp(settings_.effectsVolume + 10 * step, 0, 100);
      return step != 0;
    case 2:
      if (flip) settings_.screenShake = !settings_.screenShake;
      return flip;
    case 3:
      if (flip) settings_.fullscreen = !settings_.fullscreen;
      return flip;
    case 4:
      if (flip) settings_.vsync = !settings_.vsync;
      return flip;
    case 5:
      settings_.gameSpeed = std::clamp(settings_.gameSpeed + 10 * step, 50, 100);
      return step != 0;
    case 6: {  // auto (-1), off, 2x, 4x, 8x
      static constexpr int kSamples[] = {-1, 0, 2, 4, 8};
      const auto found = std::find(std::begin(kSamples), std::end(kSamples), settings_.multisamples);
      const int at = found == std::end(kSamples) ? 0 : static_cast<int>(found - std::begin(kSamples));
      const int next = step ? std::clamp(at + step, 0, 4) : enter ? (at + 1) % 5 : at;
      const bool changed = kSamples[next] != settings_.multisamples;
      settings_.multisamples = kSamples[next];
      return changed;
    }
    default:
      return false;
  }
}

void Game::settingsKey(core::Key key) {
  const int items = settingsItems();
  if (key == core::Key::Up) settingsItem_ = (settingsItem_ + items - 1) % items, sound("menu_move");
  if (key == core::Key::Down) settingsItem_ = (settingsItem_ + 1) % items, sound("menu_move");
  const int step = key == core::Key::Right ? 1 : key == core::Key::Left ? -1 : 0;
  const bool enter = key == core::Key::Enter;
  if (changeSetting(settingsItem_, step, enter)) applySettings(), sound("menu_move");
  // The rows after the seven settings are the actions' keys, in keyRows' order.
  if (enter && settingsItem_ >= kFirstKeyItem && settingsItem_ < items - 1)
    binding_ = settingsItem_ - kFirstKeyItem;  // the next key or pad button pressed
  if (key == core::Key::Escape || (enter && settingsItem_ == items - 1)) leaveSettings();
}

void Game::leaveSettings() {
  screen_ = settingsFrom_;
  if (const std::string error = settings_.save(settingsPath_); !error.empty()) {
    say(error);
    std::fprintf(stderr, "%s\n", error.c_str());
  }
  std::printf("settings: music %d%%, effects %d%%, screen shake %s, game speed %d%%\n", settings_.musicVolume,
              settings_.effectsVolume, settings_.screenShake ? "on" : "off", settings_.gameSpeed);
  std::fflush(stdout);
  sound("menu_select");
}

// While a key is being bound, the next key or pad button pressed is it (Escape, and the pad's
// Start, its Escape, keep the old ones).
bool Game::bindKey(const core::WindowInput& input) {
  const bool pad = input.lastKey.empty() && !input.lastPadButton.empty();
  if (screen_ != Screen::Settings || binding_ < 0 || (input.lastKey.empty() && !pad)) return false;
  if (session::Session::isToolKey(input.lastKey)) return false;  // it did its tool's work (F12: a screenshot)
  const std::vector<const core::Action*> rows = keyRows();
  const bool kept = pad ? input.lastPadButton == "start" : input.lastKey == "Escape";
  if (!kept && binding_ < static_cast<int>(rows.size())) {
    const core::Action& action = *rows[static_cast<size_t>(binding_)];
    const std::string& name = pad ? input.lastPadButton : input.lastKey;
    (pad ? settings_.keys.pad : settings_.keys.keys)[action.name] = {name};
    applySettings();
    std::printf("settings: %s is %s%s\n", action.label.c_str(), pad ? "pad " : "", name.c_str());
    std::fflush(stdout);
  }
  binding_ = -1;
  sound("menu_select");
  return true;
}

std::vector<std::string> Game::settingsLines() const {
  const std::vector<const core::Action*> rows = keyRows();
  const core::KeyBindings bound = core::bindingsFor(session_->actions(), settings_.keys);
  auto keys = [&](size_t row) {
    const auto i = static_cast<size_t>(rows[row] - session_->actions().data());
    const std::string list = joined(bound.keys[i]) + "   pad " + (bound.pad[i].empty() ? "-" : joined(bound.pad[i]));
    return binding_ == static_cast<int>(row) ? "press a key or pad button (Esc or Start: keep " + list + ")" : list;
  };
  std::vector<std::string> items = {"Music volume   < " + std::to_string(settings_.musicVolume) + "% >",
                                    "Effects volume   < " + std::to_string(settings_.effectsVolume) + "% >",
                                    std::string("Screen shake   ") + (settings_.screenShake ? "on" : "off"),
                                    std::string("Full screen   ") + (settings_.fullscreen ? "on" : "off"),
                                    std::string("Vsync   ") + (settings_.vsync ? "on" : "off"),
                                    "Game speed (assist)   < " + std::to_string(settings_.gameSpeed) + "% >",
                                    "Multisampling   < " +
                                        (settings_.multisamples < 0    ? std::string("auto")
                                         : settings_.multisamples == 0 ? std::string("off")
                                                                       : std::to_string(settings_.multisamples) + "x") +
                                        " >"};
  for (size_t row = 0; row < rows.size(); ++row) items.push_back(rows[row]->label + "   " + keys(row));
  items.push_back("Back");
  std::vector<std::string> lines{"Settings", ""};
  for (int i = 0; i < static_cast<int>(items.size()); ++i)
    lines.push_back((i == settingsItem_ ? "> " : "  ") + items[static_cast<size_t>(i)] +
                    (i == settingsItem_ ? " <" : ""));
  lines.push_back("");
  lines.push_back("Up/Down choose, Left/Right change, Enter sets a key or pad button, Esc back (pad: A, Start)");
  return lines;
}

void Game::stepSimulation(const core::WindowInput& input) {
  // The level-complete screen: the picture goes on (the goal's confetti falls), the game does not.
  if (screen_ == Screen::Complete) {
    for (int due = session_->framesDue(); due > 0; --due) session_->idle();
    return;
  }
  if (screen_ != Screen::Playing) {
    session_->hold();  // a menu's time is not play time
    return;
  }
  const auto reached = [](const script::GameStatus& st) { return st.won; };
  session_->playDue(input, settings_.gameSpeed, false, reached);
  const script::GameStatus st = status();
  if (!st.won) return;
  std::printf("level complete: %s in %s with %d deaths\n", levels_[level_].folder.c_str(),
              session::clockText(st.wonFrame).c_str(), st.deaths);
  std::fflush(stdout);
  if (!progress_.finish(levels_[level_].folder, st.wonFrame, st.deaths, assisted())) say(progress_.lastError());
  screen_ = Screen::Complete;
  finishRecording();
}

void Game::draw() {
  const script::GameStatus st = status();
  std::vector<std::string> centre;
  switch (screen_) {
    case Screen::Title:
      centre = titleLines();
      break;
    case Screen::Paused:
      centre = {"Paused"};
      for (int i = 0; i < kPauseCount; ++i)
        centre.push_back((i == menuItem_ ? "> " : "  ") + std::string(kPauseItems[i]) + (i == menuItem_ ? " <" : ""));
      break;
    case Screen::Complete: {
      const uint64_t par = levels_[level_].parFrames;
      std::string parText;
      if (par != 0 && assisted())
        parText = "    at " + std::to_string(settings_.gameSpeed) + "% speed: par is for full speed";
      else if (par != 0)
        parText = st.wonFrame <= par ? "    under par (" + session::clockText(par, false) + ")!"
                                     : "    par " + session::clockText(par, false);
      centre = {"Level complete!",
                session::clockText(st.wonFrame) + "    " + std::to_string(st.deaths) + " deaths" + parText,
                level_ + 1 < levels_.size() ? "Enter: next level    Esc: level select"
                                            : "The campaign is done. Enter: level select"};
      break;
    }
    case Screen::Settings:
      centre = settingsLines();
      break;
    case Screen::QuitAsked:
      centre = {"Quit the game?", "", "Enter: quit    Esc: back"};
      break;
    case Screen::Playing:
      break;
  }
  // The level's heads-up lines belong to the level: not behind the title or the settings.
  const bool hud = screen_ == Screen::Playing || screen_ == Screen::Paused || screen_ == Screen::Complete;
  session_->draw(centre, {}, hud);
}

int Game::run(bool quitAfterFirstFrame, const std::string& firstFrameShot) {
  const size_t firstOpen = static_cast<size_t>(
      std::find_if(levels_.begin(), levels_.end(), [&](const CampaignLevel& l) { return !progress_.done(l.folder); }) -
      levels_.begin());
  // The first level not done yet behind the title; if it will not load, the next that does.
  selected_ = firstOpen < levels_.size() ? firstOpen : 0;
  bool any = false;
  for (size_t k = 0; k < levels_.size() && !any; ++k) any = load((selected_ + k) % levels_.size());
  if (!any) return 1;
  try {
    display()->pollEvents();  // opens the window
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  bool titleShown = false;
  while (!quit_) {
    session_->reloadIfSaved();
    if (!display()) return 1;
    // The console and the editor (F4) are for the level being played, not the menus.
    session_->consoleAllowed = screen_ == Screen::Playing;
    const core::WindowInput input = session_->poll();
    loaded_ = false;
    handle(input);
    if (quit_) break;
    if (!display()) return 1;       // a load in handle() replaced the scene, and with it the rendering system
    if (loaded_) session_->hold();  // loading is not play time
    stepSimulation(input);
    draw();
    if (!titleShown) {  // the window shows the title and reads keys from now on (tests wait for it)
      titleShown = true;
      std::printf("title screen: %zu levels\n", levels_.size());
      std::fflush(stdout);
    }
    if (!firstFrameShot.empty()) {
      try {
        display()->saveScreenshot(firstFrameShot);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
      }
    }
    if (quitAfterFirstFrame) break;
  }
  finishRecording();
  const script::GameStatus st = status();
  std::printf("quit on %s: face %u at (%d, %d), %llu frames played\n", levels_[level_].folder.c_str(), st.face, st.x,
              st.y, static_cast<unsigned long long>(st.time));
  return 0;
}

}  // namespace

int gameCommand(int argc, char** argv) {
  std::string campaignPath = "levels/campaign.txt";
  std::string progressPath = Progress::defaultPath();
  std::string settingsPath = Settings::defaultPath();
  bool quitAfterFirstFrame = false;
  std::string firstFrameShot;  // the title screen as a PNG, then quit (docs, tests)
  std::string recordFolder, levelsFolder = userLevelsFolder();
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--campaign" && i + 1 < argc)
      campaignPath = argv[++i];
    else if (a == "--progress" && i + 1 < argc)
      progressPath = argv[++i];
    else if (a == "--settings" && i + 1 < argc)
      settingsPath = argv[++i];
    else if (a == "--quit-after-first-frame")
      quitAfterFirstFrame = true;  // for start-up benchmarks
    else if (a == "--first-frame-shot" && i + 1 < argc)
      firstFrameShot = argv[++i], quitAfterFirstFrame = true;
    else if (a == "--record" && i + 1 < argc)
      recordFolder = argv[++i];
    else if (a == "--levels" && i + 1 < argc)
      levelsFolder = argv[++i];
    else {
      return usageError("game");
    }
  }
  try {
    std::vector<CampaignLevel> levels = readCampaign(core::resolveDataPath(campaignPath));
    for (CampaignLevel& l : userLevels(levelsFolder)) levels.push_back(std::move(l));
    Game game(std::move(levels), Progress(progressPath), recordFolder, settingsPath);
    return game.run(quitAfterFirstFrame, firstFrameShot);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
}

}  // namespace platon::app
