// The work-precision scenes and their closed-form answers (scenes.h).
#include "scenes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace platon::bench::precision {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double g = kGravity;

Scene flight() {
  Scene s{.name = "flight", .vx0 = 3, .vy0 = 8, .seconds = 1.5};
  s.distance = [s](const Pose& p, double t) {
    return std::hypot(p.x - (s.x0 + s.vx0 * t), p.y - (s.y0 + s.vy0 * t - 0.5 * g * t * t));
  };
  return s;
}

// Dropped from 2 m above a floor: a parabola down to the engine's own contact height, then rest.
Scene landing(double gap) {
  Scene s{.name = "landing", .segments = {{-5, 0, 5, 0}}, .y0 = kHalf + 2, .seconds = 1.5, .hasExtra = true};
  const double rest = kHalf + gap, landsAt = std::sqrt(2 * (s.y0 - rest) / g);
  auto height = [s, rest](double t) { return std::max(rest, s.y0 - 0.5 * g * t * t); };
  s.score = [height, rest, landsAt](const Poses& poses, double dt) {
    Score out{.extra = std::numeric_limits<double>::quiet_NaN()};
    for (size_t f = 0; f < poses.size(); ++f) {
      const double t = static_cast<double>(f) * dt;
      out.error = std::max(out.error, std::hypot(poses[f].x, poses[f].y - height(t)));
      // Landed: the first frame within 1 mm of the engine's resting height.
      if (std::isnan(out.extra) && poses[f].y - rest < 1e-3) out.extra = t - landsAt;
    }
    return out;
  };
  return s;
}

// A frictionless slope descending to the right at `degrees`; the box's lowest corner starts on it
// (at the engine's gap above it). An entity keeps only the velocity along the line, so it slides
// with the tangential part of gravity: s(t) = g sin(a) t^2 / 2 along the slope. The error is taken
// along the slope; across it is the gap.
Scene slope(int degrees, double gap) {
  const double a = degrees * kPi / 180, dx = std::cos(a), dy = -std::sin(a), reach = 16;
  Scene s{.name = "slope" + std::to_string(degrees),
          .segments = {{-reach * dx, -reach * dy, 2 * reach * dx, 2 * reach * dy}},
          .x0 = kHalf + gap * std::sin(a),
          .y0 = kHalf + gap * std::cos(a),
          .seconds = 2};
  s.distance = [s, dx, dy, a](const Pose& p, double t) {
    const double along = (p.x - s.x0) * dx + (p.y - s.y0) * dy;
    return std::fabs(along - 0.5 * g * std::sin(a) * t * t);
  };
  return s;
}

// 1,000 collinear 0.5 m segments; the box runs at 10 m/s (set every frame, vertical velocity 0,
// gravity pressing it down): x = x0 + v t at its resting height.
Scene chain(double gap) {
  Scene s{.name = "chain", .x0 = 1, .y0 = kHalf + gap, .seconds = 45, .runSpeed = 10};
  for (int i = 0; i < 1000; ++i) s.segments.push_back({0.5 * i, 0, 0.5 * (i + 1), 0});
  s.drive = [](PeerWorld& w, int body, long, double) { w.setVelocity(body, 10, 0); };
  s.distance = [s](const Pose& p, double t) { return std::hypot(p.x - (s.x0 + s.runSpeed * t), p.y - s.y0); };
  return s;
}

// Left at its own rest pose for `frames` frames: any motion is error.
Scene rest(long frames, double gap) {
  Scene s{.name = "rest", .segments = {{-5, 0, 5, 0}}, .y0 = kHalf + gap, .frames = frames};
  s.distance = [s](const Pose& p, double) { return std::hypot(p.x - s.x0, p.y - s.y0); };
  return s;
}

// The top of a free-flight arc through three samples at equal steps (exact for a parabola sampled
// at equal times, which every engine's free flight is): {time offset from the middle, height}.
std::pair<double, double> apexThrough(double y0, double y1, double y2, double dt) {
  const double curvature = y0 - 2 * y1 + y2;
  if (curvature >= 0) return {0, y1};
  const double shift = 0.5 * (y0 - y2) / curvature;  // in steps, within [-1/2, 1/2]
  return {shift * dt, y1 - 0.25 * (y0 - y2) * shift};
}

