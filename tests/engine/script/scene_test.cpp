// Scenes from manifests: what they load and what they leave out, script errors with file:line,
// and scenarios that pass and fail.
#include "platon/core/scene.h"

#include <dlfcn.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <gtest/gtest.h>

#include "platon/script/scenario.h"
#include "platon/script/script_system.h"
#include "platon/testing/mapped.h"
#include "platon/testing/temp_folder.h"

namespace platon::script {
namespace {

namespace fs = std::filesystem;

using Folder = platon::testing::TempFolder;

std::string manifestError(const std::string& text) {
  Folder folder("manifest");
  const std::string path = folder.write("scene.lua", text);
  try {
    core::loadManifest(path);
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    return message.substr(message.find("scene.lua"));
  }
  return "";
}

// One table of the manifest's keys: the reader's known keys, ranges and defaults, the struct's
// defaults and docs/scripting.md's table are all it.
TEST(Manifest, TheKeysAreOneTableTheReaderTheStructAndTheDocsShare) {
  const core::SceneManifest defaults;
  for (const core::ManifestKey& k : core::manifestKeys()) {
    const std::string key = k.key;
    if (key == "stage.edge") {
      EXPECT_EQ(defaults.edge, k.fallback);
    }
    if (key == "gravity") {
      EXPECT_EQ(defaults.gravity, k.fallback);
    }
    if (key == "seed") {
      EXPECT_EQ(defaults.seed, k.fallback);
    }
    if (key == "stage.solid") {
      EXPECT_EQ(defaults.solid, k.shown);
    }
    if (key == "limits.memory_mb") {
      EXPECT_EQ(defaults.memoryMegabytes, k.fallback);
    }
    if (key == "limits.steps") {
      EXPECT_EQ(defaults.frameSteps, k.fallback);
    }
    if (key == "limits.deadline_ms") {
      EXPECT_EQ(defaults.deadlineMilliseconds, k.fallback);
    }
    // Each number's range is the reader's: one past either end is refused, naming the key.
    const std::string holds = k.holds;
    if (holds != "number" && holds != "whole number") continue;
    const size_t dot = key.find('.');
    const std::string name = dot == std::string::npos ? key : key.substr(dot + 1);
    auto at = [&](double v) {
      std::ostringstream value;
      value.precision(17);
      value << v;
      return dot == std::string::npos
                 ? "return { " + name + " = " + value.str() + " }"
                 : "return { " + key.substr(0, dot) + " = { " + name + " = " + value.str() + " } }";
    };
    for (const double outside : {k.low - 1, k.high + 1})
      EXPECT_NE(manifestError(at(outside)).find("'" + name + "' must be within"), std::string::npos)
          << key << " = " << outside << ": " << manifestError(at(outside));
    EXPECT_EQ(manifestError(at(k.high)), "") << key;
  }
  // The docs' table, row by row.
  std::ifstream in(std::string(PLATON_SOURCE_ROOT) + "/docs/scripting.md");
  std::vector<std::string> rows;
  bool inScene = false;
  for (std::string line; std::getline(in, line);) {
    if (line == "## A scene")
      inScene = true;
    else if (inScene && line.rfind("## ", 0) == 0)
      break;
    if (inScene && line.rfind("| `", 0) == 0) rows.push_back(line);
  }
  ASSERT_EQ(rows.size(), core::manifestKeys().size());
  for (size_t i = 0; i < rows.size(); ++i) {
    const core::ManifestKey& k = core::manifestKeys()[i];
    const std::string holds = k.holds;
    std::ostringstream range;
    if (holds == "number" || holds == "whole number")
      range << k.low << ".." << std::fixed << std::setprecision(0) << k.high;
    EXPECT_EQ(rows[i], "| `" + std::string(k.key) + "` | " + holds + " | " + (range.str().empty() ? "-" : range.str()) +
                           " | " + k.shown + " | " + k.does + " |");
  }
}

TEST(Manifest, ErrorsNameFileLineColumn) {
  EXPECT_EQ(manifestError("return {\n  name = 'x',\n  gravity = os.time(),\n}"),
            "scene.lua:3:13: 'os': a data file holds only strings, numbers, booleans, nil and tables (no names, "
            "calls or expressions)");
  EXPECT_EQ(manifestError("return { stage = { solid = 'torus' } }"),
            "scene.lua:1:28: unknown solid 'torus' (known: tetrahedron, cube, octahedron, dodecahedron, icosahedron)");
  EXPECT_EQ(manifestError("return { systems = { 'scripting' }, scripts = { level = '../../etc/passwd.lua' } }"),
            "scene.lua:1:57: '../../etc/passwd.lua': a script is a .lua path inside the scene's folder or under "
            "scripts/ (no '..', not absolute)");
  EXPECT_EQ(manifestError("return { scripts = { level = 'level.lua' } }"),
            "scene.lua:1:20: the scene has scripts but does not list \"scripting\" in its systems");
  EXPECT_EQ(manifestError("return { name = 'a', name = 'b' }"),
            "scene.lua:1:22: the key 'name' is given twice in one table");
  EXPECT_EQ(manifestError("return { gravity = 1e999 }"), "scene.lua:1:20: '1e999' is too large for a number");
  EXPECT_EQ(manifestError("return { colour = 3 }").substr(0, 40), "scene.lua:1:10: unknown field 'colour' (");
  EXPECT_EQ(manifestError("return { name = 'x'"), "scene.lua:1:8: unfinished table (no '}' for this '{')");
  EXPECT_EQ(manifestError("return { name = 'unfinished }"), "scene.lua:1:17: unfinished string");
}

// The audit's gaps: fractions where whole numbers are meant, mods that are not .lua paths in a
// list, ranges shown with six zeros; and Lua's long brackets, which a table literal may use.
TEST(Manifest, WholeNumbersModsAndLongBrackets) {
  EXPECT_EQ(manifestError("return { stage = { solid = 'cube', edge = 4096.7 } }"),
            "scene.lua:1:43: 'edge' must be a whole number, not 4096.7");
  EXPECT_EQ(manifestError("return { seed = 1.5 }"), "scene.lua:1:17: 'seed' must be a whole number, not 1.5");
  EXPECT_EQ(manifestError("return { gravity = -1 }"), "scene.lua:1:20: 'gravity' must be within [0, 1000], not -1");
  const std::string mod = "return { systems = { 'scripting' }, scripts = { mods = { ";
  EXPECT_EQ(manifestError(mod + "'/etc/passwd' } } }"),
            "scene.lua:1:58: '/etc/passwd': a mod is a .lua path inside the scene's folder (no '..', not absolute, not "
            "under scripts/)");
  EXPECT_EQ(manifestError(mod + "'cube_intro.level' } } }").substr(0, 55),
            "scene.lua:1:58: 'cube_intro.level': a mod is a .lua pat");
  EXPECT_EQ(
      manifestError(mod + "'scripts/player.lua' } } }").rfind("scene.lua:1:58: 'scripts/player.lua': a mod is", 0), 0u);
  EXPECT_EQ(manifestError(mod + "'' } } }").substr(0, 50), "scene.lua:1:58: '': a mod is a .lua path inside th");
  EXPECT_EQ(manifestError(mod + "5 } } }").substr(0, 46), "scene.lua:1:58: a mod is a .lua path inside th");
  EXPECT_EQ(manifestError(mod + "a = 'level.lua' } } }"),
            "scene.lua:1:62: 'mods' must be a list of paths ({ \"a.lua\", \"b.lua\" }), not keyed");
  Folder folder("manifest_long");
  const core::SceneManifest m = core::loadManifest(folder.write(
      "scene.lua",
      "--[==[ a long comment\n with ]] inside ]==]\nreturn { name = [[Two\nlines]], --[[ short ]] seed = 3 }\n"));
  EXPECT_EQ(m.name, "Two\nlines");
  EXPECT_EQ(m.seed, 3u);
  EXPECT_EQ(manifestError("return { name = [==[ never closed ] }").substr(0, 56),
            "scene.lua:1:17: unfinished long string (no ]==])");
}

TEST(Manifest, AcceptsCommentsAndListsSystems) {
  Folder folder("manifest_ok");
  const std::string path =
      folder.write("scene.lua",
                   "-- a comment\nreturn {\n  name = \"A\", --[[ block ]] systems = { 'scripting', "
                   "'rendering' },\n  scripts = { player = 'scripts/player.lua', level = 'l.lua' },\n}\n");
  const core::SceneManifest m = core::loadManifest(path);
  EXPECT_EQ(m.name, "A");
  EXPECT_TRUE(m.needs("scripting"));
  EXPECT_TRUE(m.needs("rendering"));
  EXPECT_FALSE(m.needs("meshes"));
  EXPECT_EQ(m.player, "scripts/player.lua");
  EXPECT_EQ(m.level, m.directory + "/l.lua");
}

// preset = "game" fills in the game's rules, player and progression; a script the manifest names
// itself wins; an unknown preset is an error at its place.
TEST(Manifest, TheGamePresetFillsInWhatIsNotNamed) {
  Folder folder("manifest_preset");
  const core::SceneManifest m = core::loadManifest(folder.write(
      "scene.lua", "return { systems = { 'scripting' }, scripts = { preset = 'game', player = 'my_player.lua' } }"));
  EXPECT_EQ(m.rules, "scripts/rules/game.lua");
  EXPECT_EQ(m.progression, "scripts/progression.lua");
  EXPECT_EQ(m.player, m.directory + "/my_player.lua");
  EXPECT_EQ(manifestError("return { systems = { 'scripting' }, scripts = { preset = 'arcade' } }"),
            "scene.lua:1:58: unknown script preset (known: \"game\")");
  EXPECT_EQ(manifestError("return { scripts = { preset = 'game' } }"),
            "scene.lua:1:20: the scene has scripts but does not list \"scripting\" in its systems");
}

TEST(Systems, ASceneWithoutScriptsCreatesNoLuaState) {
  Folder folder("no_scripts");
  const std::string path = folder.write("scene.lua", "return { name = 'bare', stage = { solid = 'cube' } }");
  int created = 0;
  core::SystemRegistry registry;
  registry.add("scripting", [&](core::Scene& scene) {
    ++created;
    return makeScriptSystem(scene);
  });
  const auto scene = core::loadScene(path, registry);
  EXPECT_EQ(created, 0);
  EXPECT_EQ(scene->systemCount(), 0u);
  for (int i = 0; i < 60; ++i) scene->step({});
  EXPECT_EQ(created, 0);
}

TEST(Systems, AHeadlessScenarioMapsNoGraphicsOrMeshLibraries) {
  const ScenarioResult r = runScenario(std::string(PLATON_SOURCE_ROOT) + "/tests/scenarios/cube_intro_walk.lua");
  ASSERT_TRUE(r.passed) << r.message;
  for (const char* library : {"libGL", "libEGL", "libSDL2", "libassimp", "libGLX"})
    EXPECT_FALSE(testing::mapped(library)) << library << " is mapped in a headless run";
}

// A process that plays a mesh level maps assimp (through the plugin); one that plays a Platonic
// level does not (Systems.AHeadlessScenarioMapsNoGraphicsOrMeshLibraries). Each in a fresh process.
bool mapsAssimpAfter(const std::string& scenario) {
  script::RunOptions options;
  options.pluginFolders = {PLATON_PLUGIN_DIR};
  const script::ScenarioResult r = script::runScenario(scenario, options);
  if (!r.passed) {
    std::fprintf(stderr, "%s\n", r.message.c_str());
    std::exit(2);
  }
  return testing::mapped("libassimp");
}

TEST(MeshPlugin, LoadedOnlyForAMeshLevel) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const std::string root = PLATON_SOURCE_ROOT;
  EXPECT_EXIT(std::exit(mapsAssimpAfter(root + "/tests/scenarios/prism_walk.lua") ? 0 : 1),
              ::testing::ExitedWithCode(0), "");
  EXPECT_EXIT(std::exit(mapsAssimpAfter(root + "/tests/scenarios/cube_intro_walk.lua") ? 0 : 1),
              ::testing::ExitedWithCode(1), "");
}

// A level folder with a manifest whose rules, player or level scripts are the test's.
std::string levelWith(const Folder& folder, const std::string& levelScript, const std::string& rules = "") {
  folder.write("level.lua", levelScript);
  if (!rules.empty()) folder.write("rules.lua", rules);
  return folder.write("scene.lua",
                      "return { systems = { 'scripting' }, gravity = 0.35, scripts = { player = "
                      "'scripts/player.lua', progression = 'scripts/progression.lua', level = 'level.lua', "
                      "rules = " +
                          std::string(rules.empty() ? "'scripts/rules/game.lua'" : "'rules.lua'") + " } }");
}

const char* kFloorLevel =
    "local level = { start = { face = 0, x = 600, y = 700 } }\n"
    "function level.build(game) for i = 1, game.world.faceCount() do game.world.line(game.world.face(i), 0, 512, 4096, "
    "512) end end\n"
    "return level\n";

std::string scenarioFor(const Folder& folder, const std::string& scene, const std::string& body) {
  // Named from the scenario's folder: a scenario names no absolute path.
  const std::string named = std::filesystem::path(scene)
                                .lexically_relative(std::filesystem::path(folder.path()).parent_path())
                                .generic_string();
  return folder.write("scenario.lua", "return { scene = '" + named + "', " + body + " }");
}

TEST(Scripts, AnErrorInARuleCallbackNamesItsLineAndTheWorldStaysWhole) {
  Folder folder("rule_error");
  const std::string scene = levelWith(folder, kFloorLevel,
                                      "local game = ...\nlocal rules = {}\nfunction rules.contact(e, tag)\n"
                                      "  error('rule broke on tag ' .. tag)\nend\nreturn rules\n");
  const ScenarioResult r = runScenario(scenarioFor(folder, scene, "frames = 120"));
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.message.find("rules.lua:4: rule broke on tag 0"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("stack traceback:"), std::string::npos) << r.message;
}

TEST(Scripts, AStaleEntityHandleIsALuaError) {
  Folder folder("stale");
  const std::string scene = levelWith(folder,
                                      "local level = { start = { face = 0, x = 600, y = 700 } }\n"
                                      "function level.tick(game, frame)\n"
                                      "  if frame == 2 then\n"
                                      "    local e = game.world.createEntity { circle = 10 }\n"
                                      "    game.world.destroyEntity(e)\n"
                                      "    game.world.velocity(e)\n"
                                      "  end\n"
                                      "end\nreturn level\n");
  const ScenarioResult r = runScenario(scenarioFor(folder, scene, "frames = 10"));
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.message.find("level.lua:6: argument 1: stale entity handle"), std::string::npos) << r.message;
}

