// The player's input as the simulation sees it: which buttons are held on each frame. Keyboard and
// gamepad in the game, a scenario or a replay headless, all produce the same InputFrame, so a
// recorded run replays bit for bit.
#pragma once
#include <cstdint>
#include <string_view>

namespace platon::core {

enum class Button : uint8_t { Left, Right, Up, Down, Jump, Restart, Pause, Reload };
inline constexpr int kButtonCount = 8;

// The button's name as scenarios and replay files spell it ("left", "jump", ...), and back;
// buttonFromName returns false for an unknown name.
std::string_view buttonName(Button button);
bool buttonFromName(std::string_view name, Button& out);

struct InputFrame {
  uint8_t held = 0;     // bit i: Button i is down on this frame
  uint8_t pressed = 0;  // bit i: Button i went down on this frame (held now, not on the frame before)

  bool isHeld(Button b) const { return (held >> static_cast<int>(b)) & 1; }
  bool wasPressed(Button b) const { return (pressed >> static_cast<int>(b)) & 1; }
  static constexpr uint8_t bit(Button b) { return static_cast<uint8_t>(1u << static_cast<int>(b)); }
};

// Turns the held buttons of successive frames into InputFrames with their press edges.
class InputEdges {
 public:
  InputFrame next(uint8_t held) {
    const InputFrame frame{held, static_cast<uint8_t>(held & ~previous_)};
    previous_ = held;
    return frame;
  }
  void reset() { previous_ = 0; }

 private:
  uint8_t previous_ = 0;
};

// Buttons tapped between two polls of the window. A press and its release both between two frames
// played would be lost to "held" alone (the state at the poll); each tap counts as held for the next
// frame played, however many polls pass before it (a display faster than the game plays none on
// some), so a tap of any length is seen, and recorded, once.
class TapCarry {
 public:
  void add(uint8_t tapped) { pending_ |= tapped; }
  // The buttons of the next frame played: those held, and every tap not played yet.
  uint8_t next(uint8_t held) {
    const uint8_t buttons = static_cast<uint8_t>(held | pending_);
    pending_ = 0;
    return buttons;
  }
  void reset() { pending_ = 0; }

 private:
  uint8_t pending_ = 0;
};

// Where a run's input comes from: the devices, a scenario script, a replay file.
class InputSource {
 public:
  virtual ~InputSource() = default;
  // The buttons held on simulation frame `frame` (1 for the first step).
  virtual uint8_t held(uint64_t frame) = 0;
};

}  // namespace platon::core