// Dropped from 2 m onto a floor with restitution 1 (Platon: the ElasticBounce rule): every bounce
// returns to the start height, and the i-th apex comes at 2 i sqrt(2 h / g) for the fall h to the
// engine's own contact height. Error: the k-th apex's height; extra: its time.
Scene bounce(int k, double gap) {
  const double y0 = kHalf + 2, fall = y0 - (kHalf + gap), half = std::sqrt(2 * fall / g);
  Scene s{.name = "bounce" + std::to_string(k),
          .segments = {{-5, 0, 5, 0}},
          .y0 = y0,
          .restitution = 1,
          .seconds = 1.25 * (2 * k + 0.5) * half,
          .hasExtra = true};
  s.score = [k, y0, half](const Poses& poses, double dt) {
    // An apex: where the height, having last changed upwards, first changes downwards (whole-unit
    // positions stay level near the top for a few frames; the fit uses the plateau's last frame).
    int apexes = 0;
    bool rising = false;
    for (size_t f = 1; f + 1 < poses.size(); ++f) {
      const double a = poses[f - 1].y, b = poses[f].y, c = poses[f + 1].y;
      if (b > a) rising = true;
      if (!rising || !(c < b)) continue;
      rising = false;
      if (++apexes < k) continue;
      const auto [shift, top] = apexThrough(a, b, c, dt);
      return Score{std::fabs(top - y0), static_cast<double>(f) * dt + shift - 2 * k * half};
    }
    // Fewer than k bounces in the time the answer takes plus a quarter: the error is how far the
    // highest point of the last quarter is from the start height (the bounce died out or grew).
    double highest = 0;
    for (size_t f = poses.size() * 3 / 4; f < poses.size(); ++f) highest = std::max(highest, poses[f].y);
    return Score{std::fabs(y0 - highest), std::numeric_limits<double>::quiet_NaN()};
  };
  return s;
}

// A run-up as a game writes one: each frame the speed grows by 12 m/s^2 dt up to 6.06 m/s, from
// 1.217 s it falls by 8 m/s^2 dt down to 0 (the changes fall inside frames at every rate), and the
// game sets it with vertical velocity 0, gravity pressing the box onto a floor. Answer: x = x0 +
// the integral of the continuous speed, at the engine's resting height.
Scene ramp(double gap) {
  constexpr double accelerate = 12, top = 6.06, speedUp = top / accelerate, brakeAt = 1.217, brake = 8;
  constexpr double stopAt = brakeAt + top / brake;
  auto position = [=](double t) {
    const double t1 = std::min(t, speedUp), t2 = std::clamp(t, speedUp, brakeAt) - speedUp;
    const double t3 = std::clamp(t, brakeAt, stopAt) - brakeAt;
    return 0.5 * accelerate * t1 * t1 + top * t2 + top * t3 - 0.5 * brake * t3 * t3;
  };
  Scene s{.name = "ramp", .segments = {{-5, 0, 30, 0}}, .y0 = kHalf + gap, .seconds = 2.5};
  auto speed = std::make_shared<double>(0);
  s.drive = [=](PeerWorld& w, int body, long frame, double dt) {
    if (frame == 0) *speed = 0;
    const double t = static_cast<double>(frame) * dt;
    *speed = t < brakeAt ? std::min(top, *speed + accelerate * dt) : std::max(0.0, *speed - brake * dt);
    w.setVelocity(body, *speed, 0);
  };
  s.distance = [s, position](const Pose& p, double t) { return std::hypot(p.x - (s.x0 + position(t)), p.y - s.y0); };
  return s;
}

