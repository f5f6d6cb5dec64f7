// What a renderer shows and the window it owns: the interface between the loop that plays a scene
// (apps/platon) and the rendering system, a plugin loaded only when a scene is played in a window
// (engine/render). Plain data in, so the plugin needs no engine code but this header.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "platon/core/draw_list.h"
#include "platon/physics/ids.h"

namespace platon::core {

class Scene;

// A map line of the face on show, in the face's coordinates.
struct ViewLine {
  Point2 a, b;
  uint32_t tag = 0;
  uint8_t kind = 0;  // physics::LineKind: 0 solid, 1 warp (a face edge), 2 one-way
};

// One frame's picture, besides the draw list: the face the player is on, the heads-up lines, and
// an error laid over everything until it is gone.
struct View {
  std::string title;
  physics::MapPartId face = 0;
  std::vector<Point2> border;  // the face's corners, counter-clockwise, in its coordinates
  std::vector<ViewLine> lines;
  std::vector<std::string> hud;  // top left, one line each
  std::string error;             // "" for none
};

// The face `face` of the scene's stage with its lines, ready to show.
View faceView(const Scene& scene, physics::MapPartId face);

class Display {
 public:
  virtual ~Display() = default;
  // The window's events since the last call: `held` gets the buttons held now (InputFrame bits).
  // False once the player closed the window or pressed Esc.
  virtual bool pollEvents(uint8_t& held) = 0;
  virtual void present(const View& view, const DrawList& draw) = 0;
  // The frame last presented: width x height RGBA pixels, rows from the top. Throws
  // std::runtime_error when nothing was presented yet.
  virtual std::vector<uint8_t> capture(int& width, int& height) = 0;
  // Writes the frame last presented as a PNG; throws std::runtime_error when it cannot.
  virtual void saveScreenshot(const std::string& path) = 0;
};

}  // namespace platon::core
