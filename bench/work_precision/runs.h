// Running a scene in one engine at one setting: the trajectory and its measurements (untimed),
// and timed samples of the frame loop alone.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scenes.h"

namespace platon::bench::precision {

using MakeWorld = std::function<std::unique_ptr<PeerWorld>()>;

// One engine at one setting and step rate, e.g. Box2D v8p3 at 60 Hz.
struct Engine {
  std::string engine;   // "Platon", "Box2D 2.4.1", "Chipmunk 7.0.3"
  std::string setting;  // "1024u/m", "v8p3", "it10"
  double hz = 60;
  MakeWorld make;
  double quantum = 0;  // position rounding (Platon: one unit), metres
  bool usual = false;  // the engine's usual setting at 60 Hz
};

struct Row {
  std::string engine, setting, scene;
  double dt = 0;
  bool usual = false;
  double error = 0;                // metres, against the answer for the engine's own resting gap
  double extra = 0;                // Score::extra (NaN when the scene has none)
  double penetration = 0;          // deepest overlap of any line, metres, over all frames
  double gap = 0;                  // to the nearest line at the end, metres (NaN without lines)
  double restGap = 0;              // the engine's own resting gap, metres
  long stuck = 0;                  // frames a runner advanced by less than half its speed
  size_t overlaps = 0;             // Platon: World::countOverlaps() summed over every frame
  std::vector<double> runtimes{};  // seconds per run of the scene, one per timed sample
  double median() const;
  double low() const;
  double high() const;
};

// The engine's own resting gap (scenes.h: settleOnFloor).
double restingGap(const Engine& e);

// Builds the scene for the engine's gap, runs it once untimed and measures it.
Row measure(const Engine& e, const SceneSpec& spec, double gap);

// Times the frame loop: `repeats` fresh worlds (built untimed) run the scene; seconds per run.
double timeScene(const Engine& e, const Scene& scene, int repeats);

}  // namespace platon::bench::precision
