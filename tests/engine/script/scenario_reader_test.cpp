// Reading scenario files: every malformed scenario is refused, before anything runs, with the
// scenario's file:line:column, what the value's path is (expect.face[50]) and what was wrong; a
// scenario that computes its values in Lua still reads, with the line of its return. Replays say
// when the scene's files changed since the recording, and `platon scenario` writes any scene path
// so that it reads back as itself.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "platon/core/replay.h"
#include "platon/script/scenario.h"
#include "platon/testing/temp_folder.h"

namespace platon::script {
namespace {

using Folder = testing::TempFolder;

const std::string kScene = "levels/cube_intro/scene.lua";  // from the game's data folder

// A scenario of 100 frames on the first level whose third line is `line`.
std::string scenarioText(const std::string& line, const std::string& frames = "100") {
  return "return {\n  scene = '" + kScene + "', frames = " + frames + ",\n" + line + "\n}\n";
}

// "file:3:C: " where C is the column `token` starts at in `line` (the scenario's third line).
std::string at(const std::string& file, const std::string& line, const std::string& token) {
  const size_t column = line.find(token);
  EXPECT_NE(column, std::string::npos) << token << " not in " << line;
  return file + ":3:" + std::to_string(column + 1) + ": ";
}

struct Case {
  std::string line;   // the scenario's third line
  std::string token;  // where the error points, in that line
  std::string error;  // what it says after file:line:column
};

TEST(ScenarioReader, EveryMalformedValueIsRefusedAtItsLineAndColumn) {
  Folder folder("scenario_reader");
  const std::string file = folder.path("sc.lua");
  const Case cases[] = {
      // C1: values of the wrong kind where a table is read (these killed the whole run).
      {"  input = { 5 },", "5",
       "input[1]: expected { hold = \"button\", from =, to = } or { press = \"button\", at =, frames = }, got 5"},
      {"  expect = { inside = { 5 } },", "5",
       "expect.inside[1]: expected { frame =, face =, box = { x0, y0, x1, y1 } }, got 5"},
      // The console's lines: { at = frame, code = "Lua" }, in the order typed.
      {"  console = { { at = 5 } },", "{ at = 5 }", "console[1]: 'code' is missing"},
      {"  console = { { at = 500, code = 'x = 1' } },", "500", "console[1].at: 500 is outside 1..100"},
      {"  console = { { at = 5, code = 7 } },", "7", "console[1].code: expected the line of Lua (a string), got 7"},
      {"  console = { { at = 9, code = 'a' }, { at = 3, code = 'b' } },", "3",
       "console[2].at: frame 3 is before the line above's, 9 (lines run in the order typed)"},
      {"  console = { { at = 5, code = 'a', when = 1 } },", "when", "console[1]: unknown key 'when' (known: at, code)"},
      // C2: unknown keys, with the known ones.
      {"  expect = { goal_bye = 10 },", "goal_bye",
       "expect: unknown key 'goal_bye' (known: goal_by, deaths, face, inside, hash, sounds, switches, checkpoint)"},
      // Switches and the checkpoint: a list of ids 1..999 once each; { face, x, y } or false.
      {"  expect = { switches = { [50] = 1 } },", "1", "expect.switches[50]: expected a list of switch ids, got 1"},
      {"  expect = { switches = { [50] = { 7, 1000 } } },", "1000", "expect.switches[50][2]: 1000 is outside 1..999"},
      {"  expect = { switches = { [50] = { 2, 2 } } },", "{ 2, 2 }", "expect.switches[50]: a switch id given twice"},
      {"  expect = { switches = { [500] = { 2 } } },", "500", "expect.switches[500] (a frame): 500 is outside 1..100"},
      {"  expect = { checkpoint = { [50] = { 0, 1 } } },", "{ 0, 1 }",
       "expect.checkpoint[50]: expected { face, x, y } (or false: none), got 2 values"},
      {"  expect = { checkpoint = { [50] = true } },", "true",
       "expect.checkpoint[50]: expected a list of face, x, y (or false: none), got true"},
      {"  expect = { checkpoint = { [50] = { 0, 1.5, 2 } } },", "1.5",
       "expect.checkpoint[50][2]: expected a whole number in -1073741823..1073741823, got 1.5"},
      {"  expcet = { goal_by = 10 },", "expcet",
       "scenario: unknown key 'expcet' (known: scene, frames, start, input, console, expect)"},
      // The start: { face, x, y } where the run starts, on the stage and clear of walls.
      {"  start = 5,", "5", "start: expected { face = F, x = X, y = Y }, got 5"},
      {"  start = { face = 0, x = 600 },", "{ face", "start: 'y' is missing"},
      {"  start = { face = 0, x = 600, y = 700, z = 1 },", "z =", "start: unknown key 'z' (known: face, x, y)"},
      {"  start = { face = 0.5, x = 600, y = 700 },", "0.5", "start.face: expected a whole number"},
      {"  start = { face = 0, x = 1e12, y = 700 },", "1e12", "start.x: 1000000000000 is outside -536870912..536870912"},
      {"  start = { face = 9, x = 600, y = 700 },", "{ face",
       "start: the level does not start there: "},  // then the level's own error (start face 9 does not exist)
      {"  start = { face = 0, x = 600, y = 512 },", "{ face", "start: the level does not start there: "},
      {"  framez = 3,", "framez", "scenario: unknown key 'framez'"},
      {"  input = { { hold = 'right', from = 1, too = 5 } },", "too",
       "input[1]: unknown key 'too' (known: hold, from, to)"},
      {"  input = { { press = 'jump', at = 1, frame = 5 } },", "frame",
       "input[1]: unknown key 'frame' (known: press, at, frames)"},
      {"  expect = { inside = { { frame = 5, face = 0, box = { 0, 0, 1, 1 }, fase = 1 } } },", "fase",
       "expect.inside[1]: unknown key 'fase' (known: frame, face, box)"},
      // C3: wrong types, fractions, ranges.
      {"  expect = { goal_by = {} },", "{}", "expect.goal_by: expected a whole number in 1..100, got a table"},
      {"  expect = 5,", "5", "expect: expected a table of checks, got 5"},
      {"  expect = { goal_by = '10' },", "'10'",
       "expect.goal_by: expected a whole number in 1..100, got '10' (a string)"},
      {"  expect = { goal_by = 5000 },", "5000", "expect.goal_by: 5000 is outside 1..100"},
      {"  expect = { face = { [50] = 'three' } },", "'three'",
       "expect.face[50]: expected a whole number in 0..4095, got 'three'"},
      {"  expect = { face = { at50 = 3 } },", "at50",
       "expect.face['at50'] (a frame): expected a whole number in 1..100, got 'at50'"},
      {"  expect = { face = { [0] = 3 } },", "0", "expect.face[0] (a frame): 0 is outside 1..100"},
      {"  expect = { face = { [-1] = 3 } },", "-1", "expect.face[-1] (a frame): -1 is outside 1..100"},
      {"  expect = { face = { [150] = 3 } },", "150", "expect.face[150] (a frame): 150 is outside 1..100"},
      {"  expect = { face = { [50.5] = 3 } },", "50.5",
       "expect.face[50.5] (a frame): expected a whole number in 1..100, got 50.5"},
      {"  expect = { hash = { [150] = '0123456789abcdef' } },", "150",
       "expect.hash[150] (a frame): 150 is outside 1..100"},
      {"  expect = { hash = { [50] = true } },", "true",
       "expect.hash[50]: frame 50: state hash true is not 16 lower-case hex digits"},
      {"  expect = { hash = { [50] = '9E8822E6431FFC25' } },", "'9E",
       "expect.hash[50]: frame 50: state hash '9E8822E6431FFC25' (a string) is not 16 lower-case hex digits"},
      {"  expect = { inside = { { frame = 150, face = 0, box = { 0, 0, 1, 1 } } } },", "150",
       "expect.inside[1].frame: 150 is outside 1..100"},
      {"  expect = { inside = { frame = 50, face = 0, box = { 0, 0, 1, 1 } } },", "frame",
       "expect.inside['frame']: not item 1 of a list"},
      {"  expect = { inside = { { frame = 5, face = 0, box = { 'a', 0, 1, 1 } } } },", "'a'",
       "expect.inside[1].box[1]: expected a whole number in -1073741823..1073741823, got 'a'"},
      {"  expect = { inside = { { frame = 5, face = 0, box = { -1e300, 0, 1, 1 } } } },", "-1e300",
       "expect.inside[1].box[1]: -1.0000000000000001e+300 is outside -1073741823..1073741823"},
      {"  expect = { inside = { { frame = 5, face = 0, box = { 10, 0, 5, 1 } } } },", "{ 10",
       "expect.inside[1].box: an inverted box"},
      {"  expect = { inside = { { frame = 5, face = 0, box = { 1, 2, 3 } } } },", "{ 1, 2",
       "expect.inside[1].box: expected { x0, y0, x1, y1 }"},
      {"  expect = { deaths = 0.5 },", "0.5", "expect.deaths: expected a whole number in 0..2147483647, got 0.5"},
      {"  expect = { deaths = -1 },", "-1", "expect.deaths: -1 is outside 0..2147483647"},
      {"  input = 'right',", "'right'", "input: expected a list of"},
      {"  input = { { hold = 'right', from = 1.5, to = 10 } },", "1.5",
       "input[1].from: expected a whole number in 1..100, got 1.5"},
      {"  input = { { hold = 'right', from = 20, to = 10 } },", "10 }", "input[1].to: frame 10 is before from = 20"},
      {"  input = { { hold = 'right', from = 1, to = 101 } },", "101", "input[1].to: 101 is outside 1..100"},
      {"  input = { { hold = 'right', from = 1 } },", "{ hold", "input[1]: 'to' is missing"},
      {"  input = { { press = 'jump', at = 5, frames = 'x' } },", "'x'", "input[1].frames: expected a whole number"},
      {"  input = { { press = 'jump', at = 5, frames = 0 } },", "0 }", "input[1].frames: 0 is outside 1..100"},
      {"  input = { { press = 'jump', at = 95, frames = 10 } },", "10 }",
       "input[1].frames: the press runs to frame 104, past"},
      {"  input = { { hold = 'right', from = 1, to = 2, press = 'jump', at = 1 } },", "'jump'",
       "input[1]: give hold or press, not both"},
      // A name no scene could have, then one this scene does not have (a mod's, elsewhere).
      {"  input = { { hold = 'f-ly', from = 1, to = 2 } },", "'f-ly'",
       "input[1].hold: unknown action 'f-ly' (left, right, up, down, jump, restart, pause, reload, or one a mod adds)"},
      {"  input = { { press = 'fly', at = 1 } },", "'fly'",
       "input[1].press: no action 'fly' in this scene (its actions: left, right, up, down, jump, restart, pause, "
       "reload)"},
      {"  input = { { hold = 'right', from = 1, to = 2 }, nil, { hold = 'left', from = 1, to = 2 } },", "nil",
       "input[2]: expected { hold"},
      {"  expect = { face = { [50] = 7 } },", "7",
       "expect.face[50]: face 7 does not exist (the stage's faces are 0..5)"},
      {"  expect = { inside = { { frame = 5, face = 9, box = { 0, 0, 1, 1 } } } },", "9",
       "expect.inside[1].face: face 9 does not exist"},
      {"  frames = 50,", "frames", "the key 'frames' is given twice in one table"},
      {"  expect = { sounds = 'jump' },", "'jump'", "expect.sounds: expected { [frame] = \"name\""},
      {"  expect = { sounds = { [200] = 'jump' } },", "200", "expect.sounds[200] (a frame): 200 is outside 1..100"},
      {"  expect = { sounds = { [5] = 7 } },", "7", "expect.sounds[5]: expected a list of sounds' names, got 7"},
      {"  expect = { sounds = { [5] = { 'jump', 3 } } },", "3 }", "expect.sounds[5][2]: expected sounds' names, got 3"},
      {"  expect = { sounds = { [5] = 'jmup' } },", "'jmup'",
       "expect.sounds[5]: the scene's sound bank has no effect 'jmup'"},
      {"  expect = { sounds = { [5] = { 'land', 'jmup' } } },", "'jmup'",
       "expect.sounds[5][2]: the scene's sound bank has no effect 'jmup'"},
      {"  expect = { face = { ['a\\0b'] = 1 } },", "'a", "expect.face['a\\x00b'] (a frame): expected a whole number"},
  };
  for (const Case& c : cases) {
    std::ofstream(file, std::ios::trunc) << scenarioText(c.line);
    const ScenarioResult r = runScenario(file);
    EXPECT_FALSE(r.passed) << c.line;
    EXPECT_EQ(r.frames, 0u) << c.line << ": ran before its plan was checked";
    const std::string expected = at(file, c.line, c.token) + c.error;
    EXPECT_EQ(r.message.substr(0, expected.size()), expected) << c.line;
  }
}

TEST(ScenarioReader, TopLevelFieldsAreChecked) {
  Folder folder("scenario_top");
  struct Top {
    std::string text, error;
  };
  const std::string scene = "scene = '" + kScene + "'";
  const Top cases[] = {
      {"return { " + scene + ", frames = '100' }", "sc.lua:1:"},
      {"return { " + scene + ", frames = 10.5 }", "frames: expected a whole number in 1..33554432, got 10.5"},
      {"return { " + scene + ", frames = 0 }", "frames: 0 is outside 1..33554432"},
      {"return { " + scene + " }", "scenario: 'frames' (how many frames to run) is missing"},
      {"return { frames = 10 }", "sc.lua:1:8: scenario: 'scene' (the manifest's path) is missing"},
      {"return { scene = 5, frames = 10 }", "sc.lua:1:18: scene: expected the manifest's path (a string), got 5"},
      {"return 42", "sc.lua:1:8: scenario: a scenario returns a table, got 42"},
      // Not a literal: the file runs as Lua, and its line of `return` is the position.
      {"return { " + scene + ", frames = 0/0 }", "sc.lua:1: frames: expected a whole number in 1..33554432, got nan"},
      {"local n = 100\nreturn { " + scene + ", frames = n, expect = { goal_bye = 1 } }",
       "sc.lua:2: expect: unknown key 'goal_bye' (known: goal_by, deaths, face, inside, hash, sounds, switches, "
       "checkpoint)"},
      {"local t = {}\nt[1] = t\nreturn { " + scene + ", frames = 10, input = t }",
       "sc.lua:3: tables nested more than 32 deep"},
      {"return { " + scene + ", frames = 10, input = { print } }", "sc.lua:1: input[1]: expected { hold"},
      {"return {\n", "sc.lua:2: unexpected symbol near '<eof>'"},  // Lua's own syntax error
  };
  for (const Top& c : cases) {
    const std::string file = folder.write("sc.lua", c.text);
    const ScenarioResult r = runScenario(file);
    EXPECT_FALSE(r.passed) << c.text;
    EXPECT_NE(r.message.find(c.error), std::string::npos) << c.text << "\n" << r.message;
    EXPECT_EQ(r.message.find("sc.lua:0"), std::string::npos) << r.message;
  }
}

TEST(ScenarioReader, AFolderOrAMissingFileIsNamedAsSuch) {
  Folder folder("scenario_folder");
  const std::string sub = folder.path("sub.lua");
  std::filesystem::create_directories(sub);
  EXPECT_EQ(runScenario(sub).message, sub + ": the scenario: not a regular file (a folder)");
  EXPECT_EQ(runScenario(folder.path("none.lua")).message,
            folder.path("none.lua") + ": the scenario: cannot open it: No such file or directory");
}

TEST(ScenarioReader, AScenarioWithAMetatableIsReadRawAndRuns) {
  Folder folder("scenario_meta");
  const std::string file = folder.write(
      "sc.lua", "return setmetatable({ scene = '" + kScene +
                    "', frames = 10, input = setmetatable({}, { __index = function() error('boom') end }) },\n"
                    "  { __index = function() error('boom') end })\n");
  const ScenarioResult r = runScenario(file);
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_EQ(r.frames, 10u);
}

TEST(ScenarioReader, LiteralsComputedScenariosAndCommentsReadTheSame) {
  Folder folder("scenario_forms");
  const std::string body =
      "scene = '" + kScene +
      "', frames = 200, input = { { hold = 'right', from = 1, to = 200 }, { press = 'jump', at = 50, frames = 20 } },"
      " expect = { deaths = 0, face = { [100] = 0 }, hash = {} }";
  const ScenarioResult literal =
      runScenario(folder.write("a.lua", "-- a comment\n--[==[ a long\n one ]==]\nreturn { " + body + " }\n"));
  const ScenarioResult computed = runScenario(folder.write("b.lua", "local frames = 200\nreturn { " + body + " }\n"));
  ASSERT_TRUE(literal.passed) << literal.message;
  ASSERT_TRUE(computed.passed) << computed.message;
  EXPECT_EQ(literal.hash, computed.hash);
  // Every escape Lua knows reads the same in a literal, \ddd included.
  const ScenarioResult escaped =
      runScenario(folder.write("c.lua", "return { scene = \"" + kScene + "\\116\", frames = 1 }\n"));
  EXPECT_NE(escaped.message.find("c.lua:1:18: scene \"" + kScene + "t\": cannot open it"), std::string::npos)
      << escaped.message;
}

// Scenarios travel with levels (the editor's kept tests, packages), so one that computes its plan
// runs in a sandbox, never as trusted code: every way out of it (files, processes, the library
// loader, bytecode, the FFI, hooks) is refused at its line, and an endless loop is stopped by the
// budget of steps. The marker file is never made.
TEST(ScenarioReader, AComputedScenarioRunsSandboxedWhoeverWroteIt) {
  Folder folder("scenario_sandboxed");
  const std::string marker = folder.path("made_by_the_scenario");
  const std::string escapes[] = {
      "io.open('" + marker + "', 'w'):write('x')",
      "io.popen('touch " + marker + "')",
      "os.execute('touch " + marker + "')",
      "os.remove('" + folder.path("sc.lua") + "')",
      "os.getenv('HOME')",
      "require('ffi')",
      "package.loadlib('libc.so.6', 'system')",
      "dofile('" + folder.path("other.lua") + "')",
      "loadfile('" + folder.path("other.lua") + "')()",
      "load(string.dump(function() end))()",
      "debug.sethook(function() end, '', 1)",
      "jit.off()",
      "collectgarbage('stop')",
      "setfenv(1, {})",
  };
  folder.write("other.lua", "local f = io.open('" + marker + "', 'w') f:write('x') f:close()\n");
  for (const std::string& escape : escapes) {
    SCOPED_TRACE(escape);
    const std::string file =
        folder.write("sc.lua", "local x = 1\n" + escape + "\nreturn { scene = '" + kScene + "', frames = 10 }\n");
    const ScenarioResult r = runScenario(file);
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.message.find("sc.lua:2:"), std::string::npos) << r.message;
    EXPECT_FALSE(std::filesystem::exists(marker));
  }
  // The sandbox's own library still computes a plan: a loop, string and math.
  const ScenarioResult computed = runScenario(folder.write(
      "sc.lua",
      "local input = {}\nfor i = 1, 3 do input[i] = { press = ('JUMP'):lower(), at = 10 * i, frames = 2 } end\n"
      "return { scene = '" +
          kScene + "', frames = math.max(50, 40), input = input }\n"));
  EXPECT_TRUE(computed.passed) << computed.message;
  EXPECT_EQ(computed.frames, 50u);
  // An endless loop is stopped by the budget, at its line.
  const ScenarioResult endless =
      runScenario(folder.write("sc.lua", "local n = 0\nwhile true do n = n + 1 end\nreturn {}\n"));
  EXPECT_FALSE(endless.passed);
  EXPECT_NE(endless.message.find("sc.lua:2:"), std::string::npos) << endless.message;
  EXPECT_NE(endless.message.find("budget"), std::string::npos) << endless.message;
}

// D4: a replay records a hash of its scene's files, and says when they changed.
TEST(ScenarioReplay, AChangedSceneIsNamedBeforeTheFirstHashMismatch) {
  Folder folder("replay_scene_files");
  const std::string source = std::string(PLATON_SOURCE_ROOT) + "/levels/cube_intro/";
  auto copy = [&](const std::string& name) {
    std::ifstream in(source + name, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return folder.write(name, text.str());
  };
  const std::string scene = copy("scene.lua");
  const std::string level = copy("cube_intro.level");
  copy("level.lua");
  RunOptions record;
  record.record = true;
  const ScenarioResult walk =
      runScenario(folder.write("walk.lua", "return { scene = '" + std::string("scene.lua") +
                                               "', frames = 120, input = { { hold = 'right', from = 1, to = 120 } } }"),
                  record);
  ASSERT_TRUE(walk.passed) << walk.message;
  ASSERT_TRUE(walk.recorded && walk.recorded->sceneFiles.has_value());
  const std::string replay = folder.path("walk.replay");
  core::writeReplay(*walk.recorded, replay);
  core::Replay old = *walk.recorded;
  old.sceneFiles.reset();
  const std::string oldReplay = folder.path("old.replay");
  core::writeReplay(old, oldReplay);
  EXPECT_TRUE(runReplay(replay).passed);

  // The floor of face 0 moves down by 8 units: the player falls longer, from the first frames.
  std::ifstream in(level, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  std::string edited = text.str();
  const size_t floor = edited.find("256 512 4096 512");
  ASSERT_NE(floor, std::string::npos) << "cube_intro.level changed: pick another line to move";
  folder.write("cube_intro.level", edited.replace(floor, 16, "256 504 4096 504"));
  const ScenarioResult changed = runReplay(replay);
  EXPECT_FALSE(changed.passed);
  EXPECT_EQ(changed.message.find("the scene's files changed since the recording"), 0u) << changed.message;
  EXPECT_NE(changed.message.find("state hash"), std::string::npos) << changed.message;
  // A replay from before the line existed reads, and says only what it knows.
  const ScenarioResult unknown = runReplay(oldReplay);
  EXPECT_FALSE(unknown.passed);
  EXPECT_EQ(unknown.message.find("the scene's files changed"), std::string::npos) << unknown.message;
  EXPECT_NE(unknown.message.find("state hash"), std::string::npos) << unknown.message;
}

TEST(ScenarioReplay, AReplayWithoutHashesSaysItComparedNothing) {
  Folder folder("replay_no_hashes");
  const std::string file = folder.write(
      "a.replay", "platon replay 1\nscene \"" + kScene + "\"\nframes 10\nhash_every 60\ninput\n10 right\nend\n");
  const ScenarioResult r = runReplay(file);
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_NE(r.message.find("the replay has no hashes: its input ran, nothing was compared"), std::string::npos)
      << r.message;
}

// G: `platon scenario` writes the scene path so that it reads back as itself.
TEST(ScenarioReplay, AScenarioFromAReplayQuotesItsScenePath) {
  Folder folder("scenario_quoting");
  core::Replay replay;
  replay.scene = "odd\\path \"quoted\"\n\x01/scene.lua";
  replay.held.assign(5, 0);
  ScenarioResult outcome;
  outcome.frames = 5;
  const std::string text = scenarioFromReplay(replay, outcome, "a\nb.replay");
  EXPECT_EQ(text.find("a\nb"), std::string::npos) << "the name broke out of the comment";
  const ScenarioResult r = runScenario(folder.write("sc.lua", text));
  EXPECT_NE(r.message.find("scene \"" + replay.scene + "\": cannot open it"), std::string::npos) << text << "\n"
                                                                                                 << r.message;
}

}  // namespace
}  // namespace platon::script
