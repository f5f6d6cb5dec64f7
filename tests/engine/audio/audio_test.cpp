// The audio plugin: loaded only for a scene that names "audio"; what a scene makes heard reaches
// the device on its frame, the tune plays, and the volumes and the pause hold it. The device is
// SDL's disk driver (SDL_AUDIODRIVER=disk): it writes, in real time, exactly what a sound card
// would have played, so the test reads the game's sound as samples.
#include "platon/core/audio.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "platon/core/scene.h"
#include "platon/testing/mapped.h"
#include "platon/testing/temp_folder.h"

namespace platon {
namespace {

using testing::mapped;

// Plays an effect on frame `at` of the scene it is added to and names a tune on frame `tuneAt`
// (what a script's platon.sound calls do).
class Plays : public core::System {
 public:
  Plays(std::string effect, uint64_t at, std::string tune, uint64_t tuneAt)
      : effect_(std::move(effect)), tune_(std::move(tune)), at_(at), tuneAt_(tuneAt) {}
  void beforeStep(core::Scene& scene, const core::InputFrame&) override {
    if (scene.frame() + 1 == at_) scene.sounds().play(effect_, 1, 0);
    if (scene.frame() + 1 == tuneAt_) scene.sounds().setMusic(tune_);
  }

 private:
  std::string effect_, tune_;
  uint64_t at_, tuneAt_;
};

// The disk device's file as stereo 16-bit frames' loudness: the root mean square of each
// window of `window` frames.
std::vector<double> loudness(const std::string& path, size_t window) {
  std::ifstream in(path, std::ios::binary);
  std::vector<int16_t> samples;
  int16_t s;
  while (in.read(reinterpret_cast<char*>(&s), sizeof s)) samples.push_back(s);
  std::vector<double> out;
  for (size_t start = 0; start + 2 * window <= samples.size(); start += 2 * window) {
    double sum = 0;
    for (size_t i = start; i < start + 2 * window; ++i) sum += double(samples[i]) * samples[i];
    out.push_back(std::sqrt(sum / double(2 * window)) / 32768.0);
  }
  return out;
}

// Steps `scene` `frames` times at the game's pace (the disk device plays in real time).
void playFor(core::Scene& scene, int frames) {
  auto next = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) {
    scene.step({});
    next += std::chrono::microseconds(16667);
    std::this_thread::sleep_until(next);
  }
}

core::SystemRegistry withAudio() {
  core::SystemRegistry registry;
  registry.addPlugin("audio", "platon_audio", {PLATON_PLUGIN_DIR});
  return registry;
}

TEST(Audio, ThePluginIsLoadedOnlyWhenASceneNamesIt) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");  // a fresh process: nothing an earlier test loaded
  EXPECT_EXIT(
      {
        setenv("SDL_AUDIODRIVER", "dummy", 1);
        testing::TempFolder folder("audio_plugin");
        const core::SystemRegistry registry = withAudio();
        auto bare = core::loadScene(folder.write("a.lua", "return { name = 'a' }"), registry);
        const bool before = mapped("libplaton_audio") || mapped("libSDL2_mixer");
        auto heard = core::loadScene(folder.write("b.lua", "return { name = 'b', systems = { 'audio' } }"), registry);
        const bool after = mapped("libplaton_audio") && mapped("libSDL2_mixer") && heard->findSystem("audio");
        if (before || !after) std::fprintf(stderr, "mapped before the scene named it: %d, after: %d\n", before, after);
        std::exit(!before && after ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

// What a scene makes heard reaches the device in order: the silence before a sound, the sound, the
// silence after it, a tune once named that plays on without a gap; the player's volumes of 0 and the
// pause silence both.
TEST(Audio, WhatASceneMakesHeardReachesTheDeviceOnItsFrame) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  // The child is this program started afresh (its own temporary folders): it names the file by
  // its parent's id, this process's.
  const auto fileOf = [](pid_t parent) { return "/tmp/platon_audio_disk_" + std::to_string(parent) + ".raw"; };
  const std::string file = fileOf(getpid());
  EXPECT_EXIT(
      {
        testing::TempFolder folder("audio_disk");
        setenv("SDL_AUDIODRIVER", "disk", 1);
        setenv("SDL_DISKAUDIOFILE", fileOf(getppid()).c_str(), 1);
        const core::SystemRegistry registry = withAudio();
        auto scene = core::loadScene(folder.write("s.lua", "return { name = 's', systems = { 'audio' } }"), registry);
        // The goal's chord (0.92 s) on frame 45, the tune on frame 160: a second of silence between
        // them at the game's pace, and more on a machine too loaded to keep it.
        scene->addSystem(std::make_unique<Plays>("goal", 45, "orbit", 160));
        core::AudioControls* audio = scene->findSystem("audio")->audio();
        if (!audio || !audio->silentBecause().empty()) std::exit(2);
        playFor(*scene, 250);  // silence, the chord, silence, 1.5 s of the tune
        audio->setVolumes(0, 0);
        playFor(*scene, 60);  // 1 s with both volumes at 0
        audio->setVolumes(1, 1);
        audio->setPaused(true);
        playFor(*scene, 60);  // 1 s paused
        scene.reset();        // the device stays open until the exit, which writes out what it played
        std::exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  const std::vector<double> level = loudness(file, 4410);  // tenths of a second
  std::remove(file.c_str());
  // What was played, in order, whatever a loaded machine does to the timing (a late step or a late
  // device thread stretches a part, never reorders them): silence, the goal's chord, silence, the
  // tune with no gap, then silence to the end (volumes at 0, then paused).
  std::string shape;
  for (double v : level) shape += v == 0 ? '0' : v < 0.005 ? '.' : '#';
  SCOPED_TRACE("tenths of a second: 0 silent, . faint, # heard: " + shape);
  ASSERT_GE(level.size(), 50u);
  const size_t chord = shape.find('#'), afterChord = shape.find_first_not_of('#', chord);
  ASSERT_NE(chord, std::string::npos) << "nothing heard";
  EXPECT_EQ(shape.find_first_not_of('0'), chord) << "a sound before the goal's";
  EXPECT_GE(chord, 4u) << "heard before frame 45";
  ASSERT_NE(afterChord, std::string::npos);
  EXPECT_GE(afterChord - chord, 6u) << "the chord is 0.92 s long";
  EXPECT_LE(afterChord - chord, 11u) << "the chord is 0.92 s long";
  const size_t tune = shape.find('#', afterChord), last = shape.rfind('#');
  ASSERT_NE(tune, std::string::npos) << "the tune is not heard";
  EXPECT_GE(tune - afterChord, 3u) << "no silence between the chord and the tune";
  EXPECT_EQ(shape.substr(tune, last - tune + 1).find_first_not_of('#'), std::string::npos) << "a gap in the tune";
  EXPECT_GE(last - tune + 1, 10u) << "the tune did not play on";
  EXPECT_GE(level.size() - last - 1, 12u) << "heard with volumes of 0 or paused";
  for (size_t i = last + 2; i < level.size(); ++i) EXPECT_LT(level[i], 0.001) << i;
}

// Plays `perFrame` effects of the bank (e1, e2, ...) each frame, a different one each time.
class PlaysMany : public core::System {
 public:
  PlaysMany(int count, int perFrame) : count_(count), perFrame_(perFrame) {}
  void beforeStep(core::Scene& scene, const core::InputFrame&) override {
    for (int i = 0; i < perFrame_; ++i) scene.sounds().play("e" + std::to_string(next_++ % count_ + 1), 1, 0);
  }

 private:
  int count_, perFrame_, next_ = 0;
};

// What freed memory still holds of the process under AddressSanitizer: it keeps freed blocks in a
// quarantine (256 MB by default) before reusing them, so they stay resident.
#if defined(__SANITIZE_ADDRESS__)
constexpr size_t kQuarantineMegabytes = 256;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr size_t kQuarantineMegabytes = 256;
#else
constexpr size_t kQuarantineMegabytes = 0;
#endif
#else
constexpr size_t kQuarantineMegabytes = 0;
#endif

size_t residentKilobytes() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stoul(line.substr(6));
  return 0;
}

// A bank may name thousands of effects of 10 s each (1.9 MB of samples apiece): played one after
// another, the samples kept stay within the cache's bound (the least recently played let go), and a
// frame makes at most 12 s of sound (30 asked for a frame, one made). Before, every effect played
// was kept for good: 300 of them grew the process by about 570 MB.
TEST(Audio, AHugeBankKeepsBoundedSamples) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        testing::TempFolder folder("audio_many");
        setenv("SDL_AUDIODRIVER", "dummy", 1);
        std::string bank = "return { effects = {\n";
        for (int i = 1; i <= 300; ++i)
          bank += "  e" + std::to_string(i) + " = { wave = 'noise', frequency = " + std::to_string(100 + i) +
                  ", attack = 2, sustain = 4, decay = 4, volume = 0.1 },\n";
        folder.write("bank.lua", bank + "} }\n");
        const core::SystemRegistry registry = withAudio();
        auto scene = core::loadScene(
            folder.write("s.lua", "return { name = 's', systems = { 'audio' }, sounds = 'bank.lua' }"), registry);
        scene->addSystem(std::make_unique<PlaysMany>(300, 30));
        core::AudioControls* audio = scene->findSystem("audio")->audio();
        if (!audio || !audio->silentBecause().empty()) std::exit(2);
        const size_t before = residentKilobytes();
        for (int f = 0; f < 330; ++f) scene->step({});
        const size_t grown = (residentKilobytes() - before) / 1024;
        std::fprintf(stderr, "grown by %zu MB\n", grown);
        std::exit(grown < 96 + kQuarantineMegabytes ? 0 : 3);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace platon
