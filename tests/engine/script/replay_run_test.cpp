// Replays: a recorded run replays bit for bit, a changed input is caught at the first hash after
// it, and a replay turns into a scenario that passes.
#include <gtest/gtest.h>

#include "platon/core/replay.h"
#include "platon/script/scenario.h"
#include "platon/testing/rng.h"
#include "platon/testing/temp_folder.h"

namespace platon::script {
namespace {

using core::Button;
using core::InputFrame;

// A random run on the first level: walking both ways, jumping, standing still, restarting.
core::Replay randomRun(testing::Rng& rng, int frames, uint64_t hashEvery) {
  core::Replay r;
  r.scene = "levels/cube_intro/scene.lua";
  r.hashEvery = hashEvery;
  core::Buttons held = 0;
  for (int f = 0; f < frames; ++f) {
    if (rng.between(0, 30) == 0) {
      held = 0;
      const int move = rng.between(0, 2);
      if (move == 1) held |= InputFrame::bit(Button::Left);
      if (move == 2) held |= InputFrame::bit(Button::Right);
      if (rng.between(0, 2) == 0) held |= InputFrame::bit(Button::Jump);
      if (rng.between(0, 40) == 0) held |= InputFrame::bit(Button::Restart);
    }
    r.held.push_back(held);
  }
  return r;
}

// Records `input` by replaying it with recording on (a replay without hashes checks nothing).
core::Replay record(const testing::TempFolder& folder, const core::Replay& input, const std::string& name) {
  const std::string path = folder.write(name, core::formatReplay(input));
  RunOptions options;
  options.record = true;
  options.hashEvery = input.hashEvery;
  const ScenarioResult r = runReplay(path, options);
  EXPECT_TRUE(r.passed) << r.message;
  EXPECT_TRUE(r.recorded.has_value());
  return *r.recorded;
}

TEST(Replay, RandomRunsReplayBitForBit) {
  testing::TempFolder folder("replay_random");
  testing::Rng rng{5};
  for (int trial = 0; trial < 12; ++trial) {
    const core::Replay input = randomRun(rng, rng.between(200, 1500), static_cast<uint64_t>(rng.between(1, 90)));
    const core::Replay recorded = record(folder, input, "run.replay");
    ASSERT_EQ(recorded.held, input.held);
    ASSERT_FALSE(recorded.hashes.empty());
    const std::string path = folder.write("recorded.replay", core::formatReplay(recorded));
    const ScenarioResult again = runReplay(path);
    ASSERT_TRUE(again.passed) << "trial " << trial << ": " << again.message;
    ASSERT_EQ(again.frames, recorded.frames());
  }
}

TEST(Replay, AChangedInputFailsAtTheFirstHashAfterIt) {
  testing::TempFolder folder("replay_changed");
  testing::Rng rng{9};
  int caught = 0;
  for (int trial = 0; trial < 12; ++trial) {
    core::Replay input = randomRun(rng, 900, 10);
    // Keep the player walking right so that a changed direction always changes the state.
    for (core::Buttons& h : input.held) h = InputFrame::bit(Button::Right);
    const core::Replay recorded = record(folder, input, "run.replay");
    core::Replay changed = recorded;
    // Before the goal (frame 336 walking right): once won, the level ignores input.
    const size_t at = static_cast<size_t>(rng.between(1, 330));
    changed.held[at - 1] = InputFrame::bit(Button::Left);
    const ScenarioResult r = runReplay(folder.write("changed.replay", core::formatReplay(changed)));
    ASSERT_FALSE(r.passed) << "frame " << at << " changed, replay still passed";
    const uint64_t firstCheck = (at + 9) / 10 * 10;
    EXPECT_NE(r.message.find("frame " + std::to_string(firstCheck) + ": state hash"), std::string::npos)
        << "changed frame " << at << ": " << r.message;
    ++caught;
  }
  EXPECT_EQ(caught, 12);
}

TEST(Replay, MissingSceneAndBadFileAreErrors) {
  testing::TempFolder folder("replay_bad");
  const ScenarioResult missing = runReplay(folder.write(
      "a.replay", "platon replay 1\nscene \"levels/nowhere/scene.lua\"\nframes 1\nhash_every 0\ninput\n1 -\nend\n"));
  EXPECT_FALSE(missing.passed);
  EXPECT_NE(missing.message.find("levels/nowhere/scene.lua"), std::string::npos) << missing.message;
  const ScenarioResult bad = runReplay(folder.write("b.replay", "platon replay 1\nscene \"x\"\nframes 2\n"));
  EXPECT_FALSE(bad.passed);
  EXPECT_NE(bad.message.find("b.replay:3:"), std::string::npos) << bad.message;
}

TEST(Replay, TurnsIntoAScenarioThatPasses) {
  testing::TempFolder folder("replay_scenario");
  testing::Rng rng{21};
  for (int trial = 0; trial < 6; ++trial) {
    core::Replay input = randomRun(rng, 1200, 60);
    if (trial == 0)  // one run that reaches the goal
      for (core::Buttons& h : input.held) h = InputFrame::bit(Button::Right);
    // Lines typed in the console are part of the input (a play-test kept with K may carry them);
    // a long one too, with quotes (the scenario quotes it whole).
    if (trial % 2 == 1) {
      input.console.push_back({static_cast<uint64_t>(rng.between(2, 400)),
                               "game.world.setVelocity(game.player(), 0, -9) -- \"up\" " + std::string(150, 'x')});
      input.console.push_back({input.console.back().frame + 5, "game.message('typed')"});
    }
    const core::Replay recorded = record(folder, input, "run.replay");
    const std::string replayPath = folder.write("run.replay", core::formatReplay(recorded));
    const ScenarioResult outcome = runReplay(replayPath);
    ASSERT_TRUE(outcome.passed) << outcome.message;
    const std::string text = scenarioFromReplay(recorded, outcome, "run.replay");
    if (trial == 0) {
      EXPECT_NE(text.find("goal_by = "), std::string::npos) << text;
    }
    const ScenarioResult r = runScenario(folder.write("scenario.lua", text));
    ASSERT_TRUE(r.passed) << r.message << "\n" << text;
    if (!input.console.empty()) {
      EXPECT_NE(text.find("console = {"), std::string::npos) << text;
    }
    // Every line within the project's lint, but a console line's own (it is quoted whole).
    for (size_t begin = 0; begin < text.size();) {
      const size_t end = text.find('\n', begin);
      const std::string line = text.substr(begin, end - begin);
      if (line.find("code = ") == std::string::npos) {
        EXPECT_LE(line.size(), 120u) << line;
      }
      begin = end == std::string::npos ? text.size() : end + 1;
    }
    // A scenario that expects the goal stops there; otherwise it ends where the replay did.
    if (!outcome.status->won) {
      EXPECT_EQ(r.hash, outcome.hash);
    }
  }
}

}  // namespace
}  // namespace platon::script
