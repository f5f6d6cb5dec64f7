// The window's tools every mode has (session.h), driven through a window of the test's own: the
// keys it reads and the pictures it is shown. The game, `play` and the editor's play-test are each
// a Session, so what holds here holds in all three.
#include "platon/session/session.h"

#include <deque>

#include <gtest/gtest.h>

#include "platon/core/display.h"
#include "platon/core/live_scene.h"
#include "platon/script/script_system.h"
#include "platon/testing/temp_folder.h"

namespace platon::session {
namespace {

// A window of the test's own: it hands out the polls the test queued and keeps what it is shown.
class TestWindow final : public core::Display, public core::System {
 public:
  std::deque<core::WindowInput> polls;
  std::vector<core::View> shown;
  core::WindowInput pollEvents() override {
    if (polls.empty()) return {};
    core::WindowInput next = polls.front();
    polls.pop_front();
    return next;
  }
  void present(const core::View& view, const core::DrawList&) override { shown.push_back(view); }
  void resize(int, int) override {}
  std::vector<uint8_t> capture(int& width, int& height) override { return width = height = 0, std::vector<uint8_t>{}; }
  void saveScreenshot(const std::string&) override {}
  std::vector<std::string> setBindings(const core::KeyBindings&) override { return {}; }
  void setFullscreen(bool) override {}
  void setVsync(bool) override {}
  void setMultisamples(int) override {}
  core::Display* display() override { return this; }
};

core::WindowInput keys(std::vector<core::Key> pressed, std::string text = "") {
  core::WindowInput in;
  in.pressed = std::move(pressed);
  in.text = std::move(text);
  return in;
}

core::KeyPress named(const std::string& name) {
  core::KeyPress k;
  k.name = name;
  return k;
}

bool shows(const core::View& view, const std::string& line) {
  for (const std::string& l : view.hud)
    if (l.find(line) != std::string::npos) return true;
  return false;
}

struct Played {
  testing::TempFolder folder{"session"};
  core::SystemRegistry registry;
  TestWindow* window = nullptr;
  std::unique_ptr<Session> session;
  Played() {
    registry.add("scripting", script::makeScriptSystem);
    registry.add("rendering", [this](core::Scene&) {
      auto w = std::make_unique<TestWindow>();
      window = w.get();
      return w;
    });
    folder.write("level.lua",
                 "counter = 5\n"
                 "local level = { start = { face = 0, x = 600, y = 700 } }\n"
                 "function level.build(game) game.world.line(game.world.face(1), 0, 512, 4096, 512) end\n"
                 "return level\n");
    const std::string scene = folder.write(
        "scene.lua",
        "return { systems = { 'scripting', 'rendering' }, scripts = { preset = 'game', level = 'level.lua' } }\n");
    session = std::make_unique<Session>(std::make_unique<core::LiveScene>(scene, registry, false));
  }
  // One poll and one picture, as a mode's loop does; `frames` played with nothing held.
  core::WindowInput loop(core::WindowInput in, int frames = 0) {
    window->polls.push_back(std::move(in));
    const core::WindowInput left = session->poll();
    for (int f = 0; f < frames && !session->consoleOpen(); ++f) session->playFrame(0);
    session->draw();
    return left;
  }
};

TEST(Session, TheConsoleRunsALineAndHoldsTheGameWhileOpen) {
  Played p;
  p.loop({}, 3);
  const core::WindowInput opened = p.loop(keys({core::Key::Console}));
  EXPECT_TRUE(p.session->consoleOpen());
  EXPECT_TRUE(opened.pressed.empty()) << "the console's key is the tools'";
  core::WindowInput typing = keys({}, "counter * 2");
  typing.held = typing.tapped = core::InputFrame::bit(core::Button::Right);
  const core::WindowInput typed = p.loop(typing);
  EXPECT_EQ(typed.held, 0) << "letters typed into the console are no buttons";
  EXPECT_EQ(typed.tapped, 0);
  p.loop(keys({core::Key::Enter}));
  EXPECT_TRUE(shows(p.window->shown.back(), "> counter * 2"));
  EXPECT_TRUE(shows(p.window->shown.back(), "10"));
  EXPECT_EQ(p.session->framesDue(100, true), 0) << "the game waits while the console is open";
  const core::WindowInput closed = p.loop(keys({core::Key::Escape}));
  EXPECT_FALSE(p.session->consoleOpen());
  EXPECT_TRUE(closed.pressed.empty()) << "Esc closed the console: it is not the mode's (a pause, a quit)";
  EXPECT_EQ(p.session->framesDue(100, true), 1);
  EXPECT_EQ(p.session->run().frame(), 3u);
}

// Typed fast, or read in one slow frame, the console's key and the line after it come in one poll:
// the line is the console's from the key on (the CI's loaded window test lost the "6" of "6 * 7"),
// and what came before the key is not; a line typed whole then run in the next poll is too.
TEST(Session, TheConsoleTakesWhatIsTypedAfterItsKeyInTheSamePoll) {
  Played p;
  p.loop({}, 3);
  p.loop(keys({core::Key::Console}, "x`counter * 3"));
  ASSERT_TRUE(p.session->consoleOpen());
  p.loop(keys({core::Key::Enter}));
  EXPECT_TRUE(shows(p.window->shown.back(), "> counter * 3")) << "the line typed with the key";
  EXPECT_TRUE(shows(p.window->shown.back(), "15"));
  p.loop(keys({core::Key::Escape}));
  // The key, the line and Enter in one poll: the line runs.
  p.loop(keys({core::Key::Console, core::Key::Enter}, "`counter + 1"));
  EXPECT_TRUE(shows(p.window->shown.back(), "> counter + 1"));
  EXPECT_TRUE(shows(p.window->shown.back(), "6"));
}

TEST(Session, TheMenusKeepTheConsoleAndTheEditorShut) {
  Played p;
  int edits = 0;
  p.session->edit = [&] { return ++edits, true; };
  p.session->consoleAllowed = false;  // a menu is shown
  core::WindowInput f4 = keys({core::Key::Console});
  f4.keys.push_back(named("F4"));
  const core::WindowInput left = p.loop(f4);
  EXPECT_FALSE(p.session->consoleOpen());
  EXPECT_EQ(edits, 0);
  ASSERT_EQ(left.pressed.size(), 1u) << "the key goes to the menu";
  p.session->consoleAllowed = true;  // playing
  core::WindowInput again;
  again.keys.push_back(named("F4"));
  p.loop(again);
  EXPECT_EQ(edits, 1);
}

TEST(Session, F5ReloadsAndTheModeHearsOfIt) {
  Played p;
  int reloads = 0;
  p.session->reloaded = [&](const core::ReloadReport& r) { reloads += r.ok ? 1 : 100; };
  p.loop({}, 2);
  const core::WindowInput left = p.loop(keys({core::Key::Reload}));
  EXPECT_EQ(reloads, 1);
  EXPECT_TRUE(left.pressed.empty());
  EXPECT_TRUE(shows(p.window->shown.back(), "reloaded"));
}

TEST(Session, ANoticeFades) {
  Played p;
  p.session->noticeSeconds = 0;  // shown for no time at all: gone at the next picture
  p.session->say("a notice");
  p.loop({});
  EXPECT_FALSE(shows(p.window->shown.back(), "a notice"));
  p.session->noticeSeconds = 60;
  p.session->say("another notice");
  p.loop({});
  EXPECT_TRUE(shows(p.window->shown.back(), "another notice"));
}

}  // namespace
}  // namespace platon::session
