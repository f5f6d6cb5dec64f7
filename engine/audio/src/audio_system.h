// The audio system: SDL_mixer plays what a scene makes heard (core/sound.h). Effects are rendered
// by engine/synth the first time each is played and kept; the scene's tune is stepped by the
// synthesizer in the mixer's thread as it plays (no start-up cost, no file). The device is the
// process's: opened by the first audio system, shared by the scenes after it (a hot reload or the
// next level) and kept open until the process ends, so a tune that both scenes name plays on
// without a break.
#pragma once
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

  Device* device_;  // the process's (audio_system.cpp)
  core::SoundBank bank_;
  std::map<std::string, Mix_Chunk*, std::less<>> chunks_;
};

}  // namespace platon::audio
