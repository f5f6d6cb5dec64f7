// What scripts and systems ask to draw on one frame. Shapes live in a face's own 2D coordinates
// (the renderer maps them onto the solid); text may also be placed on the screen. The renderer
// reads the list after each frame. Without a renderer the list is disabled and every call returns
// at once, recording nothing: a headless run pays one branch per call.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "platon/physics/ids.h"
#include "platon/stage/tags.h"

namespace platon::core {

struct Color {
  uint8_t r = 255, g = 255, b = 255, a = 255;
  friend bool operator==(Color, Color) = default;
};

struct Point2 {
  float x = 0, y = 0;
};

// Where a shape is drawn: on a face (in its coordinates, units) or on the screen (pixels from the
// top left).
struct Place {
  bool screen = false;
  physics::MapPartId face = 0;
  bool overlay = false;  // on a face, drawn over its walls and unlit (the debug overlay)
  static Place onFace(physics::MapPartId face) { return {false, face}; }
  static Place overlayOnFace(physics::MapPartId face) { return {false, face, true}; }
  static Place onScreen() { return {true, 0}; }
};

enum class ShapeKind : uint8_t { Circle, Polygon, Line, Text, Wall };

struct DrawShape {
  ShapeKind kind = ShapeKind::Circle;
  Place place;
  Color color;
  float size = 0;      // circle radius, line width, text height
  Point2 at;           // circle centre, text anchor (its top left)
  uint32_t first = 0;  // polygon, line and wall: points()[first, first + count); text: its characters
  uint32_t count = 0;
  // Circles and polygons: the entity they are an instance of (its handle's index + 1), or 0. The
  // renderer draws one entity once: a ball on the face that holds its centre, a polygon cut at
  // each face's edges.
  uint32_t body = 0;
  uint32_t tag = 0;      // a wall's line tag (its colour and style)
  uint8_t lineKind = 0;  // a wall's physics::LineKind (1 solid... see ViewLine::kind)
  // A body's ball: its height over its width along the way it stands (below 1 squashed, as on a
  // landing; above 1 stretched, as in a jump's start), its volume kept.
  float squash = 1;
  stage::TagStyle style = {};  // a wall's tag's look
};

// A frame's list holds at most kMaxShapes shapes, kMaxPoints polygon and line points and
// kMaxTextBytes of text (what scripts draw is work and memory outside every Lua limit); a shape
// past them is dropped and its call returns false.
class DrawList {
 public:
  static constexpr size_t kMaxShapes = 10'000;
  static constexpr size_t kMaxPoints = 100'000;
  static constexpr size_t kMaxTextBytes = size_t{64} * 1024;

  explicit DrawList(bool enabled = false) : enabled_(enabled) {}
  bool enabled() const { return enabled_; }

  // Each returns false when the shape was dropped: over a limit (a disabled list drops nothing:
  // it records nothing and returns true).
  bool circle(Place place, Point2 centre, float radius, Color color, uint32_t body = 0, float squash = 1);
  // A convex polygon, counter-clockwise.
  bool polygon(Place place, std::span<const Point2> points, Color color, uint32_t body = 0);
  // A line of the world drawn as the stage's own lines are (a moving platform's), by its tag and
  // kind (ViewLine's).
  bool wall(Place place, Point2 a, Point2 b, uint32_t tag, uint8_t lineKind, stage::TagStyle style = {});
  bool line(Place place, Point2 a, Point2 b, float width, Color color);
  bool text(Place place, Point2 at, std::string_view text, float height, Color color);
  void clear();

  std::span<const DrawShape> shapes() const { return shapes_; }
  std::span<const Point2> points() const { return points_; }
  std::string_view text(const DrawShape& shape) const {
    return std::string_view(text_).substr(shape.first, shape.count);
  }

  // The picture `t` of the way (0..1) from `from` to `to`, for drawing between two simulation
  // steps: each shape of `to` whose counterpart in `from` (same index, kind, place and point
  // count) exists moves that fraction of the way; any other shape is drawn as in `to`.
  static DrawList between(const DrawList& from, const DrawList& to, float t);

 private:
  bool enabled_;
  std::vector<DrawShape> shapes_;
  std::vector<Point2> points_;
  std::string text_;
};

}  // namespace platon::core
