// The audio system's controls (the audio plugin implements them), for the game's settings and its
// pause menu. Plain interface: the plugin needs no engine code to offer it.
#pragma once
#include <string>

namespace platon::core {

class AudioControls {
 public:
  virtual ~AudioControls() = default;
  // Music and effects volumes, 0..1 each: the player's, times each sound's own.
  virtual void setVolumes(float music, float effects) = 0;
  // Holds the music and effects (the pause menu, a window that lost focus) or lets them go on.
  virtual void setPaused(bool paused) = 0;
  // Plays an effect of the scene's bank now, outside a frame (the menus' sounds).
  virtual void playNow(const std::string& name) = 0;
  // Plays a tune of the scene's bank now, outside a frame (the title's); the scene's own tune takes
  // over at its next frame.
  virtual void playTune(const std::string& name) = 0;
  // Why the game is silent ("" when it is not): no audio device, say.
  virtual std::string silentBecause() const = 0;
};

}  // namespace platon::core