// No gravity and no lines: the game turns the velocity every frame to the circle's tangent at the
// frame's start (4 m/s on a 2 m radius), two turns. Answer: the circle.
Scene circle() {
  constexpr double radius = 2, speed = 4, omega = speed / radius;
  Scene s{.name = "circle", .x0 = radius, .vy0 = speed, .gravity = 0, .seconds = 2 * 2 * kPi / omega};
  s.drive = [](PeerWorld& w, int body, long frame, double dt) {
    const double a = omega * static_cast<double>(frame) * dt;
    w.setVelocity(body, -speed * std::sin(a), speed * std::cos(a));
  };
  s.distance = [](const Pose& p, double t) {
    return std::hypot(p.x - radius * std::cos(omega * t), p.y - radius * std::sin(omega * t));
  };
  return s;
}

// Sliding at 6 m/s along a floor into a 20 degree rise, met 0.1715 s in (inside a frame at every
// rate). Frictionless and inelastic: at the kink the box's front corner keeps the velocity along
// the slope, v cos(a), then climbs against g sin(a). Lines are offset by the engine's gap.
Scene slopeChange(double gap) {
  constexpr double a = 20 * kPi / 180, v = 6, kinkTime = 0.1715;
  const double ca = std::cos(a), sa = std::sin(a);
  const double kinkX = kHalf + v * kinkTime;  // where the floor turns up
  // The front corner's path: along y = gap, then along the slope offset by the gap; they meet at K.
  const double kx = kinkX - gap * sa + gap * (1 - ca) / sa * ca, meets = (kx - kHalf) / v;
  Scene s{.name = "slopechange",
          .segments = {{-5, 0, kinkX, 0}, {kinkX, 0, kinkX + 12 * ca, 12 * sa}},
          .y0 = kHalf + gap,
          .vx0 = v,
          .seconds = kinkTime + 1.2};
  s.distance = [=](const Pose& p, double t) {
    double cx = kHalf + v * t, cy = gap;  // the corner
    if (t > meets) {
      const double tau = t - meets, along = v * ca * tau - 0.5 * g * sa * tau * tau;
      cx = kx + along * ca, cy = gap + along * sa;
    }
    return std::hypot(p.x - (cx - kHalf), p.y - (cy + kHalf));
  };
  return s;
}

}  // namespace

Polygon box() { return {{-kHalf, -kHalf}, {kHalf, -kHalf}, {kHalf, kHalf}, {-kHalf, kHalf}}; }

Scene settleOnFloor() {
  Scene s{.name = "settle", .segments = {{-5, 0, 5, 0}}, .y0 = kHalf, .seconds = 20};
  s.score = [](const Poses& poses, double) { return Score{poses.back().y - kHalf}; };
  return s;
}

std::vector<SceneSpec> allScenes(long restFrames) {
  std::vector<SceneSpec> out{
      {"flight", "free flight, 1.5 s (parabola)", [](double) { return flight(); }},
      {"landing", "landing from 2 m, 1.5 s (parabola, then the resting height)", landing},
  };
  for (const int degrees : {10, 30, 45, 60})
    out.push_back({"slope" + std::to_string(degrees),
                   "frictionless slope " + std::to_string(degrees) + "°, 2 s (along the slope)",
                   [degrees](double gap) { return slope(degrees, gap); }});
  out.push_back({"chain", "running 10 m/s over 1,000 collinear segments, 45 s", chain});
  out.push_back({"rest", "resting on a floor, " + std::to_string(restFrames) + " frames",
                 [restFrames](double gap) { return rest(restFrames, gap); }});
  for (const int k : {10, 100})
    out.push_back({"bounce" + std::to_string(k), "elastic bounce: apex height after " + std::to_string(k) + " bounces",
                   [k](double gap) { return bounce(k, gap); }});
  out.push_back({"ramp", "run-up: speed raised and lowered every frame by the game, 2.5 s", ramp});
  out.push_back(
      {"circle", "velocity turned every frame: a 2 m circle at 4 m/s, 2 turns", [](double) { return circle(); }});
  out.push_back({"slopechange", "sliding into a 20° rise met inside a frame, 1.37 s", slopeChange});
  return out;
}

}  // namespace platon::bench::precision
