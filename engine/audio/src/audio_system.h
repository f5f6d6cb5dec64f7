// The audio system: SDL_mixer plays what a scene makes heard (core/sound.h). Effects are rendered
// by engine/synth when played and kept, within bounds a bank cannot move (a 1 MB bank names tens of
// thousands of effects of up to 10 s): the kept samples at most kMaxKeptBytes (the least recently
// played let go first), and at most kMaxRenderedSeconds of sound made in one frame (what is past it
// is not heard that frame). The scene's tune is stepped by the
// synthesizer in the mixer's thread as it plays (no start-up cost, no file). The device is the
// process's: opened by the first audio system, shared by the scenes after it (a hot reload or the
// next level) and kept open until the process ends, so a tune that both scenes name plays on
// without a break.
#pragma once
#include <list>
#include <map>
#include <memory>
#include <string>

#include "platon/core/audio.h"
#include "platon/core/sound.h"
#include "platon/core/system.h"

struct Mix_Chunk;

namespace platon::audio {

struct Device;

class AudioSystem final : public core::System, public core::AudioControls {
 public:
  static constexpr size_t kMaxKeptBytes = size_t{32} << 20;
  static constexpr double kMaxRenderedSeconds = 12;  // a frame makes at least one longest effect (10 s)

  explicit AudioSystem(const core::SoundBank& bank);
  ~AudioSystem() override;

  void hear(const core::SoundFrame& frame) override;
  core::AudioControls* audio() override { return this; }

  void setVolumes(float music, float effects) override;
  void setPaused(bool paused) override;
  void playNow(const std::string& name) override;
  void playTune(const std::string& name) override;
  std::string silentBecause() const override;

 private:
  void playEffect(const std::string& name, float volume, float pan);
  void setTune(const std::string& name, const core::SoundBank& bank);
  Mix_Chunk* chunkOf(const std::string& name);

  void keep(const std::string& name, Mix_Chunk* chunk);

  Device* device_;  // the process's (audio_system.cpp)
  core::SoundBank bank_;
  struct Kept {
    Mix_Chunk* chunk;
    std::list<std::string>::iterator use;  // its place in uses_
  };
  std::map<std::string, Kept, std::less<>> chunks_;
  std::list<std::string> uses_;  // the kept effects, the most recently played first
  size_t keptBytes_ = 0;
  double renderedThisFrame_ = 0;  // seconds
};

}  // namespace platon::audio
