#include "platon/session/session.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "platon/core/visible_text.h"
#include "platon/session/user_folder.h"

namespace platon::session {

namespace {

constexpr size_t kConsoleLog = 6;  // lines of the console kept on screen
constexpr size_t kConsoleLineBytes = 400;

}  // namespace

Session::Session(std::unique_ptr<core::LiveScene> live) { replace(std::move(live)); }

void Session::replace(std::unique_ptr<core::LiveScene> live) {
  core::System* previous = live_ ? live_->scene().findSystem("rendering") : nullptr;
  if (core::System* rendering = live->scene().findSystem("rendering"); rendering && previous)
    rendering->carryOver(live->scene(), *previous);  // the same window
  live_ = std::move(live);
  run_.emplace(*live_);
  const bool debug = view_.debug();  // the overlay stays on from one level to the next
  view_ = GameView{};
  view_.setDebug(debug);
  view_.step(scene(), status(), 1.0 / clock_.hz());
  taps_.reset();
  consoleOpen_ = false;
  consoleLog_.clear();
  lastError_.clear();
  hold();
  rebind_ = true;
}

std::vector<std::string> Session::bindKeys(const core::BindingChoices& choices) {
  choices_ = choices;
  core::Display* d = display();
  if (!d) return {};
  rebind_ = false;
  return d->setBindings(core::bindingsFor(scene().actions(), choices_));
}

bool Session::isToolKey(const std::string& name) {
  static const char* const kTools[] = {"F2", "F3", "F4", "F5", "F11", "F12", "`"};
  return std::any_of(std::begin(kTools), std::end(kTools), [&](const char* k) { return name == k; });
}

// Binds the window for the scene's actions when a scene came since it was bound (the first poll;
// a reload or another level, which may have other actions: a mod's dash, or none now).
void Session::applyBindings() {
  core::Display* d = display();
  if (!d || !rebind_) return;
  rebind_ = false;
  (void)d->setBindings(core::bindingsFor(scene().actions(), choices_));  // unknown names were said at bindKeys
}

core::Display* Session::display() { return windowless_ ? nullptr : displayOf(scene()); }

script::GameStatus Session::status() { return statusOf(scene()); }

core::WindowInput Session::poll() {
  core::Display* d = display();
  if (!d) return {};
  applyBindings();
  core::WindowInput input = d->pollEvents();
  typedThisPoll_ = input.text;
  const bool typing = consoleOpen_;  // letters typed into the console are not the game's buttons
  if (consoleOpen_)
    for (const char c : input.text)
      if (c != '`' && consoleLine_.size() < kConsoleLineBytes) consoleLine_ += c;
  const bool f4 =
      std::any_of(input.keys.begin(), input.keys.end(), [](const core::KeyPress& k) { return k.name == "F4"; });
  if (f4 && edit && consoleAllowed && !consoleOpen_) {
    std::printf("editing %s (F4)\n", live_->manifestPath().c_str());
    std::fflush(stdout);
    bool open = true;
    try {
      open = edit();
    } catch (const std::exception& e) {
      say(e.what());
    }
    reload("the editor");
    run_->releaseButtons();
    taps_.reset();
    hold();  // the time in the editor was not play time
    core::WindowInput back;
    back.closed = !open;
    return back;
  }
  std::vector<core::Key> left;
  for (const core::Key key : input.pressed)
    if (!toolKey(key)) left.push_back(key);
  input.pressed = std::move(left);
  if (typing || consoleOpen_) input.held = input.tapped = 0, input.pressed.clear();
  return input;
}

bool Session::toolKey(core::Key key) {
  if (consoleKey(key)) return true;
  switch (key) {
    case core::Key::ShowFps:
      showFps_ = !showFps_;
      return true;
    case core::Key::Debug:
      view_.setDebug(!view_.debug());
      return true;
    case core::Key::Screenshot:
      if (core::Display* d = display()) {
        const std::string said = saveScreenshot(*d);
        say(said);
        std::printf("%s\n", said.c_str());
        std::fflush(stdout);
      }
      return true;
    case core::Key::Reload:
      if (!consoleAllowed) return false;
      reload("F5");
      return true;
    default:
      return false;
  }
}

bool Session::consoleKey(core::Key key) {
  if (!consoleOpen_) {
    if (key != core::Key::Console || !consoleAllowed) return false;
    if (!scene().findSystem("scripting")) {
      say("the console runs Lua in the level's scripts: this level has none");
      return true;
    }
    consoleOpen_ = true;
    consoleLine_.clear();
    if (const size_t at = typedThisPoll_.find('`'); at != std::string::npos)
      for (const char c : typedThisPoll_.substr(at + 1))
        if (c != '`' && consoleLine_.size() < kConsoleLineBytes) consoleLine_ += c;
    return true;
  }
  if (key == core::Key::Screenshot || key == core::Key::ShowFps || key == core::Key::Debug) return false;
  if (key == core::Key::Console || key == core::Key::Escape) {
    consoleOpen_ = false;
    hold();  // the level waited while it was open
  }
  if (key == core::Key::Backspace)
    while (!consoleLine_.empty()) {  // a whole UTF-8 character
      const auto last = static_cast<unsigned char>(consoleLine_.back());
      consoleLine_.pop_back();
      if ((last & 0xC0) != 0x80) break;
    }
  if (key == core::Key::Enter) runConsoleLine();
  return true;  // the game's other keys wait while the console is open
}

void Session::runConsoleLine() {
  if (consoleLine_.empty()) return;
  // Run before the next frame, and recorded there: a replay runs it at the same place.
  const std::optional<core::ConsoleAnswer> answer = run_->console(consoleLine_);
  if (!answer) return;
  std::printf("console> %s\n%s\n", core::visibleText(consoleLine_).c_str(),
              core::visibleText(answer->text, true).c_str());
  std::fflush(stdout);
  consoleLog_.push_back("> " + core::visibleText(consoleLine_, false));
  if (!answer->text.empty()) {
    std::string shown = core::visibleText(answer->text, false);
    if (shown.size() > 160) shown = shown.substr(0, 157) + "...";
    consoleLog_.push_back((answer->ok ? "" : "error: ") + shown);
  }
  if (consoleLog_.size() > kConsoleLog)
    consoleLog_.erase(consoleLog_.begin(), consoleLog_.end() - static_cast<long>(kConsoleLog));
  consoleLine_.clear();
}

void Session::reloadIfSaved() {
  if (std::optional<core::ReloadReport> r = live_->poll(0)) afterReload(*r);
}

void Session::reload(const std::string& because) { afterReload(live_->reload({because})); }

void Session::afterReload(const core::ReloadReport& report) {
  if (report.ok) {
    view_.step(scene(), status(), 1.0 / clock_.hz());  // the new version's stage drawn from now on
    rebind_ = true;
    say("reloaded");
  } else {
    say("reload refused: " + report.error);
  }
  if (reloaded) reloaded(report);
}

void Session::hold() {
  previous_ = std::chrono::steady_clock::now();
  freezeUntil_ = {};
}

int Session::framesDue(int speedPercent, bool fast) {
  const auto now = std::chrono::steady_clock::now();
  if (now < freezeUntil_) previous_ = now;  // frozen: the time passes unplayed
  // The assist mode slows the game's pace, never its frames: a slowed run replays bit for bit.
  const int due = fast ? 1
                       : clock_.advance(std::chrono::duration_cast<std::chrono::nanoseconds>(now - previous_).count() *
                                        speedPercent / 100);
  previous_ = now;
  if (due == 0 && !fast) std::this_thread::sleep_for(std::chrono::milliseconds(1));  // no vsync: do not spin
  return consoleOpen_ ? 0 : due;
}

int Session::playDue(const core::WindowInput& input, int speedPercent, bool fast,
                     const std::function<bool(const script::GameStatus&)>& stopAt) {
  const int due = framesDue(speedPercent, fast);
  if (!consoleOpen_) taps_.add(input.tapped);
  int played = 0;
  while (played < due) {
    playFrame(taps_.next(input.held));
    ++played;
    if (frozen() || (stopAt && stopAt(status()))) break;
  }
  return played;
}

std::optional<std::string> Session::playFrame(core::Buttons held) {
  std::optional<std::string> error = run_->step(held);
  if (error && *error != lastError_) {
    std::printf("frame %llu: error (the game goes on):\n%s\n", static_cast<unsigned long long>(run_->frame()),
                core::visibleText(*error, true).c_str());
    std::fflush(stdout);
  }
  lastError_ = error.value_or("");
  if (!display()) return error;  // headless: no picture to keep
  view_.step(scene(), status(), 1.0 / clock_.hz());
  // A hard event holds the picture a moment (the simulation waits with it: no frame is lost).
  if (const int frames = view_.feedback().takeFreeze(); frames > 0)
    freezeUntil_ = std::chrono::steady_clock::now() + std::chrono::milliseconds(1000 * frames / 60);
  return error;
}

void Session::idle() { view_.idle(scene()); }

void Session::say(const std::string& text) {
  notices_.push_back({core::visibleText(text, false), std::chrono::steady_clock::now()});
  if (notices_.size() > 3) notices_.erase(notices_.begin());
}

// With PLATON_PRINT_SCREEN set, the screen's text (menus, questions, level lists) is printed as it
// changes, "screen> " before each line: what a person reads there, for the journey tests.
void Session::printScreen(const std::vector<std::string>& centre) {
  static const bool wanted = std::getenv("PLATON_PRINT_SCREEN") != nullptr;
  if (!wanted || centre == printedScreen_) return;
  printedScreen_ = centre;
  std::printf("screen>\n");
  for (const std::string& line : centre) std::printf("screen> %s\n", core::visibleText(line, false).c_str());
  std::fflush(stdout);
}

void Session::draw(const std::vector<std::string>& centre, const std::vector<std::string>& more, bool hud) {
  core::Display* d = display();
  if (!d) return;
  const bool paused = consoleOpen_ || !centre.empty();
  const double alpha = paused ? 1.0 : clock_.alpha();
  const script::GameStatus st = status();
  core::View view = view_.view(scene(), alpha);
  view.showFps = showFps_;
  view.error = live_->lastError();
  if (hud) view.hud = hudLines(scene(), st);
  view.hud.insert(view.hud.end(), more.begin(), more.end());
  const auto now = std::chrono::steady_clock::now();
  // Read in noticeSeconds, then gone after a second more (noticeSeconds 0: at the next picture).
  const auto shownFor = std::chrono::duration<double>(noticeSeconds + (noticeSeconds > 0 ? 1 : 0));
  std::erase_if(notices_, [&](const Notice& n) { return now - n.shown >= shownFor; });
  for (const Notice& n : notices_) view.hud.push_back(n.text);
  if (consoleOpen_) {
    view.hud.emplace_back("console (Lua in the level's sandbox; Enter runs, ` or Esc closes):");
    view.hud.insert(view.hud.end(), consoleLog_.begin(), consoleLog_.end());
    view.hud.push_back("> " + core::visibleText(consoleLine_, false) + "_");
  }
  view.centreText = centre;
  printScreen(centre);
  d->present(view, view_.drawing(alpha));
}

}  // namespace platon::session
