// The sandbox inside a running scene: each test is one finding of the sandbox audit
// (docs/scripting.md, "Sandbox"), played through the engine as a downloaded level would be, with
// the error a player or a scenario sees. Every one of them failed (or hung, or aborted) before its fix.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "platon/core/draw_list.h"
#include "platon/core/live_scene.h"
#include "platon/core/replay.h"
#include "platon/script/scenario.h"
#include "platon/script/script_system.h"
#include "platon/testing/temp_folder.h"

namespace platon::script {
namespace {

namespace fs = std::filesystem;
using core::Button;
using core::InputFrame;
using Folder = testing::TempFolder;

std::string fileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A downloaded level: the first level's stage, the game's scripts, and the level's own level.lua
// (and mod.lua, rules.lua when given).
struct Level {
  Folder folder;
  std::string scene;
  Level(const std::string& name, const std::string& level, const std::string& mod = "", const std::string& rules = "",
        const std::string& extra = "")
      : folder(name) {
    folder.write("cube_intro.level", fileText(std::string(PLATON_SOURCE_ROOT) + "/levels/cube_intro/cube_intro.level"));
    folder.write("level.lua", level);
    std::string scripts = "preset = 'game', level = 'level.lua'";
    if (!mod.empty()) {
      folder.write("mod.lua", mod);
      scripts += ", mods = { 'mod.lua' }";
    }
    if (!rules.empty()) {
      folder.write("rules.lua", rules);
      scripts += ", rules = 'rules.lua'";
    }
    scene = folder.write("scene.lua",
                         "return { name = 'audit', systems = { 'scripting' }, stage = { level = 'cube_intro.level' },"
                         " gravity = 0.35, scripts = { " +
                             scripts + " }" + extra + " }\n");
  }
};

core::SystemRegistry scripting() {
  core::SystemRegistry registry;
  registry.add("scripting", makeScriptSystem);
  return registry;
}

ScriptSystem& scriptsOf(core::LiveScene& live) {
  return dynamic_cast<ScriptSystem&>(*live.scene().findSystem("scripting"));
}

struct Played {
  std::vector<std::string> errors;  // "frame N: report"
  GameStatus status;
};

// Plays `frames` frames holding `held`, asking for the status after each (as the game loop does).
Played play(core::LiveScene& live, int frames, core::Buttons held = InputFrame::bit(Button::Right)) {
  Played p;
  core::InputEdges edges;
  for (int f = 1; f <= frames; ++f) {
    if (std::optional<std::string> error = live.step(edges.next(held)))
      p.errors.push_back("frame " + std::to_string(live.scene().frame()) + ": " + *error);
    p.status = scriptsOf(live).status();
  }
  return p;
}

std::string joined(const std::vector<std::string>& errors) {
  std::string out;
  for (const std::string& e : errors) out += e + "\n----\n";
  return out;
}

// --- 1: trust is decided from what the manifest wrote, never from a joined path ---

const char* kTellsWhatItSees =
    "return { build = function(game) game.message((io and 'io ' or 'no io ') .. (require and 'require' or 'no "
    "require')) end }\n";

TEST(Trust, ALevelOpenedThroughAPathUnderScriptsIsStillSandboxed) {
  Level level("f1_path", kTellsWhatItSees);
  // "scripts/../../../tmp/.../scene.lua" from the engine's root: the same file, a path that starts
  // with scripts/ (tests run in the source root).
  std::string up = "scripts/";
  for (const auto& part : fs::current_path()) (void)part, up += "../";
  const std::string path = up + level.scene.substr(1);
  ASSERT_TRUE(fs::exists(path)) << path;
  const core::SceneManifest m = core::loadManifest(path);
  EXPECT_FALSE(m.levelTrusted);
  EXPECT_TRUE(m.playerTrusted);  // preset = "game": the engine's
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(path, registry, false);
  EXPECT_EQ(scriptsOf(live).status().message, "no io no require");
}

TEST(Trust, ALinkOutOfTheLevelsFolderIsRefused) {
  Folder outside("f1_outside");
  const std::string target = outside.write("evil.lua", kTellsWhatItSees);
  Level level("f1_link", "return {}\n");
  fs::remove(level.folder.path("level.lua"));
  fs::create_symlink(target, level.folder.path("level.lua"));
  try {
    core::loadManifest(level.scene);
    FAIL() << "a level script linked from outside its folder was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'level.lua' leads to " + fs::canonical(target).string() +
                                         ", outside the scene's folder"),
              std::string::npos)
        << e.what();
  }
}

// An engine script is looked for under the engine's root, and must stay under its scripts/.
TEST(Trust, AnEngineScriptLinkedFromOutsideTheEnginesScriptsIsRefused) {
  Folder root("f1_root");
  for (const char* file :
       {"scripts/scene.lua", "scripts/player.lua", "scripts/progression.lua", "scripts/rules/game.lua"})
    root.write(file, fileText(std::string(PLATON_SOURCE_ROOT) + "/" + file));
  Folder outside("f1_outside_engine");
  fs::create_symlink(outside.write("evil.lua", "return {}\n"), root.path("scripts/evil.lua"));
  Level level("f1_engine_link", "return {}\n");
  level.folder.write("scene.lua",
                     "return { systems = { 'scripting' }, stage = { level = 'cube_intro.level' }, scripts = {"
                     " preset = 'game', progression = 'scripts/evil.lua' } }\n");
  core::SystemRegistry registry;
  registry.add("scripting", [&](core::Scene& s) { return std::make_unique<ScriptSystem>(s, root.path()); });
  try {
    core::LiveScene live(level.scene, registry, false);
    FAIL() << "an engine script outside the engine's scripts/ loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(core::errorReport(e).find("'scripts/evil.lua' is " + fs::canonical(outside.path("evil.lua")).string() +
                                        ", outside the engine's scripts"),
              std::string::npos)
        << core::errorReport(e);
  }
}

TEST(Trust, ReplaysAndScenariosMayNotNameASceneWithDotDot) {
  try {
    core::parseReplay(
        "platon replay 1\nscene \"scripts/../../../tmp/x/scene.lua\"\nframes 1\nhash_every 60\ninput\n1 -\nend\n",
        "r.replay");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "r.replay:2:7: 'scripts/../../../tmp/x/scene.lua': a replay's scene path may not contain '..'"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(core::parseReplay(
      "platon replay 1\nscene \"levels/a..b/scene.lua\"\nframes 1\nhash_every 60\ninput\n1 -\nend\n", "r"));
  Folder folder("f1_scenario");
  const ScenarioResult r =
      runScenario(folder.write("s.lua", "return { scene = 'scripts/../levels/cube_intro/scene.lua', frames = 1 }"));
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.message.find("s.lua:1:18: scene: may not contain '..' (scripts/../levels/cube_intro/scene.lua)"),
            std::string::npos)
      << r.message;
}

// --- 2, 16: the game's API checks what a sandbox hands it ---

