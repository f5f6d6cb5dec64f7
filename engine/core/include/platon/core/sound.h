// What a scene makes heard: the sound bank it may play from (engine/synth's effects and tunes, read
// from data files), and each frame's sounds as scripts ask for them (platon.sound). The scene
// records them whether or not a device plays them: headless, that record is the null device a
// scenario checks; in a window the audio plugin plays it. Sounds are the listener's, never the
// simulation's: nothing here is in the state hash or feeds back into a frame.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "platon/synth/synth.h"

namespace platon::core {

// The sounds a scene can play, by name: the engine's bank (share/platon/sounds/bank.lua), then a
// level's own (the manifest's `sounds`), whose names may replace the engine's.
struct SoundBank {
  std::map<std::string, synth::Effect, std::less<>> effects;
  std::map<std::string, synth::Music, std::less<>> music;
  bool hasEffect(std::string_view name) const { return effects.find(name) != effects.end(); }
  bool hasMusic(std::string_view name) const { return music.find(name) != music.end(); }
  // The names, in order, as messages list them: "crystal, first_steps, ..." ("none" for none).
  std::string effectNames() const { return namesOf(effects); }
  std::string musicNames() const { return namesOf(music); }

 private:
  static std::string namesOf(const auto& byName) {
    std::string list;
    for (const auto& [name, spec] : byName) list += (list.empty() ? "" : ", ") + name;
    return list.empty() ? "none" : list;
  }
};

// A bank file is a regular file of at most this (data/sounds: a few KB each).
inline constexpr size_t kMaxSoundBankBytes = size_t{1} << 20;
// Reads a bank file into `bank` (names it defines replace those there). Throws std::runtime_error
// "file:line:column: reason".
void readSoundBank(const std::string& path, SoundBank& bank);
// The engine's own bank, read once per process from the data root.
const SoundBank& engineSoundBank();

struct SoundEvent {
  std::string name;
  float volume = 1;  // 0..1, times the effect's own and the player's effects volume
  float pan = 0;     // -1 left .. 1 right
};

// One frame's sounds, as the scene hands them to its systems at the end of a step.
struct SoundFrame {
  uint64_t frame;
  const std::vector<SoundEvent>& effects;
  const std::string& music;  // the tune that should be playing ("" for none)
  const SoundBank& bank;
};

class Sounds {
 public:
  // A frame plays at most this many effects; more are dropped (and play() says so).
  static constexpr size_t kMaxPerFrame = 32;

  void setBank(SoundBank bank) { bank_ = std::move(bank); }
  const SoundBank& bank() const { return bank_; }
  // Adds an effect to this frame; false when the frame already has kMaxPerFrame.
  bool play(std::string name, float volume, float pan) {
    if (frame_.size() >= kMaxPerFrame) return false;
    frame_.push_back({std::move(name), volume, pan});
    return true;
  }
  void setMusic(std::string name) { music_ = std::move(name); }
  const std::string& music() const { return music_; }
  const std::vector<SoundEvent>& thisFrame() const { return frame_; }
  void clearFrame() { frame_.clear(); }

 private:
  SoundBank bank_;
  std::vector<SoundEvent> frame_;
  std::string music_;
};

}  // namespace platon::core
