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

// "ok" when perfect, else the failures that happened; for rest scenes, when the body stopped.
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
    const double shortBy = s.targetX - o.final.x;
    std::snprintf(buf, sizeof buf, "ended %.4g m %s", std::fabs(shortBy), shortBy > 0 ? "short" : "past the target");
    add(buf);
  }
  std::string out = t.tellp() > 0 ? t.str() : "ok";
  if (s.settleFrames >= 0 && o.drift <= 1e-9) out += " (still from fr " + std::to_string(o.lastMoveFrame) + ")";
  return out;
}

// How bad an outcome is, to pick a peer's worst offset: through-tunnelling first, then overlap,
// missed events, a missed target, drift, stuck frames.
double severity(const Outcome& o) {
  return o.tunnelFrames * 1e9 + o.overlapFrames * 1e6 + o.missedEvents * 1e4 + (o.missedTarget ? 1e3 : 0) +
         (o.drift > 1e-9 ? 1e2 : 0) + o.stuckFrames;
}

std::string offsetName(double offset) {
  if (offset == 0) return "0 m";
  char buf[32];
  std::snprintf(buf, sizeof buf, "10^%.0f m", std::log10(offset));
  return buf;
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
  std::ostringstream table, brief;
  table << "| scene | what | Platon | Platon at 2^30 | Box2D 0 m | 10^3 m | 10^5 m | 10^6 m | Chipmunk 0 m | 10^3 m | "
           "10^5 m | 10^6 m |\n";
  table << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  brief << "| scene | Platon (origin and 2^30) | Box2D at the origin | Box2D, worst offset | Chipmunk at the origin | "
           "Chipmunk, worst offset |\n|---|---|---|---|---|---|\n";
  const std::vector<Scene> base = scenes::stabilityScenes();
  for (size_t k = 0; k < base.size(); ++k) {
    const Scene& s = base[k];
    if (quick && s.frames > 100000) continue;
    std::fprintf(stderr, "%s...\n", s.name.c_str());
    const std::string platon = summary(s, scenes::runPlaton(s, kUnitsPerMetre));
    table << "| " << s.name << " | " << s.what << " | " << platon << " | ";
    brief << "| " << s.what << " | ";
    if (s.platonOnly) {
      table << "n/a (one part) | n/a | n/a | n/a | n/a | n/a | n/a | n/a | n/a |\n";
      brief << platon << " | n/a | n/a | n/a | n/a |\n";
      continue;
    }
    const std::string far =
        summary(s, scenes::runPlaton(s, kUnitsPerMetre, physics::kCoordLimit - scenes::extentUnits(s, kUnitsPerMetre)));
    table << far << " | ";
    brief << (platon == far ? platon : platon + "; at 2^30: " + far) << " | ";
    for (const bool box2d : {true, false}) {
      std::vector<Outcome> outcomes;
      std::vector<Scene> moved;
      for (const double offset : offsets) {
        moved.push_back(scenes::stabilityScenes(offset)[k]);
        auto world = box2d ? bench::makeBox2D(8, 3) : bench::makeChipmunk(10);
        outcomes.push_back(runPeer(moved.back(), *world));
        table << summary(moved.back(), outcomes.back()) << " | ";
      }
      size_t worst = 0;
      for (size_t i = 1; i < outcomes.size(); ++i)
        if (severity(outcomes[i]) > severity(outcomes[worst])) worst = i;
      brief << summary(s, outcomes[0]) << " | "
            << (severity(outcomes[worst]) == severity(outcomes[0])
                    ? std::string("the same at 10^3-10^6 m")
                    : summary(moved[worst], outcomes[worst]) + " (at " + offsetName(offsets[worst]) + ")")
            << " | ";
    }
    table << "\n";
    brief << "\n";
  }
  std::printf("%s\n%s", brief.str().c_str(), table.str().c_str());
  if (markdown) {
    std::ofstream file(markdown);
    file << "<!-- generated by build/bench/stability_suite --markdown; do not edit -->\n"
         << "Outcomes per engine: \"ok\" means no penetration, no tunnel, no missed trigger, no drift at rest and no\n"
         << "stuck frame (fr = frames); for bodies that come to rest, the frame from which they did not move again.\n"
         << "Box2D 2.4.1: velocity/position iterations 8/3, 60 Hz. Chipmunk 7.0.3: 10 iterations, 60 Hz. Both\n"
         << "as Debian builds them (assertions and debug checks on). Platon: 1024 units per metre. Drift is\n"
         << "measured after a settling window long enough for every engine (the rest scene's: 1,000 frames).\n\n"
         << "Each peer at the origin, and at its worst of 10^3, 10^5 and 10^6 m from it (where float coordinates\n"
         << "lose millimetres; Box2D's answer there is a small world and b2World::ShiftOrigin):\n\n"
         << brief.str() << "\nEvery offset:\n\n"
         << table.str();
  }
  return 0;
}