TEST(SwitchIds, BadSwitchIdsAreErrorsAtTheCallersLineAndTheGameGoesOn) {
  for (const char* bad :
       {"{}", "0", "0/0", "setmetatable({}, {__add = function() error('planted') end})", "1.5", "1000", "'3'"}) {
    Level level("f2_toggle", std::string("return { tick = function(game, frame)\n  if frame == 5 then game.toggle(") +
                                 bad + ") end\nend }\n");
    const core::SystemRegistry registry = scripting();
    core::LiveScene live(level.scene, registry, false);
    const Played p = play(live, 60);
    ASSERT_EQ(p.errors.size(), 1u) << bad << "\n" << joined(p.errors);
    EXPECT_NE(p.errors[0].find("frame 5: " + std::string("level.lua") +
                               ":2: toggle: expected a switch id, an integer 1..999"),
              std::string::npos)
        << p.errors[0];
    EXPECT_GT(p.status.x, 700);  // the player walked on: the game is not broken
  }
  Level level("f2_switch_on",
              "return { tick = function(game, frame) if frame == 3 then game.switchOn('x') end end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played p = play(live, 10);
  ASSERT_EQ(p.errors.size(), 1u) << joined(p.errors);
  EXPECT_NE(p.errors[0].find("level.lua:1: switchOn: expected a switch id, an integer 1..999, got \"x\""),
            std::string::npos)
      << p.errors[0];
}

TEST(PlayerSafety, ABadCheckpointIsAnErrorAtItsLineAndDeathsStillRespawn) {
  Level level("f16_checkpoint",
              "return { tick = function(game, frame)\n"
              "  if frame == 5 then game.checkpoint(99, 0, 0) end\n"
              "  if frame == 6 then game.checkpoint(0, 0.5, 0) end\n"
              "  if frame == 7 then game.kill() end\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played p = play(live, 30);
  ASSERT_EQ(p.errors.size(), 2u) << joined(p.errors);
  EXPECT_NE(p.errors[0].find("level.lua:2: checkpoint: face: expected a face of this stage, got 99"), std::string::npos)
      << p.errors[0];
  EXPECT_NE(p.errors[1].find("level.lua:3: checkpoint: x: expected an integer within +-(2^30 - 1), got 0.5"),
            std::string::npos)
      << p.errors[1];
  EXPECT_EQ(p.status.deaths, 1);
  EXPECT_EQ(p.status.face, 0u);
}

// A checkpoint inside a wall: the respawn falls back to the level's start (the old player is
// destroyed only once the new one stands).
TEST(PlayerSafety, ACheckpointInAWallRespawnsAtTheLevelStart) {
  Level level("f16_wall",
              "return {\n"
              "  build = function(game) game.world.line(0, 2000, 400, 2000, 1400) end,\n"
              "  tick = function(game, frame)\n"
              "    if frame == 5 then game.checkpoint(0, 2000, 700) game.kill() end\n"
              "  end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played p = play(live, 7, 0);
  EXPECT_TRUE(p.errors.empty()) << joined(p.errors);
  EXPECT_EQ(p.status.deaths, 1);
  EXPECT_EQ(p.status.message, "the checkpoint's place is taken: back to the level's start");
  EXPECT_NEAR(p.status.x, 600, 2);
  EXPECT_EQ(live.scene().world().entityCount(), 1u);
}

TEST(PlayerSafety, ASandboxMayNotDestroyOrEraseThePlayer) {
  for (const char* call : {"game.world.destroyEntity(game.player())", "game.world.erase(game.player(), 0)",
                           "platon.world.destroyEntity(game.player())"}) {
    Level level("f16_destroy",
                std::string("return { tick = function(game, frame)\n  if frame == 5 then ") + call + " end\nend }\n");
    const core::SystemRegistry registry = scripting();
    core::LiveScene live(level.scene, registry, false);
    const Played p = play(live, 40);
    ASSERT_EQ(p.errors.size(), 1u) << call << "\n" << joined(p.errors);
    EXPECT_NE(p.errors[0].find("level.lua:2: "), std::string::npos) << p.errors[0];
    EXPECT_NE(p.errors[0].find(": the player's entity belongs to the game (a level script or mod may not "),
              std::string::npos)
        << p.errors[0];
    EXPECT_GT(p.status.x, 700);
  }
}

// If the player's entity is gone all the same (here: trusted code destroyed it), the player comes
// back once, with a message, instead of an error on every frame.
TEST(PlayerSafety, ALostPlayerRespawnsOnce) {
  Level level("f16_lost", "return {}\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  play(live, 20);
  scriptsOf(live).evaluate("local game = ... platon.world.destroyEntity(game.player.entity)", "=test");
  const Played p = play(live, 30);
  EXPECT_TRUE(p.errors.empty()) << joined(p.errors);
  EXPECT_EQ(p.status.message, "the player was lost: back at the last checkpoint");
  EXPECT_EQ(live.scene().world().entityCount(), 1u);
}

// --- 3: status() and draw() never throw ---

TEST(StatusAndDraw, AnErrorInStatusIsReportedWithTheNextFrameAndTheLastGoodStatusStays) {
  Level level("f3_status", "return {}\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played before = play(live, 10);
  scriptsOf(live).evaluate("local game = ... game.openSwitches = 5", "=test");  // status() now fails
  GameStatus s;
  EXPECT_NO_THROW(s = scriptsOf(live).status());
  EXPECT_EQ(s.x, before.status.x);
  const Played after = play(live, 1);
  ASSERT_FALSE(after.errors.empty());
  EXPECT_NE(after.errors[0].find("scene.lua"), std::string::npos) << after.errors[0];
  EXPECT_NE(after.errors[0].find("attempt to get length of local 'on' (a number value)"), std::string::npos)
      << after.errors[0];
}

TEST(StatusAndDraw, AnErrorInLevelDrawLeavesAnEmptyPictureAndIsReported) {
  Level level(
      "f3_draw",
      "return { draw = function(game, draw) draw.circle(0, 1, 1, 5, 0xffffff) error('an ordinary bug') end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  core::DrawList list(true);
  EXPECT_NO_THROW(live.scene().draw(list));
  EXPECT_TRUE(list.shapes().empty());
  const Played p = play(live, 1);
  ASSERT_EQ(p.errors.size(), 1u);
  EXPECT_NE(p.errors[0].find("level.lua:1: an ordinary bug"), std::string::npos) << p.errors[0];
  const ScenarioResult r = runScenario(level.folder.write("s.lua", "return { scene = 'scene.lua', frames = 10 }"));
  EXPECT_TRUE(r.passed) << r.message;  // headless: no picture, no draw() call
}

// --- 4, 5: sandboxes get read-only views of the engine's tables ---

TEST(EngineTables, TheEnginesTablesAreReadOnlyInEverySandbox) {
  const char* attempts[][2] = {
      {"game.message = 1", "game is read-only (tried to set message)"},
      {"game.world.valid = function() end", "game.world is read-only (tried to set valid)"},
      {"platon.world.position = function() end", "platon.world is read-only (tried to set position)"},
      {"setmetatable(game.world, {})", "cannot change a protected metatable"},
      {"game.newField = 1", "game is read-only (tried to set newField)"},
  };
  for (const auto& [code, message] : attempts) {
    Level level("f4_tables",
                std::string("return { tick = function(game, frame) if frame == 2 then ") + code + " end end }\n");
    const core::SystemRegistry registry = scripting();
    core::LiveScene live(level.scene, registry, false);
    const Played p = play(live, 30);
    ASSERT_EQ(p.errors.size(), 1u) << code << "\n" << joined(p.errors);
    EXPECT_NE(p.errors[0].find(std::string("level.lua:1: ") + message), std::string::npos) << p.errors[0];
    EXPECT_GT(p.status.x, 650);
  }
  // The draw argument of level.draw too.
  Level level("f4_draw", "return { draw = function(game, draw) draw.circle = nil end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  core::DrawList list(true);
  live.scene().draw(list);
  const Played p = play(live, 1);
  ASSERT_EQ(p.errors.size(), 1u);
  EXPECT_NE(p.errors[0].find("level.lua:1: draw is read-only (tried to set circle)"), std::string::npos) << p.errors[0];
}

TEST(SandboxedRules, SandboxedRulesGetTheLevelsViewAndTheGamesSetters) {
  const char* rules =
      "local game = ...\n"
      "assert(game.Player == nil and game.progression == nil and game.switches == nil, 'the trusted game table')\n"
      "assert(not pcall(function() game.won = true end), 'writable')\n"
      "local rules = {}\n"
      "function rules.pierce(entity, tag, kind) return kind == 'warp' or tag == 2 end\n"
      "function rules.beginContact(entity, tag) if tag == 2 and entity == game.player() then game.reachGoal() end end\n"
      "return rules\n";
  Level level("f5_rules", "return {}\n", "", rules);
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played p = play(live, 1500);
  EXPECT_TRUE(p.errors.empty()) << joined(p.errors);
  EXPECT_TRUE(p.status.won);
}

// --- 6, 7, 18: patterns ---

TEST(StringMethods, StringMethodsAreTheCountedPatternFunctionsToo) {
  Level level("f6_method",
              "return { build = function(game)\n"
              "  local ok, e = pcall(function() local r = (string.rep('a', 200)):find('.-.-.-.-b') return r end)\n"
              "  game.message(tostring(e) .. ' / dump: ' .. tostring(('').dump))\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  EXPECT_EQ(scriptsOf(live).status().message,
            std::string("level.lua") + ":2: pattern too costly (more than 2000000 steps) / dump: nil");
}

TEST(CostlyPatterns, CostlyPatternsAreRefusedWhateverTheirShape) {
  struct Case {
    const char* code;
    const char* result;
  };
  const Case cases[] = {
      {"string.find(string.rep('a', 1500), '.-.-b')", "pattern too costly"},    // unanchored: n^(items+1)
      {"string.find(string.rep('a', 1500), '(.-)%1b')", "pattern too costly"},  // a back-reference
      {"string.gsub(string.rep('a', 1500), '.-.-b', '')", "pattern too costly"},
      {"string.find(string.rep('a', 4e5), string.rep('a', 1e5) .. 'b', 1, true)", "nil"},  // plain: linear now
      {"string.find(string.rep('a', 4e5), string.rep('a', 1e5) .. 'b')", "nil"},           // no items: plain
  };
  for (const Case& c : cases) {
    Level level("f7_patterns",
                std::string("return { build = function(game)\n  local ok, e = pcall(function() return ") + c.code +
                    " end)\n  game.message(tostring(e))\nend }\n");
    const core::SystemRegistry registry = scripting();
    core::LiveScene live(level.scene, registry, false);
    const std::string message = scriptsOf(live).status().message;
    EXPECT_NE(message.find(c.result), std::string::npos) << c.code << ": " << message;
  }
}

// --- 8: a loop of slow C calls is stopped by the work they are charged ---

TEST(SlowCalls, ALoopOfSlowCallsIsStoppedByTheirWork) {
  // Each search of 4 MB is charged the bytes it passes (250,000 steps), and so was making the
  // string: the loop runs 39 times, not the 10^6 its instructions alone would allow.
  const char* level =
      "local n = 0\n"
      "return { tick = function(game, frame)\n"
      "  local s = string.rep('a', 4e6)\n"
      "  while true do n = n + 1 game.message(n) s:find('b', 1, true) end\n"
      "end }\n";
  Level charged("f8_charged", level);
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(charged.scene, registry, false);
  const Played p = play(live, 3);
  ASSERT_EQ(p.errors.size(), 1u) << joined(p.errors);
  EXPECT_NE(p.errors[0].find("level.lua:4: script stopped: it ran past the frame's script budget of 10000000 steps"),
            std::string::npos)
      << p.errors[0];
  EXPECT_EQ(p.status.message, "39");
}

// Whole-world queries cost what they do: a loop of them spends the frame's budget by their work
// (the overlap check's pairs and index nodes, the hash's entities), not one step a call. Without
// the charge each loop ran about ten times as long before the budget stopped it.
TEST(SlowCalls, ALoopOfWholeWorldQueriesIsStoppedByTheirWork) {
  for (const std::string query : {"countOverlaps", "stateHash"}) {
    SCOPED_TRACE(query);
    const std::string level =
        "local n = 0\n"
        "return { tick = function(game, frame)\n"
        "  if frame == 1 then for i = 1, 200 do local e = game.world.createEntity{circle = 6} "
        "game.world.insert(e, game.world.face(1), 300 + 16 * i, 3000) end end\n"
        "  while true do n = n + 1 game.message(n) game.world." +
        query +
        "() end\n"
        "end }\n";
    Level charged("f8_queries", level);
    const core::SystemRegistry registry = scripting();
    core::LiveScene live(charged.scene, registry, false);
    const Played p = play(live, 3);
    ASSERT_EQ(p.errors.size(), 1u) << joined(p.errors);
    EXPECT_NE(p.errors[0].find("level.lua:4: script stopped: it ran past the frame's script budget"), std::string::npos)
        << p.errors[0];
    EXPECT_LT(std::stoi(p.status.message), 30000) << p.status.message;
  }
}

// --- 9: a level's manifest may lower the limits, never raise them ---

TEST(ManifestLimits, AManifestCannotRaiseTheLimits) {
  Level level("f9_limits", "return {}\n", "return { tick = function() while true do end end }\n", "",
              ", limits = { memory_mb = 4096, steps = 1e9, deadline_ms = 60000 }");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played p = play(live, 2);
  ASSERT_EQ(p.errors.size(), 1u) << joined(p.errors);
  EXPECT_NE(p.errors[0].find("mod.lua:1: script stopped: it ran past the frame's script budget of 10000000 steps"),
            std::string::npos)
      << p.errors[0];
  Level hog(
      "f9_memory", "return {}\n",
      "local t = {} return { tick = function() for i = 1, 1e5 do t[i] = string.rep('x', 1000000) .. i end end }\n", "",
      ", limits = { memory_mb = 4096 }");
  core::LiveScene live2(hog.scene, registry, false);
  const Played q = play(live2, 2);
  ASSERT_EQ(q.errors.size(), 1u) << joined(q.errors);
  EXPECT_NE(q.errors[0].find("memory limit of 96 MB (of the Lua state's 128 MB"), std::string::npos) << q.errors[0];
}

// --- 10: one budget a frame for every sandboxed call, rules callbacks included ---

TEST(FrameBudget, RulesCallbacksShareTheFramesBudget) {
  const char* level =
      "return { tick = function(game, frame)\n"
      "  if frame == 1 then for i = 0, 19 do local e = game.world.createEntity { circle = 40 }\n"
      "    game.world.insert(e, 0, 300 + i * 150, 700) end end\n"
      "end }\n";
  // Each contact spins a while (about 400,000 steps); 20 balls rest on the floor, each in contact
  // every frame: the budget of 2,000,000 steps is spent by the fifth callback of a frame.
  const char* rules =
      "local rules = {}\n"
      "function rules.pierce(e, tag, kind) return kind == 'warp' end\n"
      "function rules.contact(entity) for i = 1, 2e5 do end end\n"
      "return rules\n";
  Level l("f10_rules", level, "", rules, ", limits = { steps = 2e6 }");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(l.scene, registry, false);
  const Played p = play(live, 60, 0);
  ASSERT_FALSE(p.errors.empty());
  EXPECT_NE(p.errors[0].find("rules.lua:3: script stopped: it ran past the frame's script budget of 2000000 steps"),
            std::string::npos)
      << p.errors[0];
  EXPECT_NE(p.errors[0].find("rules.lua disabled"), std::string::npos) << p.errors[0];
  EXPECT_EQ(p.errors.size(), 1u) << joined(p.errors);
}

// --- 11: a runaway module is disabled; each module's hooks have their own error boundary ---

TEST(RunawayMods, ARunawayModIsDisabledAndTheOthersGoOn) {
  const char* levelScript = "return { tick = function(game, frame) error('the level fails every frame') end }\n";
  const char* mod =
      "return { tick = function(game, frame)\n"
      "  game.message('mod tick ' .. frame)\n"
      "  if frame == 10 then while true do end end\n"
      "end }\n";
  Level level("f11_mod", levelScript, mod, "", ", limits = { steps = 1e6 }");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played p = play(live, 40);
  bool disabled = false;
  for (const std::string& e : p.errors) {
    EXPECT_NE(e.find("the level fails every frame"), std::string::npos) << e;  // the level's error, every frame
    if (e.find(
            "mod.lua:3: script stopped: it ran past the frame's script budget of 1000000 steps (an endless loop?); " +
            std::string("mod.lua") + " disabled: fix it and save to reload") != std::string::npos)
      disabled = true;
  }
  EXPECT_TRUE(disabled) << joined(p.errors);
  EXPECT_EQ(p.status.message, "mod tick 10");  // ran every frame until its stop, despite the level's errors
  // Hot reload brings it back.
  ASSERT_TRUE(live.reload().ok);
  EXPECT_EQ(play(live, 1).status.message, "mod tick 41");
}

// --- 12: hot reload's copy of save() data ---

TEST(ReloadCarry, SavedDataIsCopiedOnceCyclesKeptAndTooMuchRefused) {
  // A DAG of 60 levels (2^60 paths), a cycle and a shared table.
  const std::string hooks =
      "local saved\n"
      "local function dag() local n = { 'leaf' } for i = 1, 60 do n = { n, n } end return n end\n"
      "return { save = function() local t = { dag = dag(), shared = { 1 } } t.again = t.shared t.self = t return t "
      "end,\n"
      "  onReload = function(game, s)\n"
      "    local d = s.dag for i = 1, 60 do assert(d[1] == d[2]) d = d[1] end\n"
      "    game.message(d[1] .. ' ' .. tostring(s.self == s) .. ' ' .. tostring(s.again == s.shared)) end }\n";
  Level level("f12_dag", hooks);
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  play(live, 5);
  const core::ReloadReport r = live.reload();  // 2^60 paths: copied path by path, it would never end
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(scriptsOf(live).status().message, "leaf true true");

  // One 24 MB string held 99,999 times is copied once (each copied anew, the reload hung).
  Level shared(
      "f12_shared",
      "local big = string.rep('x', 24 * 1024 * 1024)\n"
      "return { save = function() local t = {} for i = 1, 99999 do t[i] = big end return t end,\n"
      "  onReload = function(game, s) game.message(#s .. ' ' .. #s[1] .. ' ' .. tostring(s[1] == s[99999])) end }\n");
  core::LiveScene live3(shared.scene, registry, false);
  play(live3, 5);
  const core::ReloadReport r3 = live3.reload();
  ASSERT_TRUE(r3.ok) << r3.error;
  EXPECT_EQ(scriptsOf(live3).status().message, "99999 25165824 true");
}

// Past the copy's bounds (entries, bytes of distinct strings, depth) the reload is refused with the
// reason, and the old version goes on: its state and its scripts, frame after frame.
TEST(ReloadCarry, TooMuchToCarryOverKeepsTheOldVersion) {
  const std::pair<const char*, const char*> saves[] = {
      {"local t = {} for i = 1, 1100000 do t[i] = true end return t", "more than 1000000 table entries"},
      {"local t = {} for i = 1, 40 do t[i] = string.rep(string.char(64 + i), 1024 * 1024) end return t",
       "more than 32 MB of strings"},
      {"local t = {} local n = t for i = 1, 300 do n[1] = {} n = n[1] end return t",
       "tables nested more than 200 deep"},
  };
  const core::SystemRegistry registry = scripting();
  for (const auto& [save, why] : saves) {
    Level big("f12_big", std::string("return { save = function() ") + save +
                             " end,\n  tick = function(game, frame) game.message('old ' .. frame) end,\n"
                             "  onReload = function(game, s) game.message('new') end }\n");
    core::LiveScene live(big.scene, registry, false);
    play(live, 5);
    const core::ReloadReport r = live.reload();
    EXPECT_FALSE(r.ok) << save;
    EXPECT_NE(r.error.find(std::string("reload refused, the old version goes on: the level's save(): too much to carry "
                                       "over (") +
                           why + "); restart the level to start the new version without it"),
              std::string::npos)
        << r.error;
    const Played p = play(live, 3);
    EXPECT_EQ(p.status.message, "old 8") << save;  // the old version's tick, its frames counting on
    EXPECT_EQ(p.status.time, 8u);
  }
}

// --- 13, 14: what Lua makes in C++ is capped ---

TEST(CreationCaps, EntitiesAndPlatformsMadeFromLuaAreCapped) {
  Level level("f13_flood",
              "return { tick = function(game, frame)\n"
              "  for i = 1, 1000 do game.world.createEntity { circle = 10 } end\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played p = play(live, 15);
  ASSERT_FALSE(p.errors.empty());
  EXPECT_NE(p.errors[0].find("level.lua:2: createEntity: the world holds 10000 entities, the most scripts may make"),
            std::string::npos)
      << p.errors[0];
  EXPECT_EQ(live.scene().world().entityCount(), 10000u);
  Level platforms("f13_platforms",
                  "return { build = function(game)\n"
                  "  local ok, e = pcall(game.world.createPlatform, 0, (function() local t = {} for i = 1, 4004 do "
                  "t[i] = i end return t end)())\n"
                  "  local made = 0\n"
                  "  local ok2, e2 = pcall(function() for i = 1, 1001 do game.world.createPlatform(0, { 10, 10, 20, 10 "
                  "}) made = made + 1 end end)\n"
                  "  game.message(tostring(e) .. ' / ' .. made .. ' / ' .. tostring(e2))\n"
                  "end }\n");
  core::LiveScene live2(platforms.scene, registry, false);
  const std::string m = scriptsOf(live2).status().message;
  EXPECT_NE(m.find("createPlatform: argument 2 (lines): at most 4000 numbers, got 4004 / 1000 / "), std::string::npos)
      << m;
  EXPECT_NE(m.find("createPlatform: scripts have made 1000 platforms, the most they may"), std::string::npos) << m;
}

// An entity's handle and a platform's are never the same number (the audit moved a platform with
// the player's handle): each kind of function refuses the other kind's handle.
TEST(Handles, EntityAndPlatformHandlesNeverMix) {
  Level level("handles_mix",
              "return { build = function(game)\n"
              "  local w = game.world\n"
              "  local p = w.createPlatform(0, { 100, 300, 400, 300 })\n"
              "  local e = w.createEntity { circle = 20 }\n"
              "  local ok1, e1 = pcall(w.setPlatformMotion, e, 1, 0)\n"
              "  local ok2, e2 = pcall(w.velocity, p)\n"
              "  local ok3 = pcall(w.setPlatformMotion, p, 1, 0)\n"
              "  game.message(tostring(p < 0) .. ' ' .. tostring(e >= 0) .. ' | ' .. tostring(e1) .. ' | ' .. "
              "tostring(e2) .. ' | ' .. tostring(ok3))\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const std::string m = scriptsOf(live).status().message;
  EXPECT_EQ(m.rfind("true true | ", 0), 0u) << m;
  EXPECT_NE(m.find("argument 1: expected a platform handle (from createPlatform), got "), std::string::npos) << m;
  EXPECT_NE(m.find("argument 1: expected an entity handle, got -"), std::string::npos) << m;
  EXPECT_NE(m.find("| true"), std::string::npos) << m;
}

// A platform driven over a face's edge belongs to the face beyond from then on: platformPart says
// which, and its offset counts from the crossing (in that face's frame).
TEST(Platforms, ScriptsSeeAPlatformCrossAnEdge) {
  Level level("platform_crossing",
              "local p\n"
              "return { build = function(game)\n"
              "  p = game.world.createPlatform(0, { 3600, 1200, 3900, 1200 })\n"
              "  game.world.setPlatformMotion(p, 10, 0)\n"
              "end, tick = function(game, frame)\n"
              "  local dx, dy = game.world.platformOffset(p)\n"
              "  game.message(game.world.platformPart(p) .. ' ' .. dx .. ' ' .. dy)\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  EXPECT_EQ(play(live, 40).status.message, "0 390 0");  // the tick reads the frame's start
  const Played p = play(live, 30);                      // its far end at 3900 + 700: over by 500
  ASSERT_TRUE(p.errors.empty()) << joined(p.errors);
  EXPECT_EQ(p.status.message.substr(0, 2), "1 ") << p.status.message;  // face 0's right edge leads to face 1
}

// The draw API checks its arguments with or without a renderer, so a script's mistake shows in a
// headless scenario as in the window (headless it returned before looking at them).
TEST(DrawApi, BadArgumentsAreErrorsHeadlessToo) {
  // One call a frame, its error (or "ok") the frame's message.
  Level level("draw_args",
              "local calls = {\n"
              "  function(d) d.circle(999, 0, 0, 10, 0xffffff) end,\n"
              "  function(d) d.circle('Screen', 0, 0, 10, 0xffffff) end,\n"
              "  function(d) d.circle(0, 0, 0, -5, 0xffffff) end,\n"
              "  function(d) d.line(0, 0, 0, 1e300, 0, 2, 0xffffff) end,\n"
              "  function(d) d.text('screen', 0, 0, 'hi', 0, 0xffffff) end,\n"
              "  function(d) d.polygon(0, { 0, 0, 100, 100, 100, 0 }, 0xffffff) end,\n"
              "  function(d) d.polygon(0, { 0, 0, 100, 0, 100, 100 }, 0xffffff) end,\n"
              "  function(d) d.look('x', 0xffffff) end,\n"
              "  function(d, game) d.look(game.player(), 0x1000000) end,\n"
              "  function(d, game) d.look(game.player(), 0xffffff, 'sphere') end,\n"
              "  function(d, game) d.look(game.player(), 0x55aaee, 'ball') end }\n"
              "return { tick = function(game, frame)\n"
              "  local ok, e = pcall(calls[frame], platon.draw, game)\n"
              "  game.message(ok and 'ok' or e)\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const std::vector<std::string> expected = {
      "level.lua:2: argument 1: expected a face id of this stage or \"screen\", got 999",
      "level.lua:3: argument 1: expected a face id of this stage or \"screen\", got \"Screen\"",
      "level.lua:4: argument 4: expected a size above 0 (and at most 2^30), got -5",
      "level.lua:5: argument 4: expected a number within +-2^30, got 1e+300",
      "level.lua:6: argument 5: expected a size above 0 (and at most 2^30), got 0",
      "level.lua:7: polygon: argument 2: the points must go counter-clockwise round a convex shape",
      "ok",
      "level.lua:9: argument 1: expected an entity handle, got \"x\"",
      "level.lua:10: argument 2: expected an integer",
      "level.lua:11: argument 3: expected \"shape\", \"ball\" or \"none\", got \"sphere\"",
      "ok"};
  for (const std::string& e : expected) {
    const Played p = play(live, 1);
    EXPECT_NE(p.status.message.find(e), std::string::npos) << "expected: " << e << "\ngot: " << p.status.message;
  }
}

// platon.sound checks its arguments against the scene's bank headless too: a misspelt sound fails
// in a scenario as it would in the game.
TEST(SoundApi, BadCallsAreErrorsAtTheScriptsLine) {
  Level level("sound_args",
              "local calls = {\n"
              "  function(s) s.play('jmup') end,\n"
              "  function(s) s.play('jump', 2) end,\n"
              "  function(s) s.play('jump', 1, -3) end,\n"
              "  function(s) s.play(5) end,\n"
              "  function(s) s.music('humm') end,\n"
              "  function(s) s.has('jump', 'effects') end,\n"
              "  function(s) assert(s.play('jump', 0.5, -1) == true) end,\n"
              "  function(s) s.music('orbit') assert(s.playing() == 'orbit') end,\n"
              "  function(s) s.music(nil) assert(s.playing() == nil) end,\n"
              "  function(s) assert(s.has('land') and s.has('orbit', 'music') and not s.has('orbit')) end }\n"
              "return { tick = function(game, frame)\n"
              "  local ok, e = pcall(calls[frame], platon.sound)\n"
              "  game.message(ok and 'ok' or e)\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const std::vector<std::string> expected = {
      "level.lua:2: sound: no effect named 'jmup' (the scene's bank has: checkpoint, cross, death, door, goal, jump, "
      "land, menu_move, menu_select, respawn, switch)",
      "level.lua:3: argument 2: expected a volume 0..1, got 2",
      "level.lua:4: argument 3: expected a pan -1..1, got -3",
      "level.lua:5: argument 1: expected a string, got 5",
      "level.lua:6: sound: no tune named 'humm' (the scene's bank has: crystal, first_steps, lattice, orbit, title)",
      "level.lua:7: argument 2: expected nil or \"music\", got \"effects\"",
      "ok",
      "ok",
      "ok",
      "ok"};
  for (const std::string& e : expected) {
    const Played p = play(live, 1);
    EXPECT_NE(p.status.message.find(e), std::string::npos) << "expected: " << e << "\ngot: " << p.status.message;
  }
}

// A frame plays at most core::Sounds::kMaxPerFrame effects; past that play() says false.
TEST(SoundApi, AFrameHoldsAtMostItsCapOfEffects) {
  Level level("sound_cap",
              "return { tick = function(game)\n"
              "  local played = 0\n"
              "  for i = 1, 40 do if platon.sound.play('land') then played = played + 1 end end\n"
              "  game.message(tostring(played))\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played p = play(live, 2);
  EXPECT_EQ(p.status.message, std::to_string(core::Sounds::kMaxPerFrame));
  EXPECT_EQ(live.scene().sounds().thisFrame().size(), core::Sounds::kMaxPerFrame);
}

// draw() runs once per displayed frame: a sound from it would depend on the display's rate.
TEST(SoundApi, DrawMayNotPlay) {
  Level level("sound_draw", "return { draw = function(game, draw) platon.sound.play('jump') end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  core::DrawList list(true);
  live.scene().draw(list);
  const Played p = play(live, 1);
  ASSERT_EQ(p.errors.size(), 1u);
  EXPECT_NE(p.errors[0].find("level.lua:1: sound: play from a frame's logic, not from draw"), std::string::npos)
      << p.errors[0];
  EXPECT_TRUE(live.scene().sounds().thisFrame().empty() || live.scene().sounds().thisFrame().front().name != "jump");
}

// Sounds are the listener's: a level that plays sounds and changes its tune every frame has the
// same state hash, frame by frame, as the same level silent.
TEST(SoundApi, SoundsNeverEnterTheStateHash) {
  const char* loud =
      "return { tick = function(game, frame)\n"
      "  platon.sound.play(frame % 2 == 0 and 'jump' or 'land', 0.5)\n"
      "  platon.sound.music(frame % 3 == 0 and 'orbit' or 'crystal')\n"
      "end }\n";
  const char* silent = "return { tick = function(game, frame) end }\n";
  Level a("sound_hash_loud", loud), b("sound_hash_silent", silent);
  const core::SystemRegistry registry = scripting();
  core::LiveScene withSound(a.scene, registry, false), without(b.scene, registry, false);
  core::InputEdges edgesA, edgesB;
  size_t heard = 0;
  for (int f = 1; f <= 400; ++f) {
    const core::Buttons held = InputFrame::bit(Button::Right) | (f % 50 < 10 ? InputFrame::bit(Button::Jump) : 0);
    ASSERT_FALSE(withSound.step(edgesA.next(held)));
    ASSERT_FALSE(without.step(edgesB.next(held)));
    heard += withSound.scene().sounds().thisFrame().size();
    ASSERT_EQ(withSound.scene().world().stateHash(), without.scene().world().stateHash()) << "frame " << f;
  }
  EXPECT_GE(heard, 400u);
}

// A level's own player script runs sandboxed but is handed the game state (it is the game's logic).
// What it writes there never becomes something the engine calls outside its limits: the engine
// dispatches on its own copies, game.Player and game.progression are sealed, and the engine's
// progression reads the game's tables raw (the re-audit planted an endless level tick this way and
// it ran 500 ms every frame, outside the budget; a metatable on game made reading it run code).
TEST(OwnPlayer, WhatItWritesInGameIsNeverCalledOutsideItsLimits) {
  Level level("own_player", "return {}\n", "", "", "");
  std::string player = fileText(std::string(PLATON_SOURCE_ROOT) + "/scripts/player.lua");
  const std::string attack =
      "local spin = function() while true do end end\n"
      "game.level.tick = spin\n"
      "game.mods = { { tick = spin } }\n"
      "local sealedPlayer = pcall(function() game.Player.tick = spin end)\n"
      "local sealedProgression = pcall(function() game.progression.afterStep = spin end)\n"
      "local lockedGame = pcall(setmetatable, game, { __index = spin })\n"
      "local lockedSwitches = pcall(setmetatable, game.switches, { __index = spin })\n"
      "game.message = tostring(sealedPlayer) .. ' ' .. tostring(sealedProgression) .. ' ' .. tostring(lockedGame) .. ' "
      "' .. tostring(lockedSwitches)\n";
  level.folder.write("scene.lua",
                     "return { name = 'own player', systems = { 'scripting' }, stage = { level = 'cube_intro.level' },"
                     " gravity = 0.35, scripts = { preset = 'game', player = 'player.lua', level = 'level.lua' } }\n");
  const core::SystemRegistry registry = scripting();
  // A checkpoint the engine would read through a metatable is set back, and the load says so.
  std::string planted = player;
  planted.replace(planted.find("return Player"), std::string("return Player").size(),
                  attack + "game.checkpoint = setmetatable({}, { __index = spin })\nreturn Player");
  level.folder.write("player.lua", planted);
  try {
    core::LiveScene refused(level.scene, registry, false);
    ADD_FAILURE() << "a planted checkpoint loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("game.checkpoint was left a table of another kind, where the engine reads nil "
                                         "or a table { face =, x =, y = } of numbers; it is set back"),
              std::string::npos)
        << e.what();
  }
  player.replace(player.find("return Player"), std::string("return Player").size(), attack + "return Player");
  level.folder.write("player.lua", player);
  core::LiveScene live(level.scene, registry, false);
  EXPECT_EQ(scriptsOf(live).status().message, "false false false false");
  Played p;
  for (int i = 0; i < 60; ++i) {  // Restart pressed every other frame: a respawn each time
    for (const core::Buttons held : {core::Buttons(InputFrame::bit(Button::Right) | InputFrame::bit(Button::Restart)),
                                     InputFrame::bit(Button::Right)}) {
      const Played one = play(live, 1, held);
      p.errors.insert(p.errors.end(), one.errors.begin(), one.errors.end());
      p.status = one.status;
    }
  }
  // Had the engine called a planted spin, the frame would never end (a compiled loop) or end in a
  // stop after twice the deadline (an interpreted one): the test would hang, or see the stop.
  EXPECT_GT(p.status.deaths, 50);  // the restarts respawned it, past the planted checkpoint
  for (const std::string& e : p.errors) EXPECT_EQ(e.find("stopped"), std::string::npos) << e;
}

// Every engine function a sandbox can call is counted as its own code is: with a level's own
// player, the engine's progression is within its reach (game.progression), and with its own
// progression, the engine's player (game.Player). Trusted, the JIT compiled such a function after
// a few calls and ran it uncounted, so a loop of calls ran on far past what its steps allowed,
// and how far depended on the process. Here each loop counts its calls until the budget stops it,
// against a loop calling a function of the script's own that does nothing.
TEST(OwnGameLogic, TheEnginesFunctionsItCallsAreCountedAsItsOwn) {
  const std::string player = fileText(std::string(PLATON_SOURCE_ROOT) + "/scripts/player.lua");
  const std::string progression = fileText(std::string(PLATON_SOURCE_ROOT) + "/scripts/progression.lua");
  struct Case {
    const char* own;   // "player" or "progression": the script the level brings
    const char* call;  // what its loop calls, as `f`
  };
  const Case cases[] = {
      {"player", "game.progression.spawnPoint"},
      {"player", "function() end"},
      {"progression", "game.Player.canJump"},
      {"progression", "function() end"},
  };
  const core::SystemRegistry registry = scripting();
  int calls[4] = {};
  for (int i = 0; i < 4; ++i) {
    const Case& c = cases[i];
    Level level(std::string("own_logic_") + std::to_string(i), "return {}\n");
    const std::string loop = std::string("if game.time == 3 then local f, self, n = ") + c.call +
                             ", { coyote = 1 }, 0 while true do f(self) n = n + 1 game.deaths = n end end\n";
    if (std::string(c.own) == "player") {
      std::string own = player;
      own.replace(own.find("function Player.tick(self, input)\n"), 34, "function Player.tick(self, input)\n" + loop);
      level.folder.write("player.lua", own);
    } else {
      std::string own = progression;
      own.replace(own.find("function progression.afterStep()\n"), 33, "function progression.afterStep()\n" + loop);
      level.folder.write("progression.lua", own);
    }
    level.folder.write("scene.lua",
                       std::string("return { name = 'own logic', systems = { 'scripting' }, stage = { level = "
                                   "'cube_intro.level' }, gravity = 0.35, scripts = { preset = 'game', ") +
                           c.own + " = '" + c.own + ".lua', level = 'level.lua' } }\n");
    core::LiveScene live(level.scene, registry, false);
    const Played p = play(live, 6);
    ASSERT_FALSE(p.errors.empty()) << c.call;
    // Stopped by the budget, in the level's script or in the engine's one it called (then the
    // stop names the level's script as the one that spent the budget): it is disabled either way.
    EXPECT_NE(p.errors[0].find("script stopped:"), std::string::npos) << p.errors[0];
    EXPECT_NE(p.errors[0].find("budget"), std::string::npos) << p.errors[0];
    EXPECT_NE(p.errors[0].find(std::string(c.own) + ".lua disabled"), std::string::npos) << p.errors[0];
    calls[i] = static_cast<int>(p.status.deaths);
  }
  // The engine's function costs its instructions and the call into another sandbox: fewer calls
  // fit the budget than of a function that does nothing (uncounted, more did).
  EXPECT_GT(calls[1], 0);
  EXPECT_LT(calls[0], calls[1] / 2) << calls[0] << " calls of game.progression.spawnPoint, " << calls[1]
                                    << " of its own";
  EXPECT_GT(calls[3], 0);
  EXPECT_LT(calls[2], calls[3] / 2) << calls[2] << " calls of game.Player.canJump, " << calls[3] << " of its own";
}

// Every index the API takes or hands out counts from 1, as Lua does: the line a contact names is
// the one lineAt gives for it (lineAt counted from 0, contacts and faces from 1), on the classic
// path a sandbox calls and the FFI path the engine's own scripts call.
TEST(Indices, ALinesIndexCountsFromOneAndAContactNamesIt) {
  const char* probe =
      "local w = game.world or platon.world\n"
      "local p = game.player and (type(game.player) == 'function' and game.player() or game.player.entity)\n"
      "local out = {}\n"
      "for i = 1, w.contactCount(p) do\n"
      "  local _, ny, _, kind, part, line = w.contact(p, i)\n"
      "  if kind ~= 'entity' and ny > 0.5 then\n"
      "    local x0, y0, x1, y1 = w.lineAt(part, line)\n"
      "    local _, py = w.position(p)\n"
      "    out[#out + 1] = (y0 == y1 and y0 < py and x0 <= 600 and x1 >= 600) and 'floor' or ('not ' .. y0 .. ' ' .. "
      "y1)\n"
      "    out[#out + 1] = tostring(pcall(w.lineAt, part, 0)) .. ' ' .. tostring(pcall(w.lineAt, part, "
      "w.lineCount(part)))"
      " .. ' ' .. tostring(pcall(w.lineAt, part, w.lineCount(part) + 1))\n"
      "  end\n"
      "end\n";
  Level level("indices", std::string("return { tick = function(game, frame) if frame == 40 then ") + probe +
                             " game.message(table.concat(out, ';')) end end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played p = play(live, 41, 0);
  EXPECT_TRUE(p.errors.empty()) << joined(p.errors);
  EXPECT_EQ(p.status.message, "floor;false true false") << "sandboxed, classic path";
  const std::string trusted =
      scriptsOf(live).evaluate(std::string("local game = ... ") + probe + " return table.concat(out, ';')", "=t");
  EXPECT_EQ(trusted, "floor;false true false") << "trusted, the FFI path";
}

// A rules table whose callback is not a function names the rules script (it named nothing).
TEST(RulesScript, ACallbackThatIsNoFunctionNamesTheScript) {
  Level level("rules_not_fn", "return {}\n", "", "return { pierce = function() return true end, contact = 5 }\n");
  const core::SystemRegistry registry = scripting();
  try {
    core::LiveScene live(level.scene, registry, false);
    ADD_FAILURE() << "loaded";
  } catch (const std::exception& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(std::string("rules.lua") + ": rules: 'contact' is a number, not a function"), std::string::npos)
        << m;
  }
}

// An error message with a NUL in it is shown whole (it was cut at the NUL), and a huge one is cut.
TEST(ErrorMessages, ANulDoesNotCutAMessageAndAHugeOneIsCut) {
  Level level("error_nul",
              "return { tick = function(game, frame)\n"
              "  if frame == 1 then error('before\\0after') end\n"
              "  if frame == 2 then error(string.rep('x', 1000000)) end\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played p = play(live, 2);
  ASSERT_EQ(p.errors.size(), 2u) << joined(p.errors);
  EXPECT_NE(p.errors[0].find("level.lua:2: before\\0after"), std::string::npos) << p.errors[0];
  EXPECT_LT(p.errors[1].size(), 20000u);
  EXPECT_NE(p.errors[1].find("bytes in all)"), std::string::npos);
}

// Option tables with a misspelt field or two shapes, and a body put off its face, are errors at the
// script's line (they were taken silently: the typo ignored, the first shape used, the body put
// back by a corner).
TEST(WorldApi, TyposTwoShapesAndBodiesOffTheirFaceAreErrors) {
  // One call a frame, its error (or "ok") the frame's message.
  Level level("world_api_typos",
              "local e\n"
              "local calls = {\n"
              "  function(w) w.setFilter(e, { catgory = 1 }) end,\n"
              "  function(w) w.createEntity { circle = 5, box = { 1, 1 } } end,\n"
              "  function(w) w.insert(e, 0, -5000, 2500) end,\n"
              "  function(w) w.insert(e, 0, 4096 + 20, 2000) end }\n"
              "return { tick = function(game, frame)\n"
              "  e = e or game.world.createEntity { circle = 20 }\n"
              "  local ok, err = pcall(calls[frame], game.world)\n"
              "  game.message(ok and 'ok' or err)\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const std::vector<std::string> expected = {
      "level.lua:3: setFilter: unknown field \"catgory\" (known: category, solidWith, overlapWith, pushable)",
      "level.lua:4: createEntity: one shape: circle, box or polygon, not two",
      "level.lua:5: insert: (-5000, 2500) is not on face 0",
      "ok"};  // 20 units over an edge, as while crossing it: fine
  for (const std::string& e : expected) {
    const Played p = play(live, 1);
    EXPECT_NE(p.status.message.find(e), std::string::npos) << "expected: " << e << "\ngot: " << p.status.message;
  }
}

// A mod the manifest names but the folder lacks is reported at the manifest's line:column.
TEST(Manifests, AMissingModIsNamedAtTheManifestsPlace) {
  Level level("missing_mod", "return {}\n");
  level.folder.write("scene.lua",
                     "return { name = 'x', systems = { 'scripting' }, stage = { level = 'cube_intro.level' },\n"
                     "  scripts = { preset = 'game', level = 'level.lua', mods = { 'gone.lua' } } }\n");
  const core::SystemRegistry registry = scripting();
  try {
    core::LiveScene live(level.scene, registry, false);
    ADD_FAILURE() << "loaded";
  } catch (const std::exception& e) {
    const std::string m = e.what();
    EXPECT_NE(
        m.find("gone.lua: the script: cannot open it: No such file or directory (named at " + level.scene + ":2:62)"),
        std::string::npos)
        << m;
  }
}

TEST(OutputCaps, MessagesAndDrawingAreCapped) {
  Level level(
      "f14_caps",
      "return {\n"
      "  tick = function(game, frame) game.message(string.rep('\\226\\128\\162', 100000)) end,\n"
      "  draw = function(game, draw) for i = 1, 20000 do draw.text('screen', 0, 0, 'x', 10, 0xffffff) end end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played p = play(live, 2);
  EXPECT_TRUE(p.errors.empty()) << joined(p.errors);
  EXPECT_LE(p.status.message.size(), 200u + 3);
  EXPECT_EQ(p.status.message.size() % 3, 0u);  // cut between characters (each 3 bytes), then "..."
  core::DrawList list(true);
  live.scene().draw(list);
  EXPECT_TRUE(list.shapes().empty());  // the draw failed: an empty picture
  const Played q = play(live, 1);
  ASSERT_EQ(q.errors.size(), 1u);
  EXPECT_NE(q.errors[0].find("level.lua:3: draw: this frame's picture is full (at most 10000 shapes"),
            std::string::npos)
      << q.errors[0];
}

// --- 15: a mod at the memory ceiling leaves the engine's scripts their reserve ---

TEST(MemoryCeiling, AModAtTheMemoryCeilingDoesNotStarveThePlayer) {
  const char* mod =
      "hoard = {}\n"
      "return { tick = function(game, frame)\n"
      "  pcall(function() while true do hoard[#hoard + 1] = string.rep('x', 4096) .. #hoard end end)\n"
      "end }\n";
  Level level("f15_memhog", "return {}\n", mod, "", ", limits = { memory_mb = 32 }");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played p = play(live, 200);
  ASSERT_EQ(p.errors.size(), 1u) << joined(p.errors);
  EXPECT_NE(
      p.errors[0].find(
          "mod.lua:3: script stopped: the sandboxes reached their memory limit of 24 MB (of the Lua state's 32 MB"),
      std::string::npos)
      << p.errors[0];
  EXPECT_NE(p.errors[0].find("mod.lua disabled"), std::string::npos);
  EXPECT_GT(p.status.x, 1500);                                   // the player walked on
  EXPECT_LT(scriptsOf(live).luaMemoryBytes(), size_t{8} << 20);  // the hoard was collected
}

// --- 17: replays are exact: the same run gives the same hash in separate processes ---

// Plays `frames` frames of `scene` in a fresh process (LuaJIT seeds its string hashes and its JIT
// per process) and returns what `read` reads of the live scene then (0 when it failed).
uint64_t inAChildProcess(const std::string& scene, int frames, uint64_t (*readOf)(core::LiveScene&)) {
  int pipeFds[2];
  if (pipe(pipeFds) != 0) return 0;
  const pid_t child = fork();
  if (child == 0) {
    close(pipeFds[0]);
    uint64_t value = 0;
    try {
      const core::SystemRegistry registry = scripting();
      core::LiveScene live(scene, registry, false);
      play(live, frames);
      value = readOf(live);
    } catch (...) {}
    (void)!write(pipeFds[1], &value, sizeof value);
    _exit(0);
  }
  close(pipeFds[1]);
  uint64_t value = 0;
  (void)!read(pipeFds[0], &value, sizeof value);
  close(pipeFds[0]);
  waitpid(child, nullptr, 0);
  return value;
}

uint64_t hashInAChildProcess(const std::string& scene) {
  return inAChildProcess(scene, 60, [](core::LiveScene& live) { return live.scene().world().stateHash(); });
}

// A sandbox that floods memory while it changes the world is stopped in every process, in the same
// frame, with the world up to that frame the same. Where in the frame is close but not exact: the
// state's memory (what the share is measured on) differs a little from one process to the next
// (LuaJIT seeds its string hashes per process, so tables resize and the collector runs at other
// moments; the JIT is not the cause: turned off, runs still differed), and that flood counts its
// place into face 5's gravity, so a later stop shows as a larger count (docs/scripting.md, Limits).
TEST(MemoryCeiling, AMemoryFloodIsStoppedInTheSameFrameOfEveryProcess) {
  const char* level =
      "hoard = {}\n"
      "return { tick = function(game, frame)\n"
      "  if frame < 300 then return end\n"
      "  for i = 1, 1e6 do\n"
      "    hoard[#hoard + 1] = string.rep('x', 1000 + i % 7) .. i\n"
      "    game.world.setGravity(5, i / 65536, 0.35)\n"
      "  end\n"
      "end }\n";
  Level flood("f15_memory_stop", level, "", "", ", limits = { memory_mb = 32 }");
  const auto before = [](core::LiveScene& live) { return live.scene().world().stateHash(); };
  const auto count = [](core::LiveScene& live) {
    return static_cast<uint64_t>(live.scene().world().mapPart(5).gravity().x);
  };
  const uint64_t hashBefore = inAChildProcess(flood.scene, 299, before);
  uint64_t least = UINT64_MAX, most = 0;
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(inAChildProcess(flood.scene, 299, before), hashBefore);
    const uint64_t n = inAChildProcess(flood.scene, 300, count);
    least = std::min(least, n), most = std::max(most, n);
  }
  // 24 MB of 1 KB strings: about 23,600 of them, and the processes within a few of each other
  // (26 apart at most in 36 processes; the bound leaves room for other allocators and loads).
  EXPECT_GT(least, 15'000u);
  EXPECT_LE(most - least, 256u) << least << " to " << most;
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(flood.scene, registry, false);
  const Played p = play(live, 320);
  ASSERT_EQ(p.errors.size(), 1u) << joined(p.errors);
  EXPECT_NE(p.errors[0].find("frame 300: "), std::string::npos) << p.errors[0];
  EXPECT_NE(p.errors[0].find("level.lua:5: script stopped: the sandboxes reached their memory limit of 24 MB"),
            std::string::npos)
      << p.errors[0];
  EXPECT_LT(scriptsOf(live).luaMemoryBytes(), size_t{8} << 20);  // the hoard was collected
}

TEST(Determinism, PairsClocksAndAddressesGiveTheSameRunInEveryProcess) {
  const char* script =
      "local keys = {}\n"
      "for i = 1, 8 do keys['k' .. i] = i end\n"
      "local order = {}\n"
      "for k, v in pairs(keys) do order[#order + 1] = v end\n"
      "local first = next(keys)\n"
      "local id = tonumber(tostring({}):match('%d+$')) or 1e9\n"
      "return { tick = function(game, frame)\n"
      "  if frame == 30 then\n"
      "    local vx = order[1] + (os.clock() * 60) % 3 + os.time() % 2 + #os.date('%H') + id % 2 + #first\n"
      "    game.world.setVelocity(game.player(), vx, -3)\n"
      "  end\n"
      "end }\n";
  Level level("f17_determinism", script);
  const uint64_t first = hashInAChildProcess(level.scene);
  ASSERT_NE(first, 0u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(hashInAChildProcess(level.scene), first) << "run " << i + 2;
  // What it saw: keys in byte order, the game's clock at frame 30 (0.5 s after 1970-01-01 UTC).
  Level show(
      "f17_show",
      "local keys = {}\nfor i = 1, 8 do keys['k' .. i] = i end\n"
      "local order = {}\nfor k, v in pairs(keys) do order[#order + 1] = v end\n"
      "return { tick = function(game, frame) if frame == 30 then game.message(table.concat(order, ',') .. ' ' .. "
      "os.clock() .. ' ' ..\n"
      "  os.time() .. ' ' .. os.date('%Y-%m-%d %H:%M:%S') .. ' ' .. tostring(print):gsub('%d+', 'N')) end end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(show.scene, registry, false);
  const Played p = play(live, 30);
  EXPECT_EQ(p.status.message, "1,2,3,4,5,6,7,8 0.48333333333333 0 1970-01-01 00:00:00 function: #N");
  Level tables("f17_table_keys", "local t = { [{}] = 1 } for k in pairs(t) do end return {}\n");
  try {
    core::LiveScene refused(tables.scene, registry, false);
    FAIL();
  } catch (const std::exception& e) {
    EXPECT_NE(core::errorReport(e).find("level.lua:1: pairs over table keys has no fixed order in a replayable game"),
              std::string::npos)
        << core::errorReport(e);
  }
}

// --- 19: error messages say where, and who ---

TEST(ErrorMessages, ErrorsNameTheSandboxedFileAndLine) {
  struct Case {
    const char* tick;
    const char* message;
  };
  const Case cases[] = {
      {"error({})", "level.lua:1: (error object is a table value)"},
      {"local function f(n) return 1 + f(n) end f(1)", "level.lua:1: stack overflow"},
      {"local t = setmetatable({}, {__index = function(t, k) return t[k] end}) local _ = t.x",
       "level.lua:1: stack overflow"},
      {"game.world.setVelocity(game.player(), 0, 2^45)",
       "level.lua:1: argument 3: expected a velocity within +-2^30 units per frame, got 35184372088832"},
      {"game.world.setFilter(game.player(), { category = 2^32 })",
       "level.lua:1: setFilter: category: expected an integer in [0, 4294967295], got 4294967296"},
      {"game.world.createEntity { polygon = { 0, 0, 10, 0, 'x' } }",
       "level.lua:1: createEntity: polygon: item 5 is not an integer coordinate"},
      {"game.world.createEntity { circle = 0.5 }",
       "level.lua:1: createEntity: circle: expected an integer in [1, 268435456], got 0.5"},
      {"local ok = pcall(string.rep, 'x', 1e9) local t = nil return t.field",
       "level.lua:1: script stopped: the sandboxes reached their memory limit"},
  };
  for (const Case& c : cases) {
    Level level("f19_messages",
                std::string("return { tick = function(game, frame) if frame == 2 then ") + c.tick + " end end }\n");
    const core::SystemRegistry registry = scripting();
    core::LiveScene live(level.scene, registry, false);
    const Played p = play(live, 3);
    ASSERT_FALSE(p.errors.empty()) << c.tick;
    EXPECT_NE(p.errors[0].find("frame 2: " + std::string(c.message)), std::string::npos) << c.tick << "\n"
                                                                                         << p.errors[0];
  }
}

// The velocity's range is the world's, the same with the FFI path (the default) and without.
TEST(ErrorMessages, TheVelocityRangeIsTheWorldsOnBothPaths) {
  for (const bool ffi : {true, false}) {
    if (ffi)
      unsetenv("PLATON_NO_FFI");
    else
      setenv("PLATON_NO_FFI", "1", 1);
    Level level("f19_velocity",
                "local e\n"
                "return { tick = function(game, frame)\n"
                "  e = e or game.world.createEntity { circle = 10 }  -- not inserted: it does not move\n"
                "  if frame == 2 then game.world.setVelocity(e, 2^30, -2^30) end\n"
                "  if frame == 3 then game.world.setVelocity(e, 2^30 + 1, 0) end\n"
                "end }\n");
    const core::SystemRegistry registry = scripting();
    core::LiveScene live(level.scene, registry, false);
    const Played p = play(live, 3, 0);
    ASSERT_EQ(p.errors.size(), 1u) << (ffi ? "FFI" : "classic") << "\n" << joined(p.errors);
    EXPECT_NE(p.errors[0].find("frame 3: " + std::string("level.lua") +
                               ":5: argument 2: expected a velocity within +-2^30 units per frame, got 1073741825"),
              std::string::npos)
        << p.errors[0];
  }
  unsetenv("PLATON_NO_FFI");
}

// A sandboxed rules script that spends the frame inside a trusted call (the player's spawn asks
// pierce): the stop names the rules script, not the engine's code that happened to run.
TEST(ErrorMessages, ABudgetStopBlamesTheSandboxThatSpentIt) {
  const char* rules =
      "local rules = {}\n"
      "function rules.pierce(entity, tag, kind)\n"
      "  while true do end\n"
      "end\n"
      "return rules\n";
  Level level("f19_blame", "return {}\n", "", rules, ", limits = { steps = 1e6 }");
  const core::SystemRegistry registry = scripting();
  try {
    core::LiveScene live(level.scene, registry, false);
    FAIL() << "loaded";
  } catch (const std::exception& e) {
    const std::string report = core::errorReport(e);
    EXPECT_EQ(
        report.rfind(
            std::string("rules.lua") + ":3: script stopped: it ran past the frame's script budget of 1000000 steps", 0),
        0u)
        << report;
  }
}

// --- 20: table.sort runs in C: a bound on what it sorts ---

TEST(SortBound, SortRefusesHugeTables) {
  Level level("f20_sort",
              "return { build = function(game)\n"
              "  local t = {} for i = 1, 1000001 do t[i] = -i end\n"
              "  local ok, e = pcall(table.sort, t)\n"
              "  local small = { 3, 1, 2 } table.sort(small)\n"
              "  game.message(tostring(e) .. ' / ' .. table.concat(small, ','))\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  EXPECT_EQ(scriptsOf(live).status().message,
            "table.sort: at most 1000000 items in a sandbox (this table has 1000001) / 1,2,3");
}

// --- re-audit N7: a read-only view lists what it shows ---

// pairs, next and ipairs over game, game.world and platon walk the entries the view shows (they
// saw nothing before), in the fixed order; what they hand out is what indexing gives (functions
// and views), so the view stays read-only, and a copy of the API works.
TEST(ReAuditN7, PairsNextAndIpairsWalkAViewsEntriesAndItStaysReadOnly) {
  Level level("n7_views",
              "return { build = function(game)\n"
              "  local names = {}\n"
              "  for k, v in pairs(game) do names[#names + 1] = k .. ':' .. type(v) end\n"
              "  local viaPairs, viaNext = {}, {}\n"
              "  for k, v in pairs(game.world) do viaPairs[#viaPairs + 1] = k assert(v == game.world[k]) end\n"
              "  local k = next(game.world) while k ~= nil do viaNext[#viaNext + 1] = k k = next(game.world, k) end\n"
              "  assert(#viaPairs > 10 and table.concat(viaPairs, ' ') == table.concat(viaNext, ' '))\n"
              "  local _, state = pairs(game) assert(rawequal(state, game), 'pairs handed out the entries')\n"
              "  local n = 0 for _ in ipairs(game) do n = n + 1 end\n"
              "  for k, v in pairs(game) do assert(not pcall(function() game[k] = v end)) end\n"
              "  assert(not pcall(function() for k, v in pairs(platon) do v.x = 1 end end))\n"
              "  local copy = {} for k, v in pairs(game) do copy[k] = v end\n"
              "  local drawNames = {} for k in pairs(platon.draw) do drawNames[#drawNames + 1] = k end\n"
              "  copy.message(names[1] .. ' ' .. names[#names] .. ' ' .. n .. ' ' .. #game .. ' ' .. "
              "tostring((next(platon))) .. ' ' ..\n"
              "               table.concat(drawNames, ','))\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  EXPECT_EQ(scriptsOf(live).status().message,
            "checkpoint:function world:table 0 0 draw circle,enabled,line,look,polygon,text");
}

// --- The physics of what a sandbox makes is charged to it ---

// `count` bodies of `shape` dropped on face 3 by `maker` (the level's build or tick, or a mod's
// tick), with the level's and the mod's ticks saying they still run.
std::string bodiesMaker(const std::string& shape, int count) {
  return "local made = false\n"
         "local function make(w)\n"
         "  if made then return end made = true\n"
         "  for i = 0, " +
         std::to_string(count - 1) +
         " do\n"
         "    local e = w.createEntity(" +
         shape +
         ")\n"
         "    w.insert(e, w.face(4), 200 + (i % 40) * 90, 700 + math.floor(i / 40) * 90)\n"
         "  end\n"
         "end\n";
}

TEST(MadeBodies, ThePhysicsOfWhatASandboxMakesIsChargedToItAndOverTheBudgetItStops) {
  const core::SystemRegistry registry = scripting();
  const std::string shapes[] = {"{ circle = 20 }", "{ box = { 20, 15 } }",
                                "{ polygon = { -20, -20, 20, -20, 0, 25 } }"};
  for (const std::string maker : {"tick", "mod"})  // (a build cannot insert: the stage is not joined yet)
    for (const std::string& shape : shapes) {
      SCOPED_TRACE(maker + " " + shape);
      const std::string levelMakes =
          bodiesMaker(shape, 400) + "return { build = function(game) " + (maker == "build" ? "make(game.world)" : "") +
          " end, tick = function(game, frame) " + (maker == "tick" ? "make(game.world)" : "") +
          " game.message('level ' .. frame) end }\n";
      const std::string modMakes =
          bodiesMaker(shape, 400) + "return { tick = function(game, frame) make(game.world) end }\n";
      // 400 bodies: each frame at least 400 * 16 * 20 = 128,000 steps, over a budget of 100,000.
      Level over("made_over",
                 maker == "mod" ? bodiesMaker(shape, 0) +
                                      "return { tick = function(game, frame) "
                                      "game.message('level ' .. frame) end }\n"
                                : levelMakes,
                 maker == "mod" ? modMakes : "return { tick = function() end }\n", "", ", limits = { steps = 1e5 }");
      core::LiveScene live(over.scene, registry, false);
      const Played p = play(live, 30);
      const std::string file = maker == "mod" ? "mod.lua" : "level.lua";
      bool stopped = false;
      for (const std::string& e : p.errors)
        stopped = stopped || (e.find(file + ": stopped: the physics of the 400 bodies and 0 platforms it made") !=
                                  std::string::npos &&
                              e.find("past the frame's script budget of 100000 steps") != std::string::npos &&
                              e.find(file + " disabled: fix it and save to reload") != std::string::npos);
      EXPECT_TRUE(stopped) << joined(p.errors);
      EXPECT_EQ(live.scene().world().entityCount(), 1u) << "what it made is removed; the player stays";
      if (maker == "mod") {
        EXPECT_EQ(p.status.message, "level 30");  // the level goes on without the mod
      }
      // Under the budget the same bodies run, and stay.
      Level under("made_under", fileText(over.folder.path("level.lua")),
                  maker == "mod" ? fileText(over.folder.path("mod.lua")) : "return { tick = function() end }\n", "",
                  ", limits = { steps = 1e7 }");
      core::LiveScene fine(under.scene, registry, false);
      const Played q = play(fine, 30);
      EXPECT_TRUE(q.errors.empty()) << joined(q.errors);
      EXPECT_EQ(fine.scene().world().entityCount(), 401u);
    }
}

// Platforms are charged as bodies are: a level turning a comb of 1,000 lines high over the floor
// pays for the lines placed each sub-step (two a frame: 2,000 lines, 40,000 steps), and past the
// budget it is stopped and the platform removed; under the budget it turns on. A turn too costly for one frame (a far
// pivot, the fastest spin) is an error at the script's line.
TEST(MadeBodies, APlatformsMovesAndTurnsAreChargedToTheSandboxThatMadeIt) {
  const std::string comb =
      "local p\n"
      "local function make(game)\n"
      "  local lines = {}\n"
      "  for i = 0, 999 do lines[#lines + 1] = 1500 + i; lines[#lines + 1] = 3000; "
      "lines[#lines + 1] = 1500 + i; lines[#lines + 1] = 3100 end\n"
      "  p = game.world.createPlatform(0, lines)\n"
      "  game.world.setPlatformSpin(p, 2000, 3050, 10)\n"
      "end\n"
      "return { tick = function(game, frame)\n"
      "  if not p then make(game) end\n"
      "  game.message('turned ' .. math.floor(game.world.platformAngle(p) + 0.5))\n"
      "end }\n";
  const core::SystemRegistry registry = scripting();
  {
    Level over("comb_over", comb, "", "", ", limits = { steps = 2e4 }");
    core::LiveScene live(over.scene, registry, false);
    const Played p = play(live, 10, 0);
    bool stopped = false;
    for (const std::string& e : p.errors)
      stopped = stopped ||
                e.find("level.lua: stopped: the physics of the 0 bodies and 1 platforms it made") != std::string::npos;
    EXPECT_TRUE(stopped) << joined(p.errors);
    EXPECT_TRUE(live.scene().world().platforms().empty()) << "what it made is removed";
  }
  {
    Level under("comb_under", comb, "", "", ", limits = { steps = 1e8 }");
    core::LiveScene live(under.scene, registry, false);
    const Played p = play(live, 10, 0);
    EXPECT_TRUE(p.errors.empty()) << joined(p.errors);
    EXPECT_EQ(p.status.message, "turned 90");  // made at the first tick: the tenth reads nine turns
  }
  {
    Level far("far_pivot",
              "return { build = function(game)\n"
              "  local p = game.world.createPlatform(0, { 100, 900, 4000, 900 })\n"
              "  game.world.setPlatformSpin(p, -1000000000, 950, 22.5)\n"
              "end }\n");
    // The level does not load: its build fails at the call, which says why.
    try {
      core::LiveScene live(far.scene, registry, false);
      ADD_FAILURE() << "a turn of 6,210 sub-steps a frame was taken";
    } catch (const std::exception& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("level.lua:3: setPlatformSpin: turning its 1 lines about (-1000000000, 950)"), std::string::npos)
          << m;
      EXPECT_NE(m.find("takes 6210 sub-steps a frame (at most 1024"), std::string::npos) << m;
    }
  }
}

// A level's own player may write into `game`, but every field the engine reads is checked after
// each of its calls: a wrong type (one with metamethods the engine would run outside every limit,
// game.time + 1 with an __add among them) is set back, and is the player's error at its file:line;
// the game goes on.
TEST(OwnPlayer, EveryFieldTheEngineReadsIsCheckedAndSetBack) {
  const std::string spin =
      "setmetatable({}, { __add = function() while true do end end, __index = function() "
      "while true do end end, __eq = function() while true do end end })";
  const std::pair<const char*, std::string> writes[] = {
      {"time", spin},
      {"time", "'12'"},
      {"time", "1.5"},
      {"deaths", spin},
      {"deaths", "true"},
      {"wonFrame", "{}"},
      {"won", "'yes'"},
      {"won", spin},
      {"message", "{}"},
      {"message", spin},
      {"checkpoint", "{ face = 'a', x = 1, y = 2 }"},
      {"checkpoint", spin},
      {"checkpoint", "5"},
      {"switches", spin},
      {"switches", "'none'"},
      {"openSwitches", "{ 'a' }"},
      {"player", "5"},
  };
  const core::SystemRegistry registry = scripting();
  const std::string stock = fileText(std::string(PLATON_SOURCE_ROOT) + "/scripts/player.lua");
  for (const auto& [field, value] : writes) {
    SCOPED_TRACE(std::string(field) + " = " + value);
    Level level("own_player_fields", "return {}\n", "", "", "");
    std::string player = stock;
    const std::string tick = "function Player.tick(self, input)\n";
    player.replace(player.find(tick), tick.size(), tick + "  game." + field + " = " + value + "\n");
    level.folder.write("player.lua", player);
    level.folder.write(
        "scene.lua",
        "return { name = 'own player', systems = { 'scripting' }, stage = { level = 'cube_intro.level' },"
        " gravity = 0.35, scripts = { preset = 'game', player = 'player.lua', level = 'level.lua' },"
        " limits = { steps = 1e6 } }\n");
    core::LiveScene live(level.scene, registry, false);
    const Played p = play(live, 20);
    ASSERT_FALSE(p.errors.empty());
    EXPECT_NE(p.errors[0].find("player.lua:"), std::string::npos) << p.errors[0];
    EXPECT_NE(p.errors[0].find(std::string("game.") + field + " was left "), std::string::npos) << p.errors[0];
    EXPECT_NE(p.errors[0].find("; it is set back"), std::string::npos) << p.errors[0];
    for (const std::string& e : p.errors) EXPECT_EQ(e.find("stopped"), std::string::npos) << e;
    EXPECT_EQ(p.status.time, 20u) << "the game's clock goes on";
  }
}

// A mod has the level script's hooks: its build runs after the level's (and may add lines), its
// draw after the level's, and the level goes on when the mod fails.
TEST(Mods, AModBuildsAndDrawsAfterTheLevel) {
  Level level("mod_hooks", "return { build = function(game) game.message('level built') end }\n",
              "return {\n"
              "  build = function(game) game.world.line(game.world.face(1), 100, 2000, 900, 2000)\n"
              "                         game.message('mod built after the level') end,\n"
              "  draw = function(game, draw) draw.circle(0, 500, 500, 40, 0xff0000) end,\n"
              "}\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  EXPECT_EQ(scriptsOf(live).status().message, "mod built after the level");
  const core::Scene& scene = live.scene();
  const physics::MapPart& face = scene.world().mapPart(scene.stage()->part(0));
  bool added = false;
  for (const physics::Segment& line : face.segments()) added = added || (line.a.x == 100 && line.a.y == 2000);
  EXPECT_TRUE(added) << "the mod's line is not on face 0";
  core::DrawList draw(true);
  scriptsOf(live).draw(scene, draw);
  bool red = false;
  for (const core::DrawShape& shape : draw.shapes()) red = red || (shape.color.r == 255 && shape.color.g == 0);
  EXPECT_TRUE(red) << "the mod's draw drew nothing";
}

// The globals luacheck lints a level's scripts against (.luacheckrc, stds.sandbox) are exactly
// those a sandboxed script finds in _G: a global added to or taken from the sandbox fails here
// until the lint knows it too.
TEST(Lint, TheSandboxGlobalsAreTheLintsGlobals) {
  Level level("lint_globals",
              "local names = {}\n"
              "for k in pairs(_G) do names[#names + 1] = k end\n"
              "table.sort(names)\n"
              "return { build = function(game) game.message(table.concat(names, ',')) end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const std::string found = scriptsOf(live).status().message;
  const std::string rc = fileText(std::string(PLATON_SOURCE_ROOT) + "/.luacheckrc");
  const size_t start = rc.find("stds.sandbox"), open = rc.find("read_globals = {", start), close = rc.find('}', open);
  ASSERT_NE(start, std::string::npos) << ".luacheckrc has no stds.sandbox";
  std::vector<std::string> listed;
  for (size_t q = rc.find('"', open); q < close; q = rc.find('"', rc.find('"', q + 1) + 1))
    listed.push_back(rc.substr(q + 1, rc.find('"', q + 1) - q - 1));
  std::sort(listed.begin(), listed.end());
  std::string lint;
  for (const std::string& name : listed) lint += (lint.empty() ? "" : ",") + name;
  EXPECT_EQ(lint, found) << "the sandbox's globals and .luacheckrc's stds.sandbox differ";
}

// The jump cut shortens the player's own jump only: a level script that throws the standing player
// up (a springboard) keeps the whole rise with jump not held, for launch speeds above the cut;
// a jump tapped for one frame is still cut short.
TEST(PlayerScript, TheJumpCutShortensOnlyThePlayersOwnJump) {
  for (const int speed : {6, 10, 15, 22}) {
    Level level("jump_cut",
                "local top, y0 = 0\n"
                "return { tick = function(game, frame)\n"
                "  local e = game.player()\n"
                "  local _, _, y = game.world.position(e)\n"
                "  if frame == 30 then y0 = y game.world.setVelocity(e, 0, " +
                    std::to_string(speed) +
                    ") end\n"
                    "  if frame > 30 then top = math.max(top or y, y) end\n"
                    "  if frame == 150 then game.message(tostring(top - y0)) end\n"
                    "end }\n");
    const core::SystemRegistry registry = scripting();
    core::LiveScene live(level.scene, registry, false);
    const Played p = play(live, 150, 0);
    ASSERT_TRUE(p.errors.empty()) << joined(p.errors);
    const double rise = std::stod(p.status.message), expected = speed * speed / (2 * 0.35);
    EXPECT_GT(rise, 0.85 * expected) << "launched at " << speed << " units per frame";
  }
  // A jump pressed for one frame and let go: cut to JUMP_CUT, far below a held jump's 11^2 / 0.7.
  Level level("jump_tap",
              "local top, y0\n"
              "return { tick = function(game, frame)\n"
              "  local _, _, y = game.world.position(game.player())\n"
              "  if frame == 30 then y0 = y end\n"
              "  if frame > 30 then top = math.max(top or y, y) end\n"
              "  if frame == 150 then game.message(tostring(top - y0)) end\n"
              "end }\n");
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  core::InputEdges edges;
  for (int f = 1; f <= 150; ++f) ASSERT_FALSE(live.step(edges.next(f == 31 ? InputFrame::bit(Button::Jump) : 0)));
  const double tapped = std::stod(scriptsOf(live).status().message);
  EXPECT_GT(tapped, 10);
  EXPECT_LT(tapped, 0.5 * 11 * 11 / (2 * 0.35));
}

}  // namespace
}  // namespace platon::script

namespace platon::script {
namespace {

// What a sandbox sees of itself is the same wherever its level is installed: its errors (caught
// with pcall), its tracebacks' names and what it computes from them name the file from the level's
// folder ("mods/m.lua:2:"), never the player's folders; the same level in two places of different
// depths plays to the same message and the same state hash.
TEST(ErrorMessages, ASandboxSeesTheSameNamesWhereverItsLevelIs) {
  const std::string level =
      "return { tick = function(game, frame)\n"
      "  local ok, e = pcall(function() error('x') end)\n"
      "  local ok2, e2 = pcall(function() game.world.setVelocity(game.player(), 0, 2^45) end)\n"
      "  game.message(e .. ' | ' .. e2 .. ' | ' .. #e .. ' ' .. #e2)\n"
      "  if #e2 % 2 == 1 then game.world.setVelocity(game.player(), 65536, 0) end\n"
      "end }\n";
  // The mod checks what it sees itself: an error of its own is named from the level's folder.
  const std::string mod =
      "return { tick = function(game, frame)\n"
      "  local ok, e = pcall(function() error('m') end)\n"
      "  if e ~= 'mods/m.lua:2: m' then error('the mod saw ' .. e) end\n"
      "end }\n";
  std::vector<std::string> messages;
  std::vector<std::string> hashes;
  for (const std::string& where :
       {std::string("f19_short"), std::string("f19_a_much_longer_folder_name/deeper/still")}) {
    Folder folder(where);
    folder.write("cube_intro.level", fileText(std::string(PLATON_SOURCE_ROOT) + "/levels/cube_intro/cube_intro.level"));
    folder.write("level.lua", level);
    folder.write("mods/m.lua", mod);
    const std::string scene =
        folder.write("scene.lua",
                     "return { name = 'where', systems = { 'scripting' }, stage = { level = 'cube_intro.level' },"
                     " scripts = { preset = 'game', level = 'level.lua', mods = { 'mods/m.lua' } } }\n");
    const core::SystemRegistry registry = scripting();
    core::LiveScene live(scene, registry, false);
    const Played p = play(live, 30);
    EXPECT_TRUE(p.errors.empty()) << joined(p.errors);
    messages.push_back(p.status.message);
    hashes.push_back(std::to_string(live.scene().world().stateHash()));
    EXPECT_EQ(p.status.message.find('/' + std::string("tmp")), std::string::npos) << p.status.message;
  }
  EXPECT_EQ(messages[0], messages[1]);
  EXPECT_EQ(hashes[0], hashes[1]);
  EXPECT_NE(messages[0].find("level.lua:2: x | level.lua:3: argument 3"), std::string::npos) << messages[0];
}

}  // namespace
}  // namespace platon::script