TEST(Scripts, WrongTypesAndRangesAreLuaErrors) {
  Folder folder("types");
  const std::string scene = levelWith(folder,
                                      "local level = { start = { face = 0, x = 600, y = 700 } }\n"
                                      "function level.tick(game, frame)\n"
                                      "  game.world.line(0, 'a', 0, 1, 1)\n"
                                      "end\nreturn level\n");
  const ScenarioResult r = runScenario(scenarioFor(folder, scene, "frames = 10"));
  EXPECT_NE(r.message.find("level.lua:3: argument 2: expected a number, got \"a\""), std::string::npos) << r.message;
  const std::string scene2 = levelWith(folder,
                                       "local level = { start = { face = 0, x = 600, y = 700 } }\n"
                                       "function level.tick(game, frame)\n"
                                       "  game.world.line(0, 0.5, 0, 1, 1)\n"
                                       "end\nreturn level\n");
  const ScenarioResult r2 = runScenario(scenarioFor(folder, scene2, "frames = 10"));
  EXPECT_NE(r2.message.find("level.lua:3: argument 2: expected an integer in [-2147483648, 2147483647]"),
            std::string::npos)
      << r2.message;
}

TEST(Scripts, ALevelScriptCannotReachTheMachine) {
  Folder folder("escape");
  const std::string scene = levelWith(folder, "io.open('/tmp/platon_pwned', 'w')\nreturn {}\n");
  const ScenarioResult r = runScenario(scenarioFor(folder, scene, "frames = 1"));
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.message.find("level.lua:1: attempt to index global 'io' (a nil value)"), std::string::npos) << r.message;
  EXPECT_FALSE(fs::exists("/tmp/platon_pwned"));
}

