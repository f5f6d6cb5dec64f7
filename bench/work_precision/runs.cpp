// Running and measuring one engine on one scene (runs.h).
#include "runs.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "peers/platon_world.h"

namespace platon::bench::precision {
namespace {

using Clock = std::chrono::steady_clock;

int setUp(PeerWorld& w, const Scene& s) {
  w.setGravity(0, -s.gravity);
  for (const auto& [x0, y0, x1, y1] : s.segments) w.addSegment(x0, y0, x1, y1);
  const int body = w.addBody(box(), s.x0, s.y0);
  w.setVelocity(body, s.vx0, s.vy0);
  if (s.restitution != 0) w.setRestitution(s.restitution);
  return body;
}

// Runs every frame; `afterFrame` (untimed runs only) sees the world after each.
Poses run(PeerWorld& w, int body, const Scene& s, double hz, const std::function<void()>& afterFrame = {}) {
  const long frames = s.frameCount(hz);
  const double dt = 1 / hz;
  Poses poses;
  poses.reserve(static_cast<size_t>(frames) + 1);
  poses.push_back(w.pose(body));
  for (long f = 0; f < frames; ++f) {
    if (s.drive) s.drive(w, body, f, dt);
    w.step(dt);
    poses.push_back(w.pose(body));
    if (afterFrame) afterFrame();
  }
  return poses;
}

// Frames on which a runner was stuck: it advanced by less than half of what it should have,
// beyond what rounding positions to whole units explains (`quantum`, 0 for the float engines).
// Where one frame's motion is within rounding, each frame is judged over the last k frames, enough
// to move four quanta; earlier frames are not judged.
long stuckFrames(const Poses& poses, double perFrame, double quantum) {
  const size_t k = std::max<size_t>(1, static_cast<size_t>(std::ceil(4 * quantum / perFrame)));
  long count = 0;
  for (size_t f = k; f < poses.size(); ++f)
    count += poses[f].x - poses[f - k].x < 0.5 * perFrame * static_cast<double>(k) - quantum;
  return count;
}

Score scoreOf(const Scene& s, const Poses& poses, double dt) {
  if (s.score) return s.score(poses, dt);
  Score out{.extra = std::numeric_limits<double>::quiet_NaN()};
  for (size_t f = 0; f < poses.size(); ++f)
    out.error = std::max(out.error, s.distance(poses[f], static_cast<double>(f) * dt));
  return out;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const double at = p * static_cast<double>(v.size() - 1);
  const size_t lo = static_cast<size_t>(std::floor(at)), hi = static_cast<size_t>(std::ceil(at));
  return v[lo] + (v[hi] - v[lo]) * (at - static_cast<double>(lo));
}

}  // namespace

double Row::median() const { return percentile(runtimes, 0.5); }
double Row::low() const { return percentile(runtimes, 0); }
double Row::high() const { return percentile(runtimes, 1); }

double restingGap(const Engine& e) {
  const Scene s = settleOnFloor();
  auto w = e.make();
  const int body = setUp(*w, s);
  return scoreOf(s, run(*w, body, s, e.hz), 1 / e.hz).error;
}

Row measure(const Engine& e, const SceneSpec& spec, double gap) {
  const Scene s = spec.make(gap);
  Row r{.engine = e.engine, .setting = e.setting, .scene = spec.name, .dt = 1 / e.hz, .usual = e.usual};
  r.restGap = gap;
  auto w = e.make();
  const int body = setUp(*w, s);
  auto* platon = dynamic_cast<PlatonWorld*>(w.get());
  const Poses poses = run(*w, body, s, e.hz, [&] {
    if (platon) r.overlaps += platon->overlaps();  // the invariant, on every frame
  });
  const Score score = scoreOf(s, poses, r.dt);
  r.error = score.error;
  r.extra = s.hasExtra ? score.extra : std::numeric_limits<double>::quiet_NaN();
  // Each engine judged on its own geometry: Platon's is rounded to units.
  const Polygon shape = platon ? platon->shape(body) : box();
  const Segments& lines = platon ? platon->segments() : s.segments;
  for (size_t f = 0; f < poses.size(); ++f) {
    const bool moved = f == 0 || poses[f].x != poses[f - 1].x || poses[f].y != poses[f - 1].y;
    if (moved && !lines.empty()) r.penetration = std::max(r.penetration, penetrationDepth(shape, poses[f], lines));
  }
  r.gap = lines.empty() ? std::numeric_limits<double>::quiet_NaN() : gapToNearest(shape, poses.back(), lines);
  if (s.runSpeed > 0) r.stuck = stuckFrames(poses, s.runSpeed * r.dt, e.quantum);
  return r;
}

double timeScene(const Engine& e, const Scene& scene, int repeats) {
  double seconds = 0;
  for (int k = 0; k < repeats; ++k) {
    auto w = e.make();
    const int body = setUp(*w, scene);
    const auto t0 = Clock::now();
    const long frames = scene.frameCount(e.hz);
    const double dt = 1 / e.hz;
    for (long f = 0; f < frames; ++f) {
      if (scene.drive) scene.drive(*w, body, f, dt);
      w->step(dt);
    }
    seconds += std::chrono::duration<double>(Clock::now() - t0).count();
  }
  return seconds / repeats;
}

}  // namespace platon::bench::precision
