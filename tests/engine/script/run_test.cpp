// core::Run (core/run.h), the one sequence every way of playing drives: a frame's buttons and their
// presses, the console's lines between frames, and the recording of both. Played live, played on a
// plain scene, recorded and played back from the recording: the same frames, the same state.
#include "platon/core/run.h"

#include <gtest/gtest.h>

#include "platon/core/live_scene.h"
#include "platon/script/script_system.h"
#include "platon/testing/temp_folder.h"

namespace platon::core {
namespace {

// A level where the console can push the player: what a typed line does shows in the state hash.
struct PushLevel {
  testing::TempFolder folder{"run"};
  SystemRegistry registry;
  std::string scene;
  PushLevel() {
    registry.add("scripting", script::makeScriptSystem);
    folder.write("level.lua",
                 "local level = { start = { face = 0, x = 600, y = 700 } }\n"
                 "function level.build(game) game.world.line(game.world.face(1), 0, 512, 4096, 512) end\n"
                 "return level\n");
    scene = folder.write("scene.lua",
                         "return { systems = { 'scripting' }, scripts = { preset = 'game', level = 'level.lua' } }\n");
  }
};

// Buttons over 240 frames (right, a jump pressed twice, left) and three console lines.
core::Buttons buttons(uint64_t frame) {
  const core::Buttons right = InputFrame::bit(Button::Right), left = InputFrame::bit(Button::Left);
  const core::Buttons jump = InputFrame::bit(Button::Jump);
  if (frame < 60) return right;
  if (frame < 70 || (frame >= 90 && frame < 95)) return static_cast<core::Buttons>(right | jump);
  if (frame < 150) return right;
  return left;
}
const std::pair<uint64_t, const char*> kTyped[] = {{30, "game.world.setVelocity(game.player(), 0, -12)"},
                                                   {30, "pushed = (pushed or 0) + 1"},
                                                   {120, "game.world.setVelocity(game.player(), 20, 0)"}};

// Plays the input through `run`, typing the lines before the frames they name; the final hash.
uint64_t play(core::Run& run) {
  for (uint64_t f = 1; f <= 240; ++f) {
    for (const auto& [at, code] : kTyped)
      if (at == f) {
        EXPECT_TRUE(run.console(code).value().ok) << code;
      }
    run.step(buttons(f - 1));
  }
  return run.scene().world().stateHash();
}

TEST(Run, EveryWayOfPlayingGivesTheSameFrames) {
  PushLevel level;
  LiveScene live(level.scene, level.registry, false);
  core::Run recorded(live);
  recorded.record({"scene.lua", 1, std::nullopt, std::nullopt, 100});
  const uint64_t liveHash = play(recorded);
  const Replay replay = *recorded.stopRecording();
  ASSERT_EQ(replay.frames(), 240u);
  ASSERT_EQ(replay.console.size(), 3u);
  EXPECT_EQ(replay.console[0].frame, 30u);  // typed before frame 30, run there on playback
  EXPECT_EQ(replay.console[2].frame, 120u);

  // A scene of its own (a scenario's), the same input: the same hash.
  std::unique_ptr<Scene> plain = loadScene(level.scene, level.registry);
  core::Run scenario(*plain);
  EXPECT_EQ(play(scenario), liveHash);

  // The recording played back through ReplayInput (play --input, shot --input, the runner): every
  // recorded hash on its frame, and the same end.
  LiveScene again(level.scene, level.registry, false);
  core::Run playback(again);
  ReplayInput input(replay, playback.scene());
  for (uint64_t f = 1; !input.over(playback.frame()); ++f) {
    playback.step(input.next(playback));
    EXPECT_EQ(playback.scene().world().stateHash(), replay.hashes[f - 1].hash) << "frame " << f;
  }
  EXPECT_EQ(playback.frame(), 240u);
  EXPECT_EQ(playback.scene().world().stateHash(), liveHash);

  // Without the console's lines the run differs: they are part of the input.
  LiveScene bare(level.scene, level.registry, false);
  core::Run noConsole(bare);
  for (uint64_t f = 1; f <= 240; ++f) noConsole.step(buttons(f - 1));
  EXPECT_NE(noConsole.scene().world().stateHash(), liveHash);
}

TEST(Run, AButtonHeldAcrossAPauseIsPressedAgain) {
  PushLevel level;
  LiveScene live(level.scene, level.registry, false);
  core::Run run(live);
  const core::Buttons jump = InputFrame::bit(Button::Jump);
  run.step(jump);
  run.step(jump);  // held: no press
  run.releaseButtons();
  run.record({"scene.lua", 1, std::nullopt, std::nullopt, 100});
  run.step(jump);  // pressed again after the pause
  EXPECT_EQ(run.recorded()->held.back(), jump);
  EXPECT_EQ(run.frame(), 3u);
  EXPECT_EQ(run.console("1 + 1")->text, "2");
  run.step(0);
  const Replay recorded = *run.recorded();
  ASSERT_EQ(recorded.console.size(), 1u);
  EXPECT_EQ(recorded.console.back().frame, 2u);  // before the recording's second frame
}

TEST(Run, AConsoleNeedsAScriptingSystem) {
  testing::TempFolder folder("run_bare");
  SystemRegistry registry;
  const std::string scene = folder.write("scene.lua", "return { stage = { solid = 'cube' } }\n");
  LiveScene live(scene, registry, false);
  core::Run run(live);
  EXPECT_FALSE(run.console("1").has_value());
  EXPECT_FALSE(run.step(0).has_value());
}

}  // namespace
}  // namespace platon::core