TEST(Scenarios, AHazardKillsAndTheGoalWins) {
  Folder folder("hazard");
  const std::string scene = levelWith(folder,
                                      "local level = { start = { face = 0, x = 600, y = 700 } }\n"
                                      "function level.build(game)\n"
                                      "  local w = game.world\n"
                                      "  w.line(0, 0, 512, 4096, 512)\n"
                                      "  w.line(0, 1500, 512, 1500, 600, 1)\n"   // a low hazard post on the floor
                                      "  w.line(0, 3000, 520, 3000, 3000, 2)\n"  // the goal beyond it
                                      "end\nreturn level\n");
  // Walking right runs into the hazard: one death, back at the start, no goal.
  const ScenarioResult dies = runScenario(scenarioFor(
      folder, scene, "frames = 200, input = { { hold = 'right', from = 1, to = 200 } }, expect = { deaths = 1 }"));
  EXPECT_TRUE(dies.passed) << dies.message;
  // Jumping over it reaches the goal.
  const ScenarioResult wins = runScenario(scenarioFor(
      folder, scene,
      "frames = 600, input = { { hold = 'right', from = 1, to = 600 }, { press = 'jump', at = 85, frames = 30 } },"
      " expect = { goal_by = 600, deaths = 0 }"));
  EXPECT_TRUE(wins.passed) << wins.message;
}

