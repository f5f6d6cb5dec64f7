// What a renderer shows and the window it owns: the interface between the loop that plays a scene
// (apps/platon) and the rendering system, a plugin loaded only when a scene is played in a window
// (engine/render). Plain data in, so the plugin needs no engine code but this header (and the
// camera's math).
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "platon/camera/camera.h"
#include "platon/core/actions.h"
#include "platon/core/draw_list.h"
#include "platon/physics/ids.h"
#include "platon/physics/world.h"
#include "platon/stage/stage.h"
#include "platon/stage/tags.h"

namespace platon::core {

class Scene;

struct Point3 {
  float x = 0, y = 0, z = 0;
};

// A map line of a face, in the face's coordinates.
struct ViewLine {
  Point2 a, b;
  uint32_t tag = 0;
  uint8_t kind = 0;            // physics::LineKind: 0 solid, 1 warp (a face edge), 2 one-way
  stage::TagStyle style = {};  // its tag's look, from the scene's tag table
  bool door = false;           // its tag's passage is a door's: drawn shut or open by GameStatus::openTags
};

// One face of the stage: its outline and lines in its own 2D frame and where that frame sits in 3D
// (the point (x, y) is at origin + x * xAxis + y * yAxis; normal points out of the solid).
struct ViewFace {
  physics::MapPartId part = 0;
  std::vector<Point2> corners;  // counter-clockwise seen from outside
  Point3 origin, xAxis, yAxis, normal;
  std::vector<ViewLine> lines;
};

// The stage as the renderer draws it, built once per scene (a reload builds a new one, so the
// renderer may keep what it made from it for as long as it holds the same pointer).
struct StageView {
  std::vector<ViewFace> faces;
  Point3 centre;
  float radius = 1;    // the farthest corner from the centre
  float edge = 1;      // the longest face edge: walls scale with it
  float faceSize = 1;  // the widest face's diameter: how much the camera shows
  bool flat = false;   // no solid (a scene built in Lua): only the player's face is drawn, from above
};

// One frame's picture, besides the draw list: the stage, the camera, the heads-up lines and an
// error laid over everything until it is gone.
struct View {
  std::string title;
  std::shared_ptr<const StageView> stage;  // null: only the heads-up lines and the overlay
  physics::MapPartId face = 0;             // the player's face (a flat stage shows only this one)
  std::vector<uint32_t> openTags;          // doors open now: their lines are drawn open
  camera::CameraPose camera;
  double verticalFov = 0.785398;
  std::vector<std::string> hud;         // top left, one line each
  std::vector<std::string> centreText;  // big, in the middle of the screen (titles, menus)
  std::string error;                    // "" for none
  bool showFps = false;                 // the renderer's frame rate in the top right corner
};

// The scene's stage, ready to show. A scene with no solid shows only the player's part, flat: build
// it again when the player changes part.
std::shared_ptr<const StageView> stageView(const Scene& scene, physics::MapPartId playerPart);
// The same for a stage in a world (the stage's parts hold its faces' lines).
std::shared_ptr<StageView> stageView(const stage::Stage& stage, const physics::World& world,
                                     const stage::TagTable& tags = *stage::gameTags());
// What the camera follows when the player stands at (x, y) on map part `face`, whose gravity
// (any length; zero: the face's -y) gives its down.
camera::CameraTarget cameraTarget(const StageView& stage, physics::MapPartId face, float x, float y,
                                  physics::Vec2w gravity);
camera::CameraTarget cameraTarget(const StageView& stage, const Scene& scene, physics::MapPartId face, float x,
                                  float y);

// Keys the game's menus and controls act on once per press (held buttons go to the simulation).
enum class Key : uint8_t {
  Escape,
  Enter,
  Up,
  Down,
  Left,
  Right,
  Restart,
  Reload,
  ShowFps,
  Settings,
  Screenshot,
  Debug,
  Console,   // ` : the game's console
  Backspace  // repeats while held
};

// The keys and pad buttons that hold the actions are core::KeyBindings (core/actions.h), by SDL's
// names (keys: "Left", "A", "Space", "Keypad 4"; pad buttons: "a", "dpleft", "back",
// "leftshoulder"). The pad's left stick always moves; the menus' own keys and buttons (arrows,
// WASD, Enter, Esc; A, B, Start) stay as they are, so no binding can lock a player out.

// A key as SDL names it ("Z", "Delete", "Return", "F5"), with the modifiers held as it went down:
// the editor's shortcuts (the game reads `pressed` and the held buttons).
struct KeyPress {
  std::string name;
  bool ctrl = false, shift = false, alt = false;
};

// A mouse button pressed or released, or the wheel turned, where the pointer was (pixels from the
// window's top left, as screen shapes are placed).
struct MouseEvent {
  enum class Kind : uint8_t { Down, Up, Wheel };
  Kind kind = Kind::Down;
  uint8_t button = 0;  // 1 left, 2 middle, 3 right (SDL's numbers)
  float x = 0, y = 0;
  float wheel = 0;  // notches, away from the user positive
};

// What the window's devices (keyboard, mouse, gamepads) did since the last poll.
struct WindowInput {
  Buttons held = 0;               // InputFrame bits of the actions held now
  Buttons tapped = 0;             // and of those pressed since the last call, held now or not (TapCarry)
  std::vector<Key> pressed;       // in order
  bool closed = false;            // the window was closed
  bool focusLost = false;         // the window lost the keyboard (the game pauses)
  std::string lastKey;            // SDL's name of the last key pressed ("Space"), for binding one
  std::string lastPadButton;      // and of the last pad button pressed ("a", "leftshoulder")
  std::string text;               // the text typed since the last call (UTF-8), for the console
  std::vector<KeyPress> keys;     // every key pressed, in order (repeats of a held key included)
  std::vector<MouseEvent> mouse;  // in order
  float mouseX = 0, mouseY = 0;   // the pointer now, in pixels from the top left
  uint8_t mouseHeld = 0;          // buttons held now: bit (button - 1)
  bool shift = false, ctrl = false, alt = false;  // modifiers held now
  int width = 0, height = 0;                      // the window's drawable, in pixels
};

class Display {
 public:
  virtual ~Display() = default;
  // The window's events since the last call (opens the window on first use; throws
  // std::runtime_error when there is no display).
  virtual WindowInput pollEvents() = 0;
  virtual void present(const View& view, const DrawList& draw) = 0;
  // The window's size; before the window opens, the size it opens at (the only way to size an
  // offscreen surface). On a high-DPI screen the drawable has more pixels than these points.
  virtual void resize(int width, int height) = 0;
  // The frame last presented: width x height RGBA pixels, rows from the top. Throws
  // std::runtime_error when nothing was presented yet.
  virtual std::vector<uint8_t> capture(int& width, int& height) = 0;
  // Writes the frame last presented as a PNG; throws std::runtime_error when it cannot.
  virtual void saveScreenshot(const std::string& path) = 0;
  // The player's keys from now on; returns the names it does not know (those keys bind nothing).
  virtual std::vector<std::string> setBindings(const KeyBindings& bindings) = 0;
  // Full screen (on the desktop's resolution) or a window, and whether frames wait for the
  // display's refresh (vsync).
  virtual void setFullscreen(bool on) = 0;
  virtual void setVsync(bool on) = 0;
  // Samples a pixel (anti-aliasing) from the next frame on: 0 none, 2, 4 or 8; -1 chooses (4 on a
  // GPU, none on a software rasterizer, where every sample costs the whole frame again).
  virtual void setMultisamples(int samples) = 0;
};

}  // namespace platon::core
