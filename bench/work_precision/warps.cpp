// Warps (Platon only: the peers have nothing like them): walking and floating across a face edge,
// every instance compared with the exact path mapped into its own part (warps.h).
#include "warps.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "platon/physics/world.h"
#include "platon/testing/si_units.h"

namespace platon::bench::precision {
namespace {

using namespace platon::physics;

Vec2 unitsAt(long double x, long double y, int upm) { return platon::testing::pointFromMetres(x, y, upm); }

// Two faces meeting at an edge whose frames differ by `degrees` (90: cube, 120: tetrahedron,
// 72 + 180: dodecahedron). Face A is x in [0, W] with the warp on x = W; face B is the continuation
// x in [W, 2W] of the same unfolded plane, drawn in B's frame turned by `degrees` (rounded to
// units). Walking: a floor on y = 0 in both faces (B's turned alike), gravity turned alike, the box
// walks across at 4 m/s. Floating: no floor, no gravity, the box drifts across at (4, 0.5) m/s.
// The analytic path is a straight line in the unfolded plane; every instance is compared with it
// mapped exactly (long double rotation) into its own part.
class WarpRun {
 public:
  static constexpr double kFace = 8, kStartX = 5, kSeconds = kWarpSeconds;

  WarpRun(const WarpScene& scene, int upm, double hz) : scene_(scene), upm_(upm), hz_(hz) {
    const long double a = scene.degrees * std::numbers::pi_v<long double> / 180;
    c_ = std::cos(a), s_ = std::sin(a);
    MapPart& faceA = world_.createMapPart(1);
    MapPart& faceB = world_.createMapPart(2);
    const Vec2 t0 = turned(kFace, 0), t1 = turned(kFace, kFace);
    faceA.warp(units(kFace, 0), units(kFace, kFace), 2, t0, t1);
    faceB.warp(t1, t0, 1, units(kFace, kFace), units(kFace, 0));
    if (scene.walk) {
      faceA.line(units(0, 0), units(kFace, 0));
      faceB.line(t0, turned(2 * kFace, 0));
      const long double g = -kGravity * upm / (hz * hz) * 65536;  // Q16 units per frame squared
      faceA.setGravity({0, std::llround(g)});
      faceB.setGravity({std::llround(-s_ * g), std::llround(c_ * g)});
    }
    faceA.initialize();
    faceB.initialize();
    const int32_t half = static_cast<int32_t>(std::lround(kHalf * upm));
    id_ = world_.createEntity(Convex::box(half, half));
    world_.insert(id_, 1, units(kStartX, y0()), 0);
    world_.setVelocity(id_,
                       {platon::testing::q16FromSpeed(vx(), upm, hz), platon::testing::q16FromSpeed(vy(), upm, hz)});
  }

  long frames() const { return std::lround(kSeconds * hz_); }
  void step() { world_.solve(); }
  const World& world() const { return world_; }
  EntityView entity() const { return world_.entity(id_); }

  // The instance's position against the analytic path mapped into its part, metres.
  double error(const InstanceView& inst, double t) const {
    const long double x = kStartX + vx() * t, y = y0() + vy() * t;
    const long double ex = inst.part == 1 ? x : c_ * x - s_ * y, ey = inst.part == 1 ? y : s_ * x + c_ * y;
    return static_cast<double>(std::hypot(inst.position.x / static_cast<long double>(upm_) - ex,
                                          inst.position.y / static_cast<long double>(upm_) - ey));
  }
  // The anchor's x in the unfolded plane, metres.
  double unfoldedX() const {
    const InstanceView anchor = entity().instance(0);
    const long double x = anchor.position.x, y = anchor.position.y;
    return static_cast<double>((anchor.part == 1 ? x : c_ * x + s_ * y) / upm_);
  }
  double vx() const { return 4; }
  double vy() const { return scene_.walk ? 0 : 0.5; }

  // The instance's pose, shape and its part's solid lines in metres, for the common measurements.
  Pose pose(const InstanceView& inst) const { return {metres(inst.position.x), metres(inst.position.y), 0}; }
  Polygon shape(const InstanceView& inst) const {
    Polygon out;
    for (const Vec2 v : inst.shape) out.push_back({metres(v.x), metres(v.y)});
    return out;
  }
  Segments solidSegments(MapPartId part) const {
    Segments out;
    const MapPart& p = world_.mapPart(part);
    for (size_t i = 0; i < p.lines().size(); ++i)
      if (p.lines()[i].kind == LineKind::Solid) {
        const Segment& seg = p.segments()[i];
        out.push_back({metres(seg.a.x), metres(seg.a.y), metres(seg.b.x), metres(seg.b.y)});
      }
    return out;
  }

 private:
  double y0() const { return scene_.walk ? kHalf : 3.5; }
  Vec2 units(double x, double y) const { return unitsAt(x, y, upm_); }
  // A point of the unfolded plane in B's frame, units.
  Vec2 turned(double x, double y) const { return unitsAt(c_ * x - s_ * y, s_ * x + c_ * y, upm_); }
  double metres(int64_t u) const { return static_cast<double>(u) / upm_; }

  WarpScene scene_;
  int upm_;
  double hz_;
  long double c_ = 1, s_ = 0;
  World world_;
  EntityId id_;
};

}  // namespace

Row measureWarp(const WarpScene& scene, int upm, double hz) {
  Row r{.engine = "Platon", .setting = std::to_string(upm) + "u/m", .scene = scene.name(), .dt = 1 / hz};
  r.extra = std::numeric_limits<double>::quiet_NaN();
  // Every instance on every frame, the invariant, and stuck frames (by the anchor's unfolded x; in
  // a turned frame both coordinates are rounded, so up to sqrt(2) units).
  WarpRun run(scene, upm, hz);
  Poses unfolded{{run.unfoldedX(), 0, 0}};
  for (long f = 1; f <= run.frames(); ++f) {
    run.step();
    r.overlaps += run.world().countOverlaps();
    for (const InstanceView inst : run.entity().instances()) {
      r.error = std::max(r.error, run.error(inst, static_cast<double>(f) / hz));
      r.penetration =
          std::max(r.penetration, penetrationDepth(run.shape(inst), run.pose(inst), run.solidSegments(inst.part)));
    }
    unfolded.push_back({run.unfoldedX(), 0, 0});
  }
  const double perFrame = run.vx() / hz, quantum = std::sqrt(2.0) / upm;
  const size_t k = std::max<size_t>(1, static_cast<size_t>(std::ceil(4 * quantum / perFrame)));
  for (size_t f = k; f < unfolded.size(); ++f)
    r.stuck += unfolded[f].x - unfolded[f - k].x < 0.5 * perFrame * static_cast<double>(k) - quantum;
  const InstanceView anchor = run.entity().instance(0);
  const Segments floor = run.solidSegments(anchor.part);
  r.gap = floor.empty() ? std::numeric_limits<double>::quiet_NaN()
                        : gapToNearest(run.shape(anchor), run.pose(anchor), floor);
  return r;
}

double timeWarp(const WarpScene& scene, int upm, double hz) {
  WarpRun run(scene, upm, hz);
  const auto t0 = std::chrono::steady_clock::now();
  for (long f = 0; f < run.frames(); ++f) run.step();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace platon::bench::precision
