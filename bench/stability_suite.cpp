// The stiff and extreme scenes (tests/scenes/stability_scenes.h) in Platon, Box2D 2.4.1 and
// Chipmunk 7.0.3, side by side. The peers also run each scene 10^3, 10^5 and 10^6 m from the
// origin; Platon runs it at the origin and flush against the end of its coordinate range.
//   stability_suite [--markdown FILE] [--quick]
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "peers/peer.h"
#include "platon/physics/vec2.h"
#include "platon/testing/stability_scenes.h"

using namespace platon;
namespace scenes = platon::testing::scenes;
using scenes::Outcome;
using scenes::Scene;

namespace {

constexpr double kUnitsPerMetre = 1024;

Outcome runPeer(const Scene& s, bench::PeerWorld& world) {
  world.setGravity(s.gravityX, s.gravityY);
  for (const scenes::Seg& g : s.solids) world.addSegment(g[0], g[1], g[2], g[3]);
  for (const scenes::Seg& g : s.triggers) world.addSegment(g[0], g[1], g[2], g[3], true);
  const int body = world.addBody(s.shape, s.start.x, s.start.y, !s.rotates);
  world.setVelocity(body, s.vx, s.vy);
  if (s.spin != 0) world.setAngularVelocity(body, s.spin);
  const double dt = 1.0 / s.hz;
  const bench::Pose start = world.pose(body);
  scenes::OutcomeTracker track(s, {start.x, start.y, start.angle});
  double vy = s.vy, lastY = start.y;
  for (int f = 1; f <= s.frames; ++f) {
    if (s.drive) world.setVelocity(body, s.vx, vy);
    if (s.spin != 0 && s.drive) world.setAngularVelocity(body, s.spin);
    world.step(dt);
    const bench::Pose p = world.pose(body);
    vy = (p.y - lastY) / dt;  // the peers' own vertical motion, kept while driving
    lastY = p.y;
    if (s.frames <= 100000 || f == s.frames) {
      const double depth = bench::penetrationDepth(s.shape, p, s.solids);
      if (depth > 1e-9) {
        ++track.outcome().overlapFrames;
        track.outcome().maxPenetration = std::max(track.outcome().maxPenetration, depth);
      }
    }
    track.frame(f, {p.x, p.y, p.angle});
  }
  Outcome out = track.finish();
  out.triggerBegins = world.sensorBeginEvents();
  out.missedEvents = std::max(0, s.expectedCrossings - out.triggerBegins);
  return out;
}

// "ok" when perfect, else the failures that happened.
std::string summary(const Scene& s, const Outcome& o) {
  std::ostringstream t;
  auto add = [&](const std::string& part) { t << (t.tellp() > 0 ? ", " : "") << part; };
  char buf[96];
  if (o.overlapFrames > 0) {
    std::snprintf(buf, sizeof buf, "penetration %d fr (max %.3g mm)", o.overlapFrames, o.maxPenetration * 1e3);
    add(buf);
  }
  if (o.tunnelFrames > 0) add("tunnel " + std::to_string(o.tunnelFrames) + " fr");
  if (o.missedEvents > 0)
    add("missed " + std::to_string(o.missedEvents) + " of " + std::to_string(s.expectedCrossings) + " triggers");
  if (o.drift > 1e-9) {
    std::snprintf(buf, sizeof buf, "drift %.3g mm", o.drift * 1e3);
    add(buf);
  }
  if (o.stuckFrames > 0) add("stuck " + std::to_string(o.stuckFrames) + " fr");
  if (o.missedTarget) {
    std::snprintf(buf, sizeof buf, "ended %.4g m short", s.targetX - o.final.x);
    add(buf);
  }
  return t.tellp() > 0 ? t.str() : "ok";
}

}  // namespace

int main(int argc, char** argv) {
  const char* markdown = nullptr;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--markdown") == 0 && i + 1 < argc) {
      markdown = argv[++i];
    } else if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
    } else {
      std::fprintf(stderr, "usage: %s [--markdown FILE] [--quick]\n", argv[0]);
      return 2;
    }
  }
  const std::vector<double> offsets = {0, 1e3, 1e5, 1e6};
  std::ostringstream table;
  table << "| scene | what | Platon | Platon at 2^30 | Box2D 0 m | 10^3 m | 10^5 m | 10^6 m | Chipmunk 0 m | 10^3 m | "
           "10^5 m | 10^6 m |\n";
  table << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  const std::vector<Scene> base = scenes::stabilityScenes();
  for (size_t k = 0; k < base.size(); ++k) {
    const Scene& s = base[k];
    if (quick && s.frames > 100000) continue;
    std::fprintf(stderr, "%s...\n", s.name.c_str());
    table << "| " << s.name << " | " << s.what << " | " << summary(s, scenes::runPlaton(s, kUnitsPerMetre)) << " | ";
    if (s.platonOnly) {
      table << "n/a (one part) | n/a | n/a | n/a | n/a | n/a | n/a | n/a | n/a |\n";
      continue;
    }
    table << summary(
                 s, scenes::runPlaton(s, kUnitsPerMetre, physics::kCoordLimit - scenes::extentUnits(s, kUnitsPerMetre)))
          << " | ";
    for (const bool box2d : {true, false})
      for (const double offset : offsets) {
        const Scene moved = scenes::stabilityScenes(offset)[k];
        auto world = box2d ? bench::makeBox2D(8, 3) : bench::makeChipmunk(10);
        table << summary(moved, runPeer(moved, *world)) << " | ";
      }
    table << "\n";
  }
  std::printf("%s", table.str().c_str());
  if (markdown) {
    std::ofstream file(markdown);
    file << "<!-- generated by build/bench/stability_suite --markdown; do not edit -->\n"
         << "Outcomes per engine: \"ok\" means no penetration, no tunnel, no missed trigger, no drift at rest and no\n"
         << "stuck frame (fr = frames). Box2D 2.4.1: velocity/position iterations 8/3, 60 Hz. Chipmunk 7.0.3: 10\n"
         << "iterations, 60 Hz (Debian's build has its debug checks on). Platon: 1024 units per metre.\n\n"
         << table.str();
  }
  return 0;
}
