// Hot reload: a saved file is seen, the new version takes over the player's place and state
// where it can, a broken edit leaves the last good version running, and module state crosses
// over through save/onReload.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <thread>

#include <gtest/gtest.h>

#include "platon/core/file_watch.h"
#include "platon/core/live_scene.h"
#include "platon/script/script_system.h"
#include "platon/testing/rng.h"
#include "platon/testing/temp_folder.h"

namespace platon::script {
namespace {

using core::Button;
using core::InputFrame;
using Folder = testing::TempFolder;

const char* kManifest =
    "return { systems = { 'scripting' }, gravity = 0.35, scripts = { player = 'scripts/player.lua',\n"
    "  progression = 'scripts/progression.lua', level = 'level.lua', rules = 'scripts/rules/game.lua' } }\n";

// A floor on every face, the goal far away; `extra` goes into build(), `hooks` into the module.
std::string level(const std::string& extra = "", const std::string& hooks = "", const std::string& message = "hello") {
  return "local level = { start = { face = 0, x = 600, y = 700 } }\n"
         "function level.build(game)\n"
         "  for i = 1, game.world.faceCount() do game.world.line(game.world.face(i), 0, 512, 4096, 512) end\n" +
         extra +
         "\nend\n"
         "function level.tick(game, frame) if frame == 1 then game.message('" +
         message + "') end end\n" + hooks + "\nreturn level\n";
}

ScriptSystem& scriptsOf(core::LiveScene& live) {
  return dynamic_cast<ScriptSystem&>(*live.scene().findSystem("scripting"));
}

core::SystemRegistry scriptingOnly() {
  core::SystemRegistry registry;
  registry.add("scripting", makeScriptSystem);
  return registry;
}

void run(core::LiveScene& live, int frames, core::Buttons held) {
  core::InputEdges edges;
  for (int f = 0; f < frames; ++f) ASSERT_FALSE(live.step(edges.next(held)).has_value()) << live.lastError();
}

// Waits for the watcher to see the save, as the game's loop would, polling once a frame.
core::ReloadReport awaitReload(core::LiveScene& live) {
  for (int i = 0; i < 200; ++i)
    if (std::optional<core::ReloadReport> r = live.poll(5)) return *r;
  ADD_FAILURE() << "no reload within a second of the save";
  return {};
}

TEST(HotReload, TheWatcherSeesSavesInPlaceAndByRenameAndNothingElse) {
  Folder folder("watch");
  const std::string a = folder.write("a.lua", "1"), b = folder.write("b.lua", "2");
  folder.write("other.lua", "3");
  core::FileWatcher watcher;
  watcher.watch({a, b});
  EXPECT_TRUE(watcher.changes(0).empty());
  folder.write("other.lua", "changed");  // not watched
  EXPECT_TRUE(watcher.changes(50).empty());
  folder.write("a.lua", "saved in place");
  EXPECT_EQ(watcher.changes(1000), std::vector<std::string>{a});
  // An editor's save: a new file renamed over the old one.
  folder.write("b.lua.swp", "saved by rename");
  ASSERT_EQ(std::rename(folder.path("b.lua.swp").c_str(), b.c_str()), 0);
  EXPECT_EQ(watcher.changes(1000), std::vector<std::string>{b});
  // Several saves before a look come out once each.
  folder.write("a.lua", "x");
  folder.write("a.lua", "y");
  folder.write("b.lua", "z");
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(watcher.changes(0), (std::vector<std::string>{a, b}));
  EXPECT_THROW(watcher.watch({folder.path("missing/c.lua")}), std::runtime_error);
}

TEST(HotReload, AnEditKeepsThePlayersPlaceVelocityAndCounters) {
  Folder folder("reload_keep");
  const std::string scene = folder.write("scene.lua", kManifest);
  folder.write("level.lua", level());
  const core::SystemRegistry registry = scriptingOnly();
  core::LiveScene live(scene, registry, true);
  run(live, 90, InputFrame::bit(Button::Right));
  const GameStatus before = scriptsOf(live).status();
  const physics::Vec2w velocity = live.scene().world().entity(*live.scene().world().entities().begin()).velocity();
  ASSERT_GT(before.x, 600 + 200);

  folder.write("level.lua", level("", "", "edited"));
  const core::ReloadReport r = awaitReload(live);
  ASSERT_TRUE(r.ok) << r.error;
  const GameStatus after = scriptsOf(live).status();
  EXPECT_EQ(after.face, before.face);
  EXPECT_EQ(after.x, before.x);
  EXPECT_EQ(after.y, before.y);
  EXPECT_EQ(after.time, before.time);
  EXPECT_EQ(live.scene().world().entity(*live.scene().world().entities().begin()).velocity(), velocity);
  // The new level script runs from here: its frames go on from the old count.
  run(live, 1, InputFrame::bit(Button::Right));
  EXPECT_EQ(scriptsOf(live).status().message, "hello");
  EXPECT_EQ(scriptsOf(live).status().time, before.time + 1);
}

TEST(HotReload, WhereTheNewLevelHasAWallThePlayerGoesBackToTheStart) {
  Folder folder("reload_wall");
  const std::string scene = folder.write("scene.lua", kManifest);
  folder.write("level.lua", level());
  const core::SystemRegistry registry = scriptingOnly();
  core::LiveScene live(scene, registry, false);
  run(live, 120, InputFrame::bit(Button::Right));
  const GameStatus before = scriptsOf(live).status();
  // A wall through where the player stands now.
  folder.write("level.lua", level("  game.world.line(0, " + std::to_string(before.x) + ", 400, " +
                                  std::to_string(before.x) + ", 2000)"));
  const core::ReloadReport r = live.reload();
  ASSERT_TRUE(r.ok) << r.error;
  const GameStatus after = scriptsOf(live).status();
  EXPECT_EQ(after.face, 0u);
  EXPECT_EQ(after.x, 600);
  EXPECT_EQ(after.y, 700);
  EXPECT_NE(after.message.find("back to the start"), std::string::npos) << after.message;
}

TEST(HotReload, ABrokenEditIsReportedAndTheLastGoodVersionGoesOn) {
  Folder folder("reload_broken");
  const std::string scene = folder.write("scene.lua", kManifest);
  folder.write("level.lua", level());
  const core::SystemRegistry registry = scriptingOnly();
  core::LiveScene live(scene, registry, true);
  run(live, 30, InputFrame::bit(Button::Right));
  struct Edit {
    std::string file, text, error;
  };
  const Edit edits[] = {
      {"level.lua", "local level = {\nreturn level\n", "level.lua:2: unexpected symbol near 'return'"},
      {"level.lua", level("  game.world.line(0, 1, 2)"), "level.lua:4: argument 4: expected a number, got no value"},
      {"level.lua", "return 42\n", "level.lua: a level script or mod returns a table"},
      {"level.lua", "while true do end\n", "level.lua:1: "},
      {"scene.lua", "return { systems = { 'scripting' }, gravity = 'x' }",
       "scene.lua:1:47: 'gravity' must be a number"},
  };
  for (const Edit& edit : edits) {
    folder.write(edit.file, edit.text);
    const core::ReloadReport r = awaitReload(live);
    EXPECT_FALSE(r.ok) << edit.text;
    EXPECT_NE(r.error.find(edit.error), std::string::npos) << "edit:\n" << edit.text << "\nerror:\n" << r.error;
    EXPECT_EQ(live.lastError(), r.error);
    // The old version still plays: the player keeps walking.
    const int32_t x = scriptsOf(live).status().x;
    run(live, 10, InputFrame::bit(Button::Right));
    EXPECT_GT(scriptsOf(live).status().x, x);
    folder.write(edit.file, edit.file == "scene.lua" ? kManifest : level());
    const core::ReloadReport fixed = awaitReload(live);
    EXPECT_TRUE(fixed.ok) << fixed.error;
    EXPECT_EQ(live.lastError(), "");
  }
}

// A scene whose stage is a level file: an edit to the file reloads it (the player keeps its place
// where the new lines allow), a broken edit is reported with file:line:column and the last good
// version plays on.
TEST(HotReload, ALevelFileEditReloadsAndABrokenOneIsRefused) {
  Folder folder("reload_level_file");
  const std::string floors = "%\n0 512 4096 512\n%\n0 512 4096 512\n%\n%\n%\n%\n";
  folder.write("l.level", "HEXAHEDRON\n0 600 700\n1 3000 800\n4096\n" + floors);
  const std::string scene = folder.write(
      "scene.lua",
      "return { systems = { 'scripting' }, stage = { level = 'l.level' }, scripts = { player = "
      "'scripts/player.lua', progression = 'scripts/progression.lua', rules = 'scripts/rules/game.lua' } }\n");
  const core::SystemRegistry registry = scriptingOnly();
  core::LiveScene live(scene, registry, true);
  run(live, 40, InputFrame::bit(Button::Right));
  const int32_t x = scriptsOf(live).status().x;
  folder.write("l.level", "HEXAHEDRON\n0 600 700\n1 3500 800\n4096\n" + floors);  // the goal moved
  const core::ReloadReport good = awaitReload(live);
  EXPECT_TRUE(good.ok) << good.error;
  EXPECT_EQ(live.scene().level()->goal.position, (physics::Vec2{3500, 800}));
  EXPECT_NEAR(scriptsOf(live).status().x, x, 1);  // the player kept its place
  folder.write("l.level", "HEXAHEDRON\n0 600 700\n1 3500 800\n4096\n%\n0 512 40q6 512\n");
  const core::ReloadReport broken = awaitReload(live);
  EXPECT_FALSE(broken.ok);
  EXPECT_NE(broken.error.find("l.level:6:7: x1: '40q6' is not a number"), std::string::npos) << broken.error;
  run(live, 10, InputFrame::bit(Button::Right));
  EXPECT_GT(scriptsOf(live).status().x, x);  // the last good version plays on
}

TEST(HotReload, AnErrorWhileRunningIsReportedAndTheFramesGoOn) {
  Folder folder("reload_runtime");
  const std::string scene = folder.write("scene.lua", kManifest);
  folder.write("level.lua", level("",
                                  "local tick = level.tick\n"
                                  "function level.tick(game, frame)\n"
                                  "  if frame > 20 then local t = nil; return t.x end\n"
                                  "end\n"));
  const core::SystemRegistry registry = scriptingOnly();
  core::LiveScene live(scene, registry, false);
  core::InputEdges edges;
  for (int f = 1; f <= 40; ++f) {
    const std::optional<std::string> error = live.step(edges.next(InputFrame::bit(Button::Right)));
    EXPECT_EQ(live.scene().frame(), static_cast<uint64_t>(f));
    if (f > 20) {
      ASSERT_TRUE(error.has_value()) << "frame " << f;
      EXPECT_NE(error->find("level.lua:9: attempt to index local 't' (a nil value)"), std::string::npos) << *error;
      EXPECT_NE(error->find("stack traceback:"), std::string::npos) << *error;
    }
  }
  EXPECT_GT(scriptsOf(live).status().x, 600 + 100);  // the player kept walking
}

TEST(HotReload, LevelStateCrossesOverThroughSaveAndOnReload) {
  Folder folder("reload_state");
  const std::string scene = folder.write("scene.lua", kManifest);
  const std::string hooks =
      "local count = 0\n"
      "local tick = level.tick\n"
      "function level.tick(game, frame) count = count + 1 end\n"
      "function level.save(game) return { count = count, nested = { list = { 1, 2, 'three' }, f = print } } end\n"
      "function level.onReload(game, saved)\n"
      "  count = saved.count\n"
      "  game.message(VERSION .. ' took over ' .. saved.count .. ' ' .. saved.nested.list[3] .. ' ' .. "
      "tostring(saved.nested.f))\n"
      "end\n";
  folder.write("level.lua", "VERSION = 'one'\n" + level("", hooks));
  const core::SystemRegistry registry = scriptingOnly();
  core::LiveScene live(scene, registry, false);
  run(live, 25, 0);
  folder.write("level.lua", "VERSION = 'two'\n" + level("", hooks));
  ASSERT_TRUE(live.reload().ok);
  EXPECT_EQ(scriptsOf(live).status().message, "two took over 25 three nil");
}

// The new version's build already sees the frames played (a platform's cycle computed from
// game.frame() in build goes on where it was, instead of restarting on every save), and sees the
// same count as its onReload; a fresh load starts at 0.
TEST(HotReload, TheNewBuildSeesTheFramesPlayed) {
  Folder folder("reload_frame");
  const std::string scene = folder.write("scene.lua", kManifest);
  const std::string hooks =
      "function level.onReload(game, saved) game.message(VERSION .. ' built at ' .. BUILT .. ', reloaded at ' .. "
      "game.frame()) end\n";
  auto version = [&](const std::string& name) {
    folder.write("level.lua", "VERSION = '" + name + "'\n" +
                                  level("BUILT = game.frame() game.message('built at ' .. BUILT)", hooks));
  };
  version("one");
  const core::SystemRegistry registry = scriptingOnly();
  core::LiveScene live(scene, registry, false);
  EXPECT_EQ(scriptsOf(live).status().message, "built at 0");
  int played = 0;
  for (const int frames : {1, 40, 333}) {
    run(live, frames, 0);
    played += frames;
    version("v" + std::to_string(frames));
    ASSERT_TRUE(live.reload().ok) << live.lastError();
    EXPECT_EQ(scriptsOf(live).status().message, "v" + std::to_string(frames) + " built at " + std::to_string(played) +
                                                    ", reloaded at " + std::to_string(played));
  }
  core::LiveScene fresh(scene, registry, false);
  EXPECT_EQ(scriptsOf(fresh).status().message, "built at 0");
}

TEST(HotReload, SwitchesDeathsAndCheckpointsSurvive) {
  Folder folder("reload_switch");
  const std::string scene = folder.write("scene.lua", kManifest);
  // A door (1000 + 1) across the floor beyond a switch (2000 + 1) the player walks through.
  const std::string extra =
      "  game.world.line(0, 1200, 400, 1200, 1400, 2001)\n"
      "  game.world.line(0, 2000, 400, 2000, 1400, 1001)\n";
  folder.write("level.lua", level(extra));
  const core::SystemRegistry registry = scriptingOnly();
  core::LiveScene live(scene, registry, false);
  run(live, 60, InputFrame::bit(Button::Restart));  // one restart: a death
  run(live, 200, InputFrame::bit(Button::Right));
  ASSERT_EQ(scriptsOf(live).status().deaths, 1);
  ASSERT_GT(scriptsOf(live).status().x, 1300);  // through the switch: the door is open
  ASSERT_TRUE(live.reload().ok);
  EXPECT_EQ(scriptsOf(live).status().deaths, 1);
  run(live, 200, InputFrame::bit(Button::Right));
  EXPECT_GT(scriptsOf(live).status().x, 2200);  // the door is still open in the new world
}

// The goal's frame counts the frames played, reloads or not (it came from the new world's frame
// count, which starts again at 0: a reload at frame 600 gave a goal at 457 instead of 1057, and a
// best time of 7 s in the game). And a message the new version's build says is not hidden by the
// old one's.
TEST(HotReload, TheGoalFrameCountsEveryFramePlayedAndTheNewBuildsMessageShows) {
  auto goalFrame = [](int reloadAt, std::string* messageAfter) {
    Folder folder("reload_goal_" + std::to_string(reloadAt));
    for (const char* file : {"scene.lua", "cube_intro.level", "level.lua"}) {
      std::ifstream in(std::string(PLATON_SOURCE_ROOT) + "/levels/cube_intro/" + file);
      folder.write(file, std::string(std::istreambuf_iterator<char>(in), {}));
    }
    const core::SystemRegistry registry = scriptingOnly();
    core::LiveScene live(folder.path("scene.lua"), registry, false);
    core::InputEdges edges;
    for (int f = 1; f <= 3000 && !scriptsOf(live).status().won; ++f) {
      if (f == reloadAt) {
        folder.write("level.lua", "return { build = function(game) game.message('edited') end }\n");
        EXPECT_TRUE(live.reload().ok);
        if (messageAfter) *messageAfter = scriptsOf(live).status().message;
      }
      EXPECT_FALSE(live.step(edges.next(InputFrame::bit(Button::Right))).has_value()) << live.lastError();
    }
    return scriptsOf(live).status().wonFrame;
  };
  std::string message;
  const uint64_t straight = goalFrame(0, nullptr);
  ASSERT_GT(straight, 600u);
  EXPECT_EQ(goalFrame(600, &message), straight);
  EXPECT_EQ(message, "edited");
}

}  // namespace
}  // namespace platon::script
