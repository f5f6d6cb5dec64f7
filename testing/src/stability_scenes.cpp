#include "platon/testing/stability_scenes.h"

#include <chrono>
#include <cmath>

#include "platon/physics/world.h"
#include "platon/testing/si_units.h"

namespace platon::testing::scenes {
namespace {

using namespace platon::physics;

constexpr double kPi = 3.14159265358979323846;

std::vector<Point> box(double halfWidth, double halfHeight) {
  return {{-halfWidth, -halfHeight}, {halfWidth, -halfHeight}, {halfWidth, halfHeight}, {-halfWidth, halfHeight}};
}

std::vector<Point> regular(int n, double radius) {
  std::vector<Point> out;
  for (int i = 0; i < n; ++i) out.push_back({radius * std::cos(2 * kPi * i / n), radius * std::sin(2 * kPi * i / n)});
  return out;
}

Scene restOnFloor(std::string name, std::string what, double gravity, std::vector<Point> shape, double height,
                  int frames) {
  Scene s;
  s.name = std::move(name);
  s.what = std::move(what);
  s.gravityY = -gravity;
  s.solids = {{-50, 0, 50, 0}};
  s.shape = std::move(shape);
  s.start = {0, height, 0};
  s.frames = frames;
  s.settleFrames = frames / 2;
  s.allowed = [](const Pose& p) { return p.y > 0; };
  return s;
}

Outcome runWarpCorner(double upm);

Scene maxSpeedScene() {
  Scene s;
  s.name = "max-speed";
  s.what = "a 0.2 m box at 6 km/s (100 m per frame) towards three 1 mm-apart walls 1 km away";
  s.solids = {{1000, -5, 1000, 5}, {1000.001, -5, 1000.001, 5}, {1000.002, -5, 1000.002, 5}};
  s.shape = box(0.1, 0.1);
  s.vx = 6000;
  s.frames = 60;
  s.settleFrames = 30;
  s.targetX = 999.9;  // against the first wall
  s.allowed = [](const Pose& p) { return p.x < 1000; };
  return s;
}

Scene slideChainScene() {
  Scene s;
  s.name = "slide-chain";
  s.what = "a 0.5 m box driven at 5 m/s along 200 collinear 0.25 m segments";
  for (int i = 0; i < 200; ++i) s.solids.push_back({i * 0.25 - 1, 0, (i + 1) * 0.25 - 1, 0});
  s.gravityY = -9.81;
  s.shape = box(0.25, 0.25);
  s.start = {0, 0.25, 0};
  s.vx = 5;
  s.drive = true;
  s.frames = 480;
  s.minSpeedX = 5;
  s.allowed = [](const Pose& p) { return p.y > 0; };
  return s;
}

// An octagon dropped into a V of this half-angle, in degrees: the narrower, the harder to rest.
Scene wedgeScene(double halfAngle) {
  Scene s;
  s.name = "wedge-" + std::to_string(halfAngle).substr(0, std::to_string(halfAngle).find('.') + 2) + "deg";
  s.what = "a 0.2 m octagon dropped into a V of half-angle " + std::to_string(halfAngle).substr(0, 4) + " degrees";
  const double t = std::tan(halfAngle * kPi / 180);
  s.solids = {{-t * 1000, 1000, 0, 0}, {0, 0, t * 1000, 1000}};
  s.gravityY = -9.81;
  s.shape = regular(8, 0.1);
  s.start = {0, 0.1 / t + 1, 0};
  s.frames = 1200;
  s.settleFrames = 900;
  s.allowed = [](const Pose& p) { return p.y > 0; };
  return s;
}

Scene starHubScene() {
  Scene s;
  s.name = "star-hub";
  s.what = "a 0.2 m octagon dropped into a star of 64 lines meeting at one point";
  for (int i = 0; i < 64; ++i)
    s.solids.push_back({0, 0, 3 * std::cos(2 * kPi * (i + 0.5) / 64), 3 * std::sin(2 * kPi * (i + 0.5) / 64)});
  s.gravityY = -9.81;
  s.shape = regular(8, 0.1);
  s.start = {0.013, 3.5, 0};
  s.frames = 900;
  s.settleFrames = 600;
  s.allowed = [](const Pose& p) { return p.y > 0; };
  return s;
}

Scene denseParallelScene() {
  Scene s;
  s.name = "dense-parallel";
  s.what = "a 0.5 m box at 50 g driven at 3 m/s over 200 lines 1 mm apart";
  for (int i = 0; i < 200; ++i) s.solids.push_back({-10, -i * 0.001, 40, -i * 0.001});
  s.gravityY = -490;
  s.shape = box(0.25, 0.25);
  s.start = {0, 0.3, 0};
  s.vx = 3;
  s.drive = true;
  s.frames = 600;
  s.allowed = [](const Pose& p) { return p.y > 0; };
  return s;
}

Scene spinCorridorScene() {
  Scene s;
  s.name = "spin-corridor";
  s.what = "a 1 m x 0.1 m stick spinning at 10 rad/s, driven at 1 m/s in a 0.3 m corridor";
  s.solids = {{-5, 0.15, 40, 0.15}, {40, -0.15, -5, -0.15}};
  s.shape = box(0.5, 0.05);
  s.vx = 1;
  s.drive = true;
  s.spin = 10;
  s.rotates = true;
  s.frames = 600;
  s.allowed = [](const Pose& p) { return std::fabs(p.y) < 0.15; };
  return s;
}

Scene fastTriggerScene() {
  Scene s;
  s.name = "fast-trigger";
  s.what = "a 0.2 m box at 96 m/s (1.6 m per frame) through 10 trigger lines 4.7 m apart";
  for (int i = 0; i < 10; ++i) s.triggers.push_back({10.3 + 4.7 * i, -5, 10.3 + 4.7 * i, 5});
  s.shape = box(0.1, 0.1);
  s.vx = 96;
  s.frames = 45;
  s.targetX = 72;
  s.expectedCrossings = 10;
  s.allowed = [](const Pose&) { return true; };
  return s;
}

// Platon's own: a body across a warp of two faces (no other engine has one to compare).
Scene warpCornerScene() {
  Scene s;
  s.name = "warp-corner";
  s.what = "a 0.5 m box straddling a cube edge, pressed into a corner on both faces, 10^4 frames";
  s.frames = 10000;
  s.platonOnly = [](double upm) { return runWarpCorner(upm); };
  return s;
}

// The scene moved by `offset` metres in x and y: its lines, its start, its target and what it
// allows (which still sees the scene's own coordinates).
void offsetScene(Scene& s, double offset) {
  for (Seg& g : s.solids) g = {g[0] + offset, g[1] + offset, g[2] + offset, g[3] + offset};
  for (Seg& g : s.triggers) g = {g[0] + offset, g[1] + offset, g[2] + offset, g[3] + offset};
  s.start.x += offset;
  s.start.y += offset;
  s.targetX += offset;
  s.allowed = [inner = s.allowed, offset](const Pose& p) { return inner({p.x - offset, p.y - offset, p.angle}); };
}

}  // namespace

std::vector<Scene> stabilityScenes(double offset) {
  std::vector<Scene> scenes;
  scenes.push_back(
      restOnFloor("high-gravity", "100 g: a 0.5 m box dropped from 10 m onto a floor", 981, box(0.25, 0.25), 10, 600));
  scenes.push_back(maxSpeedScene());
  scenes.push_back(
      restOnFloor("thin-stick", "a 20 m x 2 cm stick falling flat onto a floor", 9.81, box(10, 0.01), 3, 600));
  scenes.push_back(restOnFloor("tiny-body", "a 3 mm triangle falling onto a floor", 9.81,
                               {{-0.0015, -0.001}, {0.0015, -0.001}, {0, 0.002}}, 1, 600));
  scenes.push_back(slideChainScene());
  for (const double halfAngle : {10.0, 1.0, 0.1}) scenes.push_back(wedgeScene(halfAngle));
  scenes.push_back(starHubScene());
  scenes.push_back(denseParallelScene());
  scenes.push_back(spinCorridorScene());
  scenes.push_back(fastTriggerScene());
  scenes.push_back(warpCornerScene());
  scenes.push_back(
      restOnFloor("rest-1e6", "a 0.5 m box resting on a floor for 10^6 frames", 9.81, box(0.25, 0.25), 0.25, 1000000));
  scenes.back().settleFrames = 1000;
  for (Scene& s : scenes)
    if (offset != 0) offsetScene(s, offset);
  return scenes;
}

namespace {

struct TriggerCounter : Rules {
  int begins = 0, ends = 0;
  bool pierce(EntityId, const LineRef& line) override { return line.tag == 1 || line.kind == LineKind::Warp; }
  void beginContact(const Contact& c) override { begins += c.line.tag == 1; }
  void endContact(const Contact& c) override { ends += c.line.tag == 1; }
};

// Two faces of a cube (edge L = 10 m): face A's right edge is face B's bottom edge, turned a quarter.
// A has a floor; B has the floor's continuation and a wall 0.1 m past the edge. Driven right, the
// box crosses 0.1 m onto B and is held in the corner the floor (on A) and the wall (on B) make.
Outcome runWarpCorner(double upm) {
  const auto t0 = std::chrono::steady_clock::now();
  const int32_t L = unitsFromMetres(10, upm), wall = unitsFromMetres(0.1, upm), half = unitsFromMetres(0.25, upm);
  World world;
  MapPart& a = world.createMapPart(1);
  MapPart& b = world.createMapPart(2);
  a.line({0, 0}, {L, 0});
  a.warp({L, 0}, {L, L}, 2, {L, 0}, {0, 0});
  b.warp({0, 0}, {L, 0}, 1, {L, L}, {L, 0});
  b.line({L, 0}, {L, L});        // A's floor continued onto B
  b.line({0, wall}, {L, wall});  // the wall on B
  a.setGravity({0, q16FromAcceleration(-9.81, upm, 60)});
  b.setGravity({0, q16FromAcceleration(-9.81, upm, 60)});
  a.initialize();
  b.initialize();
  const EntityId body = world.createEntity(Convex::box(half, half));
  world.insert(body, 1, {L - unitsFromMetres(1, upm), half}, 0);
  const int64_t vx = q16FromSpeed(2, upm, 60);
  Outcome out;
  Vec2 settled{}, last = world.entity(body).instance(0).position;
  for (int f = 1; f <= 10000; ++f) {
    world.setVelocity(body, {vx, world.entity(body).velocity().y});
    world.solve();
    out.overlapFrames += world.countOverlaps() > 0;
    const EntityView e = world.entity(body);
    const std::optional<InstanceView> onA = e.instanceIn(1);
    if (!onA || onA->position.x > L + wall - half || onA->position.y < half) ++out.tunnelFrames;
    if (onA && onA->position != last) out.lastMoveFrame = f, last = onA->position;
    if (f == 2000 && onA) settled = onA->position;
    if (f > 2000 && onA)
      out.drift = std::max(out.drift, std::hypot(onA->position.x - settled.x, onA->position.y - settled.y) / upm);
    if (f > 2000 && e.instanceCount() != 2) ++out.stuckFrames;  // the straddle must hold steadily
  }
  const std::optional<InstanceView> onA = world.entity(body).instanceIn(1);
  if (onA) out.final = {onA->position.x / upm, onA->position.y / upm, 0};
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace

void OutcomeTracker::frame(int f, const Pose& p) {
  if (!scene_.allowed(p)) ++out_.tunnelFrames;
  if (scene_.minSpeedX > 0 && (p.x - previous_.x) * scene_.hz < 0.5 * scene_.minSpeedX) ++out_.stuckFrames;
  if (std::hypot(p.x - previous_.x, p.y - previous_.y) > 1e-9 || p.angle != previous_.angle) out_.lastMoveFrame = f;
  if (f == scene_.settleFrames) settled_ = p;
  if (scene_.settleFrames >= 0 && f > scene_.settleFrames)
    out_.drift = std::max(out_.drift, std::hypot(p.x - settled_.x, p.y - settled_.y));
  previous_ = p;
}

Outcome OutcomeTracker::finish() {
  out_.final = previous_;
  out_.missedTarget = !std::isnan(scene_.targetX) && std::fabs(out_.final.x - scene_.targetX) > 0.01;
  return out_;
}

int64_t extentUnits(const Scene& s, double upm) {
  const double travel = std::hypot(s.vx, s.vy) * s.frames / s.hz;
  double m = std::max(std::fabs(s.start.x), std::fabs(s.start.y)) + travel + 20;
  for (const auto* list : {&s.solids, &s.triggers})
    for (const Seg& g : *list)
      for (const double v : g) m = std::max(m, std::fabs(v));
  return static_cast<int64_t>(std::ceil(m * upm)) + 16;
}

Outcome runPlaton(const Scene& scene, double upm, int64_t offsetUnits) {
  if (scene.platonOnly) return scene.platonOnly(upm);
  const auto t0 = std::chrono::steady_clock::now();
  auto at = [&](double x, double y) {
    return Vec2{static_cast<int32_t>(unitsFromMetres(x, upm) + offsetUnits),
                static_cast<int32_t>(unitsFromMetres(y, upm) + offsetUnits)};
  };
  World world;
  MapPart& part = world.createMapPart(1);
  for (const Seg& g : scene.solids) part.line(at(g[0], g[1]), at(g[2], g[3]));
  for (const Seg& g : scene.triggers) part.line(at(g[0], g[1]), at(g[2], g[3]), 1);
  part.setGravity(
      {q16FromAcceleration(scene.gravityX, upm, scene.hz), q16FromAcceleration(scene.gravityY, upm, scene.hz)});
  part.initialize();
  TriggerCounter counter;
  world.setRules(&counter);
  std::vector<Vec2> shape;
  for (const Point& p : scene.shape) shape.push_back({unitsFromMetres(p[0], upm), unitsFromMetres(p[1], upm)});
  const EntityId body = world.createEntity(Convex(convexHull(shape)));
  world.insert(body, 1, at(scene.start.x, scene.start.y), 0);
  const int64_t vx = q16FromSpeed(scene.vx, upm, scene.hz);
  world.setVelocity(body, {vx, q16FromSpeed(scene.vy, upm, scene.hz)});
  world.setAngularVelocity(body, static_cast<int32_t>(std::llround(scene.spin / scene.hz * 4294967296.0 / (2 * kPi))));
  const bool checkEveryFrame = scene.frames <= 100000;
  auto pose = [&] {
    const InstanceView inst = world.entity(body).instance(0);
    return Pose{static_cast<double>(inst.position.x - offsetUnits) / upm,
                static_cast<double>(inst.position.y - offsetUnits) / upm,
                world.entity(body).angle() * 2 * kPi / 4294967296.0};
  };
  OutcomeTracker track(scene, pose());
  for (int f = 1; f <= scene.frames; ++f) {
    if (scene.drive) world.setVelocity(body, {vx, world.entity(body).velocity().y});
    world.solve();
    if (checkEveryFrame || f == scene.frames) track.outcome().overlapFrames += world.countOverlaps() > 0;
    track.frame(f, pose());
  }
  Outcome out = track.finish();
  out.triggerBegins = counter.begins;
  out.triggerEnds = counter.ends;
  out.missedEvents =
      std::max(0, scene.expectedCrossings - counter.begins) + std::max(0, scene.expectedCrossings - counter.ends);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace platon::testing::scenes
