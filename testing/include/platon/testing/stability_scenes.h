// The stiff and extreme scenes, described once in SI units so that the ctest assertions (Platon)
// and the comparison table (Platon, Box2D, Chipmunk) run exactly the same thing.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace platon::testing::scenes {

using Point = std::array<double, 2>;
using Seg = std::array<double, 4>;  // x0 y0 x1 y1, metres

struct Pose {
  double x = 0, y = 0, angle = 0;
};

struct Scene {
  std::string name;
  std::string what;                   // one line for the table
  double gravityX = 0, gravityY = 0;  // m/s^2
  std::vector<Seg> solids;
  std::vector<Seg> triggers;  // pierceable lines whose crossings are counted
  std::vector<Point> shape;   // the body, counter-clockwise, relative to its origin
  Pose start;
  double vx = 0, vy = 0;  // m/s, set once (or every frame when `drive`)
  bool drive = false;     // keep setting (vx, vy-component-if-free) every frame
  double spin = 0;        // rad/s
  bool rotates = false;   // false: fixed rotation (the peers' bodies too)
  double hz = 60;
  int frames = 600;
  int expectedCrossings = 0;  // trigger lines crossed, counted begin + end
  // Where the body's origin is allowed to be (false = it went through a line: a tunnel).
  std::function<bool(const Pose&)> allowed;
  // For rest scenes: frames after which the body must not move any more (drift is measured after).
  // Long enough for every engine's own settling (Box2D pushes a body out onto its skin over about
  // 30 frames); the table shows when each one actually stopped.
  int settleFrames = -1;
  // For sliding scenes: the body should keep moving along x at least this fast (m/s).
  double minSpeedX = 0;
  // When set, the body must end with its origin within 1 cm of this x (it got where it was sent).
  double targetX = std::numeric_limits<double>::quiet_NaN();
  // Scenes only Platon can express (warps between map parts) run this instead; peers show n/a.
  std::function<struct Outcome(double unitsPerMetre)> platonOnly;
};

// Outcomes of one run, in metres where lengths.
struct Outcome {
  int overlapFrames = 0;  // frames with any overlap of a solid line's interior
  double maxPenetration = 0;
  int tunnelFrames = 0;   // frames with the origin outside `allowed`
  int triggerBegins = 0;  // begin events on trigger lines (the peers report these too)
  int triggerEnds = 0;
  int missedEvents = 0;       // expected crossings without a begin or an end
  double drift = 0;           // movement after settleFrames
  int lastMoveFrame = 0;      // the last frame on which the body moved (by more than 1 nm)
  int stuckFrames = 0;        // frames moving slower than minSpeedX
  bool missedTarget = false;  // ended away from targetX
  Pose final;
  double seconds = 0;  // wall time of the run
};

// Scores one run frame by frame, the same way for every engine: tunnels, stuck frames, drift after
// settling, and at the end whether the body got where it was sent.
class OutcomeTracker {
 public:
  OutcomeTracker(const Scene& scene, Pose start) : scene_(scene), previous_(start) {}
  void frame(int f, const Pose& p);
  Outcome& outcome() { return out_; }
  Outcome finish();

 private:
  const Scene& scene_;
  Pose previous_, settled_;
  Outcome out_;
};

// Largest |coordinate| a scene can reach (its lines, and the body's start plus its travel), in
// units at `unitsPerMetre`: how far it must stay from the end of the coordinate range.
int64_t extentUnits(const Scene& scene, double unitsPerMetre);

// The scenes of the stability suite. `offset` moves everything by (offset, offset) metres.
std::vector<Scene> stabilityScenes(double offset = 0);

// Runs a scene in Platon at `unitsPerMetre`; `offsetUnits` shifts it in whole units (the range-limit
// runs put it near 2^30).
Outcome runPlaton(const Scene& scene, double unitsPerMetre, int64_t offsetUnits = 0);

}  // namespace platon::testing::scenes
