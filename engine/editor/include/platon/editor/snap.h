// Where a click lands: the point under the mouse moved to the nearest end point within a few
// pixels, else along a whole angle step from the segment being drawn (Shift), else to the grid;
// always a whole unit inside its face (a segment never leaves its face).
#pragma once
#include <optional>

#include "platon/editor/pick.h"
#include "platon/stage/level.h"

namespace platon::editor {

struct SnapSettings {
  bool enabled = true;    // off while Alt is held
  int grid = 64;          // units; 0: no grid
  double endPixels = 12;  // an end point this near on screen takes the click
  bool angles = false;    // Shift: the direction from `from` in steps of angleStep degrees
  double angleStep = 15;
};

struct Snapped {
  enum class Kind : uint8_t { Free, Grid, End, Angle };
  FacePoint point;  // whole units, inside its face
  Kind kind = Kind::Free;
};

// `raw` snapped on face raw.face of `level` (on `solid`, drawn by `view` as the lens shows it); `from` is
// the other end of a segment being drawn, when there is one.
Snapped snap(const FacePoint& raw, const stage::Level& level, const stage::Stage& solid, const core::StageView& view,
             const Lens& lens, const SnapSettings& settings, std::optional<FacePoint> from = std::nullopt);

// Whether a whole-unit point lies inside a face's corners (counter-clockwise), exactly as the level
// reader counts inside: on the border is inside.
bool insideExactly(const std::vector<physics::Vec2>& corners, physics::Vec2 p);

// The mean of face `face`'s corners: a point inside it, whatever its shape.
FacePoint faceCentre(const stage::Stage& solid, int face);

// The whole-unit point nearest (x, y) that lies inside face `face` (exactly, as the level
// reader's check counts inside: on the border is inside).
FacePoint wholeInside(const stage::Stage& solid, int face, double x, double y);

}  // namespace platon::editor
