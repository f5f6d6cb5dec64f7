// What the game shows of its events, beyond the HUD: a burst of particles where a sound was played
// (a jump's dust, a death's sparks, a goal's confetti), a flash of the screen, a shake of the view
// and a short freeze for the hard ones. Driven by the sounds each frame made (core/sound.h) and the
// player's place, so a modder's player that plays "death" gets a death's picture with no drawing
// code, and a shot of frame N shows the same particles as the game did. The picture's only: none of
// it reaches the simulation.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "platon/core/draw_list.h"
#include "platon/core/scene.h"
#include "platon/script/script_system.h"

namespace platon::session {

// How one event reads on screen.
struct Cue {
  std::string_view sound;  // the effect that plays with it
  int particles;           // how many
  float speed;             // their top speed, units per frame
  float up;                // how much of their motion is up, from the face's down (0: all round)
  int life;                // frames
  float size;              // radius, units
  core::Color color;
  int flashFrames;  // a flash of the screen in `flash`, fading
  core::Color flash;
  float shake;       // the view's shake, a fraction of the camera's distance
  int freezeFrames;  // the picture holds still (the simulation waits with it, in the game)
  bool whereBefore;  // at the player's place the frame before (a death: the respawn moved it since)
  float below;       // units below the player's centre (a jump's dust at its feet)
};

// The cues, by the sound each goes with.
const std::vector<Cue>& cues();

class Feedback {
 public:
  // After each simulation step: the frame's sounds start their cues at the player's place, and
  // every particle moves on.
  void step(const core::Scene& scene, const script::GameStatus& status);
  // A frame of the picture with no simulation under it (the level-complete screen): the particles
  // and the flash go on, no cue starts.
  void advance();
  // The particles and the flash, into the frame's picture.
  void draw(core::DrawList& out) const;
  // The view's shake now, a fraction of the camera's distance (0 with shaking off).
  float shake() const { return shakeOn_ ? shake_ : 0; }
  void setShake(bool on) { shakeOn_ = on; }
  // Frames the picture should hold still from now (once: reading it resets it).
  int takeFreeze() {
    const int f = freeze_;
    freeze_ = 0;
    return f;
  }

 private:
  struct Particle {
    physics::MapPartId face;
    float x, y, vx, vy, gx, gy;
    int age, life;
    float size;
    core::Color color;
  };
  struct Place {
    physics::MapPartId face;
    float x, y;
  };
  void start(const Cue& cue, const core::Scene& scene, const Place& at);

  std::vector<Particle> particles_;
  std::optional<Place> last_;
  core::Color flash_{};
  int flashLeft_ = 0, flashFrames_ = 1;
  float shake_ = 0;
  bool shakeOn_ = true;
  int freeze_ = 0;
  uint32_t random_ = 0x9e3779b9u;
};

}  // namespace platon::session
