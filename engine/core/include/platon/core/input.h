// The player's input as the simulation sees it: which buttons are held on each frame. Keyboard and
// gamepad in the game, a scenario or a replay headless, all produce the same InputFrame, so a
// recorded run replays bit for bit.
#pragma once
#include <cstdint>

#include "platon/core/actions.h"

namespace platon::core {

enum class Button : uint8_t { Left, Right, Up, Down, Jump, Restart, Pause, Reload };
inline constexpr int kButtonCount = 8;

// Their names, labels and keys are the engine's actions (core/actions.h), in this order.

struct InputFrame {
  Buttons held = 0;     // bit i: action i is down on this frame
  Buttons pressed = 0;  // bit i: action i went down on this frame (held now, not on the frame before)

  bool isHeld(Button b) const { return (held >> static_cast<int>(b)) & 1; }
  bool wasPressed(Button b) const { return (pressed >> static_cast<int>(b)) & 1; }
  static constexpr Buttons bit(Button b) { return static_cast<Buttons>(1u << static_cast<int>(b)); }
};

// Turns the held buttons of successive frames into InputFrames with their press edges.
class InputEdges {
 public:
  InputFrame next(Buttons held) {
    const InputFrame frame{held, static_cast<Buttons>(held & ~previous_)};
    previous_ = held;
    return frame;
  }
  void reset() { previous_ = 0; }

 private:
  Buttons previous_ = 0;
};

// Buttons tapped between two polls of the window. A press and its release both between two frames
// played would be lost to "held" alone (the state at the poll); each tap counts as held for the next
// frame played, however many polls pass before it (a display faster than the game plays none on
// some), so a tap of any length is seen, and recorded, once.
class TapCarry {
 public:
  void add(Buttons tapped) { pending_ |= tapped; }
  // The buttons of the next frame played: those held, and every tap not played yet.
  Buttons next(Buttons held) {
    const Buttons buttons = static_cast<Buttons>(held | pending_);
    pending_ = 0;
    return buttons;
  }
  void reset() { pending_ = 0; }

 private:
  Buttons pending_ = 0;
};

}  // namespace platon::core
