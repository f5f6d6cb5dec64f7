#include "platon/editor/snap.h"

#include <cmath>
#include <numbers>

namespace platon::editor {
namespace {

bool insideExactly(const std::vector<physics::Vec2>& corners, int64_t x, int64_t y) {
  for (size_t i = 0; i < corners.size(); ++i) {
    const physics::Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
    if ((int64_t{b.x} - a.x) * (y - a.y) - (int64_t{b.y} - a.y) * (x - a.x) < 0) return false;
  }
  return true;
}

}  // namespace

bool insideExactly(const std::vector<physics::Vec2>& corners, physics::Vec2 p) {
  return insideExactly(corners, int64_t{p.x}, int64_t{p.y});
}

FacePoint faceCentre(const stage::Stage& solid, int face) {
  const std::vector<physics::Vec2>& corners = solid.faces.at(static_cast<size_t>(face)).corners;
  double x = 0, y = 0;
  for (const physics::Vec2 c : corners) x += c.x, y += c.y;
  return {face, x / static_cast<double>(corners.size()), y / static_cast<double>(corners.size())};
}

FacePoint wholeInside(const stage::Stage& solid, int face, double x, double y) {
  const std::vector<physics::Vec2>& corners = solid.faces.at(static_cast<size_t>(face)).corners;
  const FacePoint centre = faceCentre(solid, face);
  const double cx = centre.x, cy = centre.y;
  // Toward the face's centre until the rounded point is inside: the first such point on the way
  // (bisection on how far; the centre itself is inside a convex face).
  auto rounded = [&](double t) { return std::pair{std::llround(x + t * (cx - x)), std::llround(y + t * (cy - y))}; };
  auto [rx, ry] = rounded(0);
  if (insideExactly(corners, rx, ry)) return {face, double(rx), double(ry)};
  double lo = 0, hi = 1;
  for (int i = 0; i < 40; ++i) {
    const double mid = (lo + hi) / 2;
    const auto [mx, my] = rounded(mid);
    (insideExactly(corners, mx, my) ? hi : lo) = mid;
  }
  std::tie(rx, ry) = rounded(hi);
  return {face, double(rx), double(ry)};
}

Snapped snap(const FacePoint& raw, const stage::Level& level, const stage::Stage& solid, const core::StageView& view,
             const Lens& lens, const SnapSettings& settings, std::optional<FacePoint> from) {
  Snapped out{wholeInside(solid, raw.face, raw.x, raw.y), Snapped::Kind::Free};
  if (!settings.enabled) return out;
  // An end point of the face's segments (or the other end of the one being drawn) near on screen.
  const auto mouse = toScreen(lens, view, raw);
  if (mouse) {
    double best = settings.endPixels;
    auto consider = [&](double x, double y) {
      const auto at = toScreen(lens, view, {raw.face, x, y});
      if (!at) return;
      const double d = (*at - *mouse).norm();
      if (d <= best) best = d, out = {{raw.face, x, y}, Snapped::Kind::End};
    };
    for (const stage::LevelLine& l : level.faces.at(static_cast<size_t>(raw.face)).lines) {
      consider(l.a.x, l.a.y);
      consider(l.b.x, l.b.y);
    }
    if (out.kind == Snapped::Kind::End) return out;
  }
  if (settings.angles && from && from->face == raw.face) {
    const double dx = raw.x - from->x, dy = raw.y - from->y, length = std::hypot(dx, dy);
    const double step = settings.angleStep * std::numbers::pi / 180;
    const double angle = std::round(std::atan2(dy, dx) / step) * step;
    // Along the snapped direction: a whole number of grid steps when there is a grid.
    double along = length;
    if (settings.grid > 0) along = std::max(1.0, std::round(length / settings.grid)) * settings.grid;
    out = {wholeInside(solid, raw.face, from->x + along * std::cos(angle), from->y + along * std::sin(angle)),
           Snapped::Kind::Angle};
    return out;
  }
  if (settings.grid > 0) {
    const double g = settings.grid;
    out = {wholeInside(solid, raw.face, std::round(raw.x / g) * g, std::round(raw.y / g) * g), Snapped::Kind::Grid};
  }
  return out;
}

}  // namespace platon::editor