TEST(Scenarios, FailWhenTheirExpectationsDoNotHold) {
  const std::string walk = std::string(PLATON_SOURCE_ROOT) + "/tests/scenarios/cube_intro_walk.lua";
  Folder folder("expect");
  const std::string scene = folder.path("levels/cube_intro/scene.lua");  // read from the game's data folder
  const ScenarioResult early = runScenario(scenarioFor(
      folder, scene, "frames = 400, input = { { hold = 'right', from = 1, to = 400 } }, expect = { goal_by = 100 }"));
  EXPECT_FALSE(early.passed);
  EXPECT_NE(early.message.find("goal not reached by frame 100"), std::string::npos) << early.message;
  const ScenarioResult hash =
      runScenario(scenarioFor(folder, scene, "frames = 10, expect = { hash = { [5] = '0000' } }"));
  EXPECT_FALSE(hash.passed);
  EXPECT_NE(hash.message.find("frame 5: state hash"), std::string::npos) << hash.message;
  const ScenarioResult face = runScenario(scenarioFor(folder, scene, "frames = 10, expect = { face = { [5] = 3 } }"));
  EXPECT_NE(face.message.find("frame 5: player on face 0, expected face 3"), std::string::npos) << face.message;
  const ScenarioResult bad =
      runScenario(scenarioFor(folder, scene, "frames = 10, input = { { hold = 'fly', from = 1, to = 2 } }"));
  EXPECT_NE(bad.message.find("input[1].hold: no action 'fly' in this scene"), std::string::npos) << bad.message;
}

TEST(Scenarios, TheSameRunGivesTheSameHash) {
  const std::string walk = std::string(PLATON_SOURCE_ROOT) + "/tests/scenarios/cube_intro_walk.lua";
  const ScenarioResult a = runScenario(walk), b = runScenario(walk);
  ASSERT_TRUE(a.passed) << a.message;
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_EQ(a.frames, b.frames);
}

}  // namespace
}  // namespace platon::script
