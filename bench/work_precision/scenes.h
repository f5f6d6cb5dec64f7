// The work-precision scenes: each has a closed-form answer and is run the same way in every engine
// through PeerWorld (peers/peer.h). All in SI: g = 9.81 m/s^2, a 0.5 m box that does not rotate.
//
// Scenes with contact are built for one engine's own resting gap (`gap`: how far above a floor the
// engine keeps a resting body; Box2D's skin, 0 for Platon and Chipmunk): the body starts at that
// engine's own rest pose and its answer is the closed form for its own contact height, so a skin
// is scored as a design and shown in its own column, not counted as error.
#pragma once
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "peers/peer.h"

namespace platon::bench::precision {

inline constexpr double kGravity = 9.81;  // m/s^2, downwards
inline constexpr double kHalf = 0.25;     // half the box's width

// A run's trajectory: poses[f] after f frames.
using Poses = std::vector<Pose>;

// How far a trajectory is from the answer (metres) and, for some scenes, a second figure:
// bounces: the k-th apex's time minus the answer's (s); landing: landing time minus the answer's.
struct Score {
  double error = 0;
  double extra = 0;
};

struct Scene {
  std::string name;
  Segments segments{};
  double x0 = 0, y0 = 0, vx0 = 0, vy0 = 0;  // the body's start, metres and m/s
  double gravity = kGravity;                // downwards, m/s^2
  double restitution = 0;
  double seconds = 0;  // simulated time, unless
  long frames = 0;     // a fixed frame count is given
  // Called before every step: what the game sets (a runner's velocity, a turned velocity).
  std::function<void(PeerWorld&, int body, long frame, double dt)> drive{};
  // Distance to the answer at time t, metres; the error is its largest value over all frames...
  std::function<double(const Pose&, double t)> distance{};
  // ...unless the whole trajectory is scored at once.
  std::function<Score(const Poses&, double dt)> score{};
  double runSpeed = 0;    // horizontal speed a runner should keep (stuck frames), m/s
  bool hasExtra = false;  // Score::extra means something

  long frameCount(double hz) const { return frames > 0 ? frames : std::lround(seconds * hz); }
};

struct SceneSpec {
  std::string name;
  std::string title;                      // one line for the tables and the plot
  std::function<Scene(double gap)> make;  // for an engine's own resting gap
};

Polygon box();

// Every scene, in report order. `restFrames`: frames of the rest scene (10^6; fewer with --quick).
std::vector<SceneSpec> allScenes(long restFrames);

// The scene an engine's own resting gap is measured in: the box placed exactly on a floor, left
// for 20 s. Its answer is that gap: the box's height above the exact contact at the end.
Scene settleOnFloor();

}  // namespace platon::bench::precision
