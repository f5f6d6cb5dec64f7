// Replay files: every malformed input is an error at file:line:column, and any input survives a
// write and a read unchanged.
#include "platon/core/replay.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

#include <gtest/gtest.h>

#include "platon/core/input.h"
#include "platon/testing/rng.h"

namespace platon::core {
namespace {

std::string errorOf(const std::string& text) {
  try {
    parseReplay(text, "run.replay");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(accepted)";
}

const std::string kHeader = "platon replay 1\nscene \"levels/a/scene.lua\"\nframes 10\nhash_every 5\ninput\n";

TEST(Replay, MalformedInputsNamePositionAndReason) {
  struct Case {
    std::string text, error;
  };
  const Case cases[] = {
      {"", "run.replay:1:1: an empty file, not a replay: missing 'platon replay 1' (at the end of the file)"},
      {"\xEF\xBB\xBFplaton replay 1\n", "run.replay:1:1: not a replay: the file starts with a byte-order mark"},
      {"platon movie 1\n", "run.replay:1:1: not a replay: the first line is 'platon replay 1'"},
      {"platon replay 7\n", "run.replay:1:15: replay version 7 is not supported (this engine reads 1)"},
      {"platon replay 1\nscene \"levels\n", "run.replay:2:7: unfinished string"},
      {"platon replay 1\nscene levels\n", "run.replay:2:7: the scene path is written in double quotes"},
      {"platon replay 1\nstage \"x\"\n", "run.replay:2:1: expected 'scene \"path\"', got 'stage'"},
      {"platon replay 1\nscene \"\"\n", "run.replay:2:7: empty scene path"},
      {"platon replay 1\nscene \"a\"\nframes ten\n", "run.replay:3:8: frames: expected a whole number, got 'ten'"},
      {"platon replay 1\nscene \"a\"\nframes -3\n", "run.replay:3:8: frames: expected a whole number, got '-3'"},
      {"platon replay 1\nscene \"a\"\nframes 99999999999\n",
       "run.replay:3:8: frames 99999999999 is more than 33554432"},
      // More than 2^64: no bare conversion error, the same message with its place.
      {"platon replay 1\nscene \"a\"\nframes 99999999999999999999\n",
       "run.replay:3:8: frames 99999999999999999999 is more than 33554432"},
      {"platon replay 1\nscene \"a\"\nframes 123456789012345678901234567890\n",
       "run.replay:3:8: frames 123456789012345678901234567890 is more"},
      {"platon replay 1\nscene \"a\"\nscene_files 12\n",
       "run.replay:3:13: the scene files' hash is 16 lower-case hex digits"},
      {"platon replay 1\nscene \"a\"\nspeed 49\n", "run.replay:3:7: speed: the game runs at 50 to 100 percent, not 49"},
      {"platon replay 1\nscene \"a\"\nspeed 101\n", "run.replay:3:7: speed 101 is more than 100"},
      {"platon replay 1\nscene \"a\"\nspeed\n", "run.replay:3:1: expected 'speed PERCENT'"},
      {"platon replay 1\nscene \"a\"\nstart 0 5\n", "run.replay:3:9: expected 'start FACE X Y'"},
      {"platon replay 1\nscene \"a\"\nstart -1 5 5\n", "run.replay:3:7: start face: expected a whole number"},
      {"platon replay 1\nscene \"a\"\nstart 0 5 x\n", "run.replay:3:11: start y: expected a whole number, got 'x'"},
      {"platon replay 1\nscene \"a\"\nstart 0 -999999999 5\n", "run.replay:3:9: start x 999999999 is more than"},
      {kHeader + "10 left left\nend\n", "run.replay:6:9: 'left' is given twice"},
      {kHeader + "10 -\nend\nhash 0 0123456789abcdef\n", "run.replay:8:6: hash frame 0: frames count from 1"},
      // The hashes hash_every implies are all there or none: a stripped or tampered file is refused.
      {kHeader + "10 -\nend\nhash 10 0123456789abcdef\n", "run.replay:8:6: hash_every 5 implies a hash at frame 5"},
      {kHeader + "10 -\nend\nhash 5 0123456789abcdef\n", "run.replay:8:1: hash_every 5 implies a hash at frame 10"},
      {kHeader + "10 -\nend\nhash 5 0123456789abcdef\nhash 7 0123456789abcdef\n",
       "run.replay:9:6: hash_every 5 implies no hash at frame 7"},
      {kHeader + "10 left\n", "missing 'end' (at the end of the file)"},
      {kHeader + "10 l-f\nend\n",
       "run.replay:6:4: 'l-f' is no action (left, right, up, down, jump, restart, pause, "
       "reload, an action a mod adds, or - for none)"},
      {kHeader + "0 -\nend\n", "run.replay:6:1: a run of 0 frames"},
      {kHeader + "4\nend\n", "run.replay:6:1: expected 'count buttons...'"},
      {kHeader + "4 -\nend\n", "run.replay:7:1: the input covers 4 frames, 'frames' says 10"},
      {kHeader + "11 -\nend\n", "run.replay:6:1: the input runs past frame 10"},
      {kHeader + "10 - left\nend\n", "run.replay:6:4: '-' is no action"},
      {kHeader + "10 -\nend\nhash 5 12\n", "run.replay:8:8: a hash is 16 lower-case hex digits"},
      {kHeader + "10 -\nend\nhash 11 0123456789abcdef\n", "run.replay:8:6: hash frame 11 is more than 10"},
      {kHeader + "10 -\nend\nhash 5 0123456789abcdef\nhash 5 0123456789abcdef\nhash 10 0123456789abcdef\n",
       "run.replay:9:6: hash frames must increase"},
      {kHeader + "10 -\nend\nhash 5\n", "run.replay:8:6: expected 'hash FRAME HEX16'"},
      {kHeader + "10 -\nend\nnoise\n", "run.replay:8:1: expected 'hash FRAME HEX16', got 'noise'"},
  };
  for (const Case& c : cases) {
    const std::string error = errorOf(c.text);
    EXPECT_NE(error.find(c.error), std::string::npos) << "input:\n" << c.text << "\nerror: " << error;
  }
}

// An action the engine does not have is a mod's, by name: it takes the file's next bit, and the
// scene it plays must have it (its bit there may differ); one it lacks is said where it was written.
TEST(Replay, AModsActionIsReadByNameAndMatchedToTheScenesByName) {
  const Replay r = parseReplay(kHeader + "4 glide\n3 dash right\n3 -\nend\n", "run.replay");
  ASSERT_EQ(r.actions.names.size(), 10u);
  EXPECT_EQ(r.actions.names[8], "glide");
  EXPECT_EQ(r.actions.names[9], "dash");
  EXPECT_EQ(r.held[4], (1u << 9) | InputFrame::bit(Button::Right));
  std::vector<Action> scene = engineActions();
  addAction(scene, {"dash", "Dash", {"X"}, {}, "", true, "dash.lua"});
  addAction(scene, {"glide", "Glide", {"G"}, {}, "", true, "glide.lua"});
  const ActionMap map(r.actions, scene);
  EXPECT_EQ(map(r.held[0]), 1u << 9);  // glide is the scene's 10th
  EXPECT_EQ(map(r.held[4]), (1u << 8) | InputFrame::bit(Button::Right));
  EXPECT_EQ(formatReplay(parseReplay(formatReplay(r), "again")), formatReplay(r));
  try {
    const ActionMap none(r.actions, engineActions());
    ADD_FAILURE() << "a scene without glide played it";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(),
                 "run.replay:6:3: no action 'glide' in this scene (its actions: left, right, up, down, jump, restart, "
                 "pause, reload)");
  }
}

TEST(Replay, CommentsBlankLinesAndNoInput) {
  const Replay r = parseReplay(
      "# a run\n\nplaton replay 1\n  scene \"s.lua\"\nframes 3\nhash_every 0\ninput\n# none\n3 -\nend\n", "x.replay");
  EXPECT_EQ(r.scene, "s.lua");
  EXPECT_EQ(r.held, (std::vector<Buttons>{0, 0, 0}));
  EXPECT_TRUE(r.hashes.empty());
}

TEST(Replay, AControlByteInTheFileIsShownNotCutShort) {
  const std::string error = errorOf(kHeader + "10 ri" + std::string(1, '\0') + "ght\nend\n");
  EXPECT_NE(error.find("run.replay:6:4: 'ri\\x00ght' is no action"), std::string::npos) << error;
}

TEST(Replay, ACommentRunsFromAHashToTheEndOfTheLine) {
  const Replay r = parseReplay(
      "platon replay 1  # a run\nscene \"a#b.lua\"\nframes 3 # three\nhash_every 0\ninput\n"
      "3 right # all the way\nend # done\nhash 3 0123456789abcdef # the last\n",
      "x.replay");
  EXPECT_EQ(r.scene, "a#b.lua");  // not inside quotes
  EXPECT_EQ(r.held, std::vector<Buttons>(3, InputFrame::bit(Button::Right)));
  ASSERT_EQ(r.hashes.size(), 1u);
  EXPECT_EQ(r.hashes[0].frame, 3u);
}

TEST(Replay, AllHashesOrNone) {
  // No hashes at all is an input-only file: it reads (and replays without checking anything).
  const Replay none = parseReplay(kHeader + "10 -\nend\n", "x.replay");
  EXPECT_TRUE(none.hashes.empty());
  const Replay all =
      parseReplay(kHeader + "10 -\nend\nhash 5 0123456789abcdef\nhash 10 0123456789abcdef\n", "x.replay");
  EXPECT_EQ(all.hashes.size(), 2u);
  // hash_every 4 over 10 frames: 4, 8 and the last.
  const std::string odd = "platon replay 1\nscene \"a\"\nframes 10\nhash_every 4\ninput\n10 -\nend\n";
  EXPECT_EQ(
      parseReplay(odd + "hash 4 0123456789abcdef\nhash 8 0123456789abcdef\nhash 10 0123456789abcdef\n", "x.replay")
          .hashes.size(),
      3u);
  EXPECT_NE(errorOf(odd + "hash 4 0123456789abcdef\nhash 10 0123456789abcdef\n").find("implies a hash at frame 8"),
            std::string::npos);
}

// The assist mode's speed: optional (100 when absent, and then not written), kept through a write.
TEST(Replay, TheSpeedIsOptionalAndSurvivesWriteAndRead) {
  EXPECT_EQ(parseReplay(kHeader + "10 -\nend\n", "old.replay").speed, 100);
  ReplayRecorder recorder("levels/a/scene.lua", 5, 0x0123456789abcdefull);
  for (int f = 0; f < 10; ++f) recorder.frame(0, 7);
  EXPECT_EQ(formatReplay(recorder.replay()).find("speed"), std::string::npos);
  recorder.setSpeed(70);
  const std::string text = formatReplay(recorder.replay());
  EXPECT_NE(text.find("scene_files 0123456789abcdef\nspeed 70\nframes 10\n"), std::string::npos) << text;
  EXPECT_EQ(parseReplay(text, "slow.replay").speed, 70);
}

// Where a run starts when not at its level's start (a play-test from the editor's cursor): optional,
// signed, kept through a write, after the speed.
TEST(Replay, TheStartIsOptionalAndSurvivesWriteAndRead) {
  EXPECT_FALSE(parseReplay(kHeader + "10 -\nend\n", "old.replay").start);
  ReplayRecorder recorder("levels/a/scene.lua", 5);
  for (int f = 0; f < 10; ++f) recorder.frame(0, 7);
  EXPECT_EQ(formatReplay(recorder.replay()).find("start"), std::string::npos);
  recorder.setSpeed(80);
  recorder.setStart(ReplayStart{4, -812, 3000});
  const std::string text = formatReplay(recorder.replay());
  EXPECT_NE(text.find("speed 80\nstart 4 -812 3000\nframes 10\n"), std::string::npos) << text;
  EXPECT_EQ(parseReplay(text, "there.replay").start, (ReplayStart{4, -812, 3000}));
}

// The console's lines (docs/scripting.md, "Console"): any code, quotes, backslashes and line
// breaks included, reads back as written, each before its frame; what is not one is refused where
// it is.
TEST(Replay, ConsoleLinesSurviveWriteAndReadAndBadOnesAreRefusedWhereTheyAre) {  // NOLINT(readability-function-size)
  ReplayRecorder recorder("levels/a/scene.lua", 5);
  const std::vector<std::string> codes = {"6 * 7", "game.message(\"a \\\"quoted\\\" word\")", "x = '\\n'\nprint(x)", "",
                                          "-- # not a comment to the reader"};
  for (int f = 0; f < 10; ++f) {
    if (f == 3 || f == 7) recorder.console(codes[static_cast<size_t>(f == 3 ? 0 : 1)]);
    recorder.frame(0, 7);
  }
  recorder.console(codes[2]);  // after the last frame: before a frame that never came, so not kept
  Replay r = recorder.replay();
  EXPECT_EQ(r.console.size(), 2u);
  for (const std::string& c : codes) r.console.push_back({10, c});
  const Replay back = parseReplay(formatReplay(r), "c.replay");
  ASSERT_EQ(back.console.size(), r.console.size());
  for (size_t i = 0; i < r.console.size(); ++i) {
    EXPECT_EQ(back.console[i].frame, r.console[i].frame);
    EXPECT_EQ(back.console[i].code, r.console[i].code);
  }
  EXPECT_EQ(back.console[0].frame, 4u);  // typed after frame 3: runs before frame 4
  const std::string body = kHeader + "10 -\nend\n";
  EXPECT_EQ(errorOf(body + "console 0 \"x\"\n"),
            "run.replay:8:9: console frame 0: a line runs before a frame, counted from 1");
  EXPECT_EQ(errorOf(body + "console 5 \"x\"\nconsole 4 \"y\"\n"), "run.replay:9:9: console frames may not decrease");
  EXPECT_EQ(errorOf(body + "console 5 x\n"), "run.replay:8:11: the console's code is written in double quotes");
  EXPECT_EQ(parseReplay(body + "console 5 \"a\\tb\"\n", "r").console[0].code, "a\\tb");  // another backslash is itself
  EXPECT_EQ(errorOf(body + "console 11 \"x\"\n").find("run.replay:8:9:"), 0u);
}

TEST(Replay, TheSceneFilesHashIsOptionalAndSurvivesWriteAndRead) {
  const Replay old = parseReplay(kHeader + "10 -\nend\n", "old.replay");
  EXPECT_FALSE(old.sceneFiles.has_value());  // files from before the line existed still read
  EXPECT_EQ(formatReplay(old).find("scene_files"), std::string::npos);
  ReplayRecorder recorder("levels/a/scene.lua", 5, 0x0123456789abcdefull);
  for (int f = 0; f < 10; ++f) recorder.frame(0, 7);
  const std::string text = formatReplay(recorder.replay());
  EXPECT_NE(text.find("scene \"levels/a/scene.lua\"\nscene_files 0123456789abcdef\nframes 10\n"), std::string::npos)
      << text;
  EXPECT_EQ(parseReplay(text, "new.replay").sceneFiles, 0x0123456789abcdefull);
}

TEST(Replay, TheSceneFilesHashFollowsEveryByteOfEveryFile) {
  const std::string folder = ::testing::TempDir() + "/platon_scene_files_" + std::to_string(getpid());
  std::filesystem::create_directories(folder);
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(folder + "/" + name, std::ios::binary | std::ios::trunc) << text;
    return folder + "/" + name;
  };
  const std::string a = write("a.lua", "return {}"), b = write("b.level", "lines");
  const uint64_t before = sceneFilesHash({a, b});
  EXPECT_EQ(sceneFilesHash({a, b}), before);
  write("b.level", "lineS");
  EXPECT_NE(sceneFilesHash({a, b}), before);
  write("b.level", "lines");
  EXPECT_EQ(sceneFilesHash({a, b}), before);
  write("a.lua", "return {}l"), write("b.level", "ines");  // the same bytes split another way
  EXPECT_NE(sceneFilesHash({a, b}), before);
  write("b.level", "");
  EXPECT_NE(sceneFilesHash({a, b}), sceneFilesHash({a, folder + "/missing"}));  // empty is not missing
  std::filesystem::remove_all(folder);
}

TEST(Replay, RandomRunsSurviveWriteAndRead) {
  testing::Rng rng{17};
  for (int trial = 0; trial < 200; ++trial) {
    ReplayRecorder recorder("levels/x y/scene.lua",
                            rng.between(0, 4) == 0 ? 0 : static_cast<uint64_t>(rng.between(1, 100)));
    const int frames = rng.between(1, 3000);
    Buttons held = 0;
    for (int f = 0; f < frames; ++f) {
      if (rng.between(0, 9) == 0) held = static_cast<Buttons>(rng.between(0, 255));
      recorder.frame(held, rng.next());
    }
    const Replay original = recorder.replay();
    const Replay copy = parseReplay(formatReplay(original), "copy.replay");
    ASSERT_EQ(copy.scene, original.scene);
    ASSERT_EQ(copy.held, original.held);
    ASSERT_EQ(copy.hashEvery, original.hashEvery);
    ASSERT_EQ(copy.hashes.size(), original.hashes.size());
    for (size_t i = 0; i < copy.hashes.size(); ++i) {
      ASSERT_EQ(copy.hashes[i].frame, original.hashes[i].frame);
      ASSERT_EQ(copy.hashes[i].hash, original.hashes[i].hash);
    }
    // The last frame always carries a hash, so a replay checks where it ends.
    ASSERT_EQ(original.hashes.back().frame, original.frames());
  }
}

}  // namespace
}  // namespace platon::core
