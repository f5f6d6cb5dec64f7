// One entity patrolling maps of 10^2, 10^4 and 10^6 segments of constant local density: Platon
// (one MapPart) against Box2D 2.4.1 (static b2EdgeShape fixtures on one static body, one dynamic
// fixed-rotation body of the same shape). Each map is first built in a forked process of its own,
// so the RSS delta measures that engine alone; the patrols are then timed side by side.
//
// The map is a block of identical-size rooms (24 x 8 m, 100 segments each: a rolling floor, walls,
// a ceiling and 14 box platforms), so a bigger map covers a bigger area at the same density. Each
// room's layout depends only on its index; the entity patrols room 0, which is the same in every map
// and closed, so the motion is the same whatever the map's size.
//
// Usage: map_scaling [--quick] [--frames=N]
#include <algorithm>
#include <box2d/box2d.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "platon/physics/world.h"
#include "platon/testing/rng.h"

namespace {

using namespace platon::physics;
using Clock = std::chrono::steady_clock;

constexpr int kUnitsPerMetre = 1024;
constexpr double kHz = 60;

constexpr double kRoomW = 24, kRoomH = 8, kPitchX = 25, kPitchY = 9;  // metres
constexpr int kFloorSegments = 40, kPlatforms = 14;
constexpr int kSegmentsPerRoom = kFloorSegments + 4 + 4 * kPlatforms;  // + 2 walls, 2 ceiling pieces
static_assert(kSegmentsPerRoom == 100);

// The entity: a regular octagon, circumradius 0.3 m, running between x = 3 and 21 m of room 0 and
// jumping once a second. Gravity 25 m/s^2.
constexpr double kRadius = 0.3, kSpeed = 6, kJumpSpeed = 9, kGravity = 25;
constexpr double kLeft = 3, kRight = 21, kStartX = 3, kStartY = 1.0;
constexpr int kJumpEvery = 60;

double elapsedMs(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// Resident set size from /proc/self/statm (second field, in pages).
double rssBytes() {
  long pages = 0, resident = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
    std::fclose(f);
  }
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

using platon::testing::Rng;

Vec2 units(double xMetres, double yMetres) {
  return {static_cast<int32_t>(std::lround(xMetres * kUnitsPerMetre)),
          static_cast<int32_t>(std::lround(yMetres * kUnitsPerMetre))};
}

void addRoom(std::vector<Segment>& out, int room, int columns) {
  Rng rng{0x9a7e0000ULL + static_cast<uint64_t>(room) * 0x100000001b3ULL};
  const double x0 = (room % columns) * kPitchX, y0 = (room / columns) * kPitchY;
  auto at = [&](double x, double y) { return units(x0 + x, y0 + y); };
  // Floor: a rolling polyline 0-0.45 m high, slopes under 15 degrees, so the entity runs over it.
  std::vector<Vec2> floor;
  double h = 0.2;
  for (int i = 0; i <= kFloorSegments; ++i) {
    floor.push_back(at(i * kRoomW / kFloorSegments, h));
    h = std::clamp(h + rng.uniform(-0.15, 0.15), 0.0, 0.45);
  }
  for (int i = 0; i < kFloorSegments; ++i) out.push_back({floor[i], floor[i + 1]});
  // Walls and a ceiling close the room: neighbours never change the patrol in room 0.
  out.push_back({floor.front(), at(0, kRoomH)});
  out.push_back({floor.back(), at(kRoomW, kRoomH)});
  out.push_back({at(0, kRoomH), at(kRoomW / 2, kRoomH)});
  out.push_back({at(kRoomW / 2, kRoomH), at(kRoomW, kRoomH)});
  // Platforms: closed boxes 1-3 m wide, bottoms 1.6-6 m up; the low ones are within a jump.
  for (int p = 0; p < kPlatforms; ++p) {
    const double w = rng.uniform(1, 3), x = rng.uniform(1, kRoomW - 1 - w);
    const double y = rng.uniform(1.6, 6), t = rng.uniform(0.2, 0.4);
    const Vec2 a = at(x, y), b = at(x + w, y), c = at(x + w, y + t), d = at(x, y + t);
    out.insert(out.end(), {Segment{a, b}, Segment{b, c}, Segment{c, d}, Segment{d, a}});
  }
}

// Rooms laid out in a roughly square block.
std::vector<Segment> makeMap(int rooms) {
  const int columns = std::max(1, static_cast<int>(std::lround(std::sqrt(rooms * kPitchY / kPitchX))));
  std::vector<Segment> segments;
  segments.reserve(static_cast<size_t>(rooms) * kSegmentsPerRoom);
  for (int r = 0; r < rooms; ++r) addRoom(segments, r, columns);
  return segments;
}

// The same commands for both engines: run at kSpeed, turn at the patrol ends, jump every second.
struct Patrol {
  double direction = 1;
  double vx(double x) {
    if (x > kRight) direction = -1;
    if (x < kLeft) direction = 1;
    return direction * kSpeed;
  }
  static bool jumps(int frame) { return frame % kJumpEvery == kJumpEvery - 1; }
};

// Building a map: what each case reports back to the parent through a pipe (plain data).
struct Build {
  double addMs = 0;      // Platon: MapPart::line() calls; Box2D: CreateFixture calls
  double buildMs = 0;    // Platon: MapPart::initialize(); Box2D: first Step's pair search (dt = 0)
  double ownBytes = -1;  // Platon: MapPart::memoryBytes(); Box2D: not reported
  double rssBytes = 0;   // RSS after building minus before, in a fresh process
};

// One patrol.
struct Motion {
  double nsPerFrame = 0;
  double travelled = 0;  // metres of horizontal motion
  double finalX = 0, finalY = 0;
  long stuckFrames = 0;  // frames without any motion
  long overlaps = -1;    // Platon: World::countOverlaps() after the last frame (or summed over frames)
};

Convex entityShape() { return Convex::regular(8, static_cast<int32_t>(std::lround(kRadius * kUnitsPerMetre))); }

int64_t q16PerFrame(double metresPerSecond) { return std::llround(metresPerSecond * kUnitsPerMetre / kHz * 65536); }

b2Vec2 metres(Vec2 p) { return {static_cast<float>(p.x) / kUnitsPerMetre, static_cast<float>(p.y) / kUnitsPerMetre}; }

class PlatonMap {
 public:
  Build build(const std::vector<Segment>& segments) {
    Build b;
    MapPart& part = world_.createMapPart(1);
    auto t0 = Clock::now();
    part.reserve(segments.size());  // a loader knows its line count
    for (const Segment& s : segments) part.line(s.a, s.b);
    b.addMs = elapsedMs(t0);
    t0 = Clock::now();
    part.initialize();
    b.buildMs = elapsedMs(t0);
    b.ownBytes = static_cast<double>(part.memoryBytes());
    part.setGravity({0, -q16PerFrame(kGravity / kHz)});
    return b;
  }

  // A fresh entity patrols for `frames` frames and is destroyed again.
  Motion patrol(int frames, bool checkEveryFrame = false) {
    const EntityId e = world_.createEntity(entityShape());
    world_.insert(e, 1, units(kStartX, kStartY), 0);
    Patrol patrol;
    Motion m;
    Vec2 last = world_.entity(e).instance(0).position;
    long overlaps = 0;
    const auto t0 = Clock::now();
    for (int f = 0; f < frames; ++f) {
      const int64_t vy = Patrol::jumps(f) ? q16PerFrame(kJumpSpeed) : world_.entity(e).velocity().y;
      world_.setVelocity(e, {q16PerFrame(patrol.vx(static_cast<double>(last.x) / kUnitsPerMetre)), vy});
      world_.solve();
      const Vec2 p = world_.entity(e).instance(0).position;
      m.travelled += std::abs(p.x - last.x) / static_cast<double>(kUnitsPerMetre);
      m.stuckFrames += p == last;
      last = p;
      if (checkEveryFrame) overlaps += static_cast<long>(world_.countOverlaps());  // O(lines): small maps only
    }
    m.nsPerFrame = elapsedMs(t0) * 1e6 / frames;
    m.overlaps = checkEveryFrame ? overlaps : static_cast<long>(world_.countOverlaps());
    m.finalX = static_cast<double>(last.x) / kUnitsPerMetre;
    m.finalY = static_cast<double>(last.y) / kUnitsPerMetre;
    world_.destroyEntity(e);
    return m;
  }

 private:
  World world_;
};

class Box2DMap {
 public:
  Build build(const std::vector<Segment>& segments) {
    Build b;
    const b2BodyDef groundDef;
    b2Body* ground = world_.CreateBody(&groundDef);
    auto t0 = Clock::now();
    for (const Segment& s : segments) {
      b2EdgeShape edge;
      edge.SetTwoSided(metres(s.a), metres(s.b));  // Platon's lines block from both sides
      ground->CreateFixture(&edge, 0.0f);
    }
    b.addMs = elapsedMs(t0);
    // New fixtures wait in the broad-phase move buffer; the next Step searches pairs for all of them.
    t0 = Clock::now();
    world_.Step(0.0f, 8, 3);
    b.buildMs = elapsedMs(t0);
    return b;
  }

  // A fresh dynamic body patrols for `frames` steps and is destroyed again.
  Motion patrol(int frames, bool = false) {
    b2BodyDef bodyDef;
    bodyDef.type = b2_dynamicBody;
    bodyDef.fixedRotation = true;
    bodyDef.position = metres(units(kStartX, kStartY));
    b2Body* body = world_.CreateBody(&bodyDef);
    const Convex platonShape = entityShape();  // named: a temporary would die before the loop below
    std::vector<b2Vec2> octagon;
    for (const Vec2 v : platonShape.vertices()) octagon.push_back(metres(v));
    b2PolygonShape shape;
    shape.Set(octagon.data(), static_cast<int32>(octagon.size()));
    b2FixtureDef fixture;
    fixture.shape = &shape;
    fixture.density = 1;
    fixture.friction = 0;  // the velocity is set every step anyway
    body->CreateFixture(&fixture);

    Patrol patrol;
    Motion m;
    b2Vec2 last = body->GetPosition();
    const auto t0 = Clock::now();
    for (int f = 0; f < frames; ++f) {
      const float vy = Patrol::jumps(f) ? static_cast<float>(kJumpSpeed) : body->GetLinearVelocity().y;
      body->SetLinearVelocity({static_cast<float>(patrol.vx(last.x)), vy});
      world_.Step(static_cast<float>(1 / kHz), 8, 3);
      const b2Vec2 p = body->GetPosition();
      m.travelled += std::fabs(p.x - last.x);
      m.stuckFrames += p.x == last.x && p.y == last.y;
      last = p;
    }
    m.nsPerFrame = elapsedMs(t0) * 1e6 / frames;
    m.finalX = last.x;
    m.finalY = last.y;
    world_.DestroyBody(body);
    return m;
  }

 private:
  b2World world_{{0, static_cast<float>(-kGravity)}};
};

// Runs `f` in a forked child and returns its Build; a failing child ends the benchmark.
template <class F>
Build inChild(F f) {
  int fds[2];
  if (pipe(fds) != 0) std::abort();
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    try {
      const Build b = f();
      if (write(fds[1], &b, sizeof b) != static_cast<ssize_t>(sizeof b)) _exit(2);
      _exit(0);
    } catch (const std::exception& ex) {
      std::fprintf(stderr, "error: %s\n", ex.what());
      _exit(1);
    }
  }
  close(fds[1]);
  Build b;
  const bool complete = read(fds[0], &b, sizeof b) == static_cast<ssize_t>(sizeof b);
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!complete || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "benchmark case failed\n");
    std::exit(1);
  }
  return b;
}

// Each build runs in a fresh process, as a game loads a level: its RSS delta is that engine's alone,
// and its time includes the page faults of new memory. Times are the best of kBuilds such processes.
constexpr int kBuilds = 3;
// Patrols: each case is timed kPatrols times, the cases interleaved so that a busy neighbour on a
// shared machine slows all of them alike; the fastest patrol counts.
constexpr int kPatrols = 5;

template <class Map>
Build measureBuild(int rooms) {
  const std::vector<Segment> segments = makeMap(rooms);
  Build best;
  for (int i = 0; i < kBuilds; ++i) {
    const Build b = inChild([&] {
      const double rss0 = rssBytes();
      Map map;
      Build r = map.build(segments);
      r.rssBytes = rssBytes() - rss0;
      return r;
    });
    if (i == 0) best = b;
    best.addMs = std::min(best.addMs, b.addMs);
    best.buildMs = std::min(best.buildMs, b.buildMs);
  }
  return best;
}

struct Case {
  int segments;
  const char* engine;
  Build build;
  Motion motion;
};

void printRow(const Case& c) {
  char own[32] = "-", overlaps[32] = "-";
  if (c.build.ownBytes >= 0) std::snprintf(own, sizeof own, "%.2f", c.build.ownBytes / 1e6);
  if (c.motion.overlaps >= 0) std::snprintf(overlaps, sizeof overlaps, "%ld", c.motion.overlaps);
  std::printf("%9d %-7s %9.2f %9.2f %9.2f %9s %9.2f %9.0f %9.1f %7.2f,%5.2f %6ld %8s\n", c.segments, c.engine,
              c.build.addMs, c.build.buildMs, c.build.addMs + c.build.buildMs, own, c.build.rssBytes / 1e6,
              c.motion.nsPerFrame, c.motion.travelled, c.motion.finalX, c.motion.finalY, c.motion.stuckFrames,
              overlaps);
}

// Times the patrols of every case, interleaved; keeps the fastest and the last patrol's motion.
void measurePatrols(std::vector<Case>& platon, std::vector<Case>& box2d, int frames) {
  std::vector<std::unique_ptr<PlatonMap>> platonMaps;
  std::vector<std::unique_ptr<Box2DMap>> box2dMaps;
  for (const Case& c : platon) {
    const std::vector<Segment> segments = makeMap(c.segments / kSegmentsPerRoom);
    platonMaps.push_back(std::make_unique<PlatonMap>());
    platonMaps.back()->build(segments);
    box2dMaps.push_back(std::make_unique<Box2DMap>());
    box2dMaps.back()->build(segments);
  }
  auto keepFastest = [](Case& c, const Motion& m) {
    const double best = c.motion.nsPerFrame > 0 ? std::min(c.motion.nsPerFrame, m.nsPerFrame) : m.nsPerFrame;
    c.motion = m;
    c.motion.nsPerFrame = best;
  };
  for (int run = 0; run < kPatrols; ++run)
    for (size_t i = 0; i < platon.size(); ++i) {
      keepFastest(platon[i], platonMaps[i]->patrol(frames));
      keepFastest(box2d[i], box2dMaps[i]->patrol(frames));
    }
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  int frames = 10000;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0)
      quick = true, frames = 600;
    else if (std::strncmp(argv[i], "--frames=", 9) == 0)
      frames = std::max(1, std::atoi(argv[i] + 9));
    else
      return std::fprintf(stderr, "usage: map_scaling [--quick] [--frames=N]\n"), 2;
  }
  const std::vector<int> sizes = quick ? std::vector<int>{100, 10000} : std::vector<int>{100, 10000, 1000000};
  std::printf(
      "Map scaling: rooms of %gx%g m with %d segments each (rolling floor, walls, ceiling, %d box "
      "platforms),\n%d units per metre; one octagon (circumradius %g m) patrols room 0 at %g m/s, "
      "jumping every %d frames, gravity %g m/s^2, %d frames at %g Hz\n",
      kRoomW, kRoomH, kSegmentsPerRoom, kPlatforms, kUnitsPerMetre, kRadius, kSpeed, kJumpEvery, kGravity, frames, kHz);
  std::printf(
      "Platon add = MapPart::line() calls, build = initialize(), own = memoryBytes(); Box2D add = "
      "CreateFixture(b2EdgeShape) calls, build = first Step's pair search; Step(1/60, 8, 3) per frame.\n"
      "Builds: each in a fresh process, times best of %d, RSS delta of the first. ns/frame: best of %d "
      "patrols by a fresh entity, all cases interleaved;\nmoved / final / stuck / overlaps: the last "
      "patrol (overlaps = World::countOverlaps() after its last frame)\n",
      kBuilds, kPatrols);

  std::vector<Case> platon, box2d;
  for (const int segments : sizes) {
    const int rooms = segments / kSegmentsPerRoom;
    platon.push_back({segments, "Platon", measureBuild<PlatonMap>(rooms), {}});
    box2d.push_back({segments, "Box2D", measureBuild<Box2DMap>(rooms), {}});
  }
  measurePatrols(platon, box2d, frames);
  std::printf("%9s %-7s %9s %9s %9s %9s %9s %9s %9s %13s %6s %8s\n", "segments", "engine", "add ms", "build ms",
              "total ms", "own MB", "RSS MB", "ns/frame", "moved m", "final x,y m", "stuck", "overlaps");
  for (size_t i = 0; i < sizes.size(); ++i) printRow(platon[i]), printRow(box2d[i]);

  PlatonMap small;
  small.build(makeMap(sizes.front() / kSegmentsPerRoom));
  const Motion checked = small.patrol(frames, true);
  std::printf(
      "\n%d-segment map, World::countOverlaps() after every frame: %ld overlaps in %d frames "
      "(final position %.3f, %.3f m)\n",
      sizes.front(), checked.overlaps, frames, checked.finalX, checked.finalY);

  const Case &p0 = platon.front(), &pN = platon.back(), &bN = box2d.back();
  std::printf("\nRatios (largest map: %d segments)\n", pN.segments);
  std::printf("  Platon ns/frame, %d vs %d segments:        %6.2f  (goal <= 1.5)\n", pN.segments, p0.segments,
              pN.motion.nsPerFrame / p0.motion.nsPerFrame);
  for (size_t i = 0; i < sizes.size(); ++i)
    std::printf("  Platon frame / Box2D step, %7d segments:    %6.3f  (goal <= 0.5)\n", sizes[i],
                platon[i].motion.nsPerFrame / box2d[i].motion.nsPerFrame);
  const double platonBuild = pN.build.addMs + pN.build.buildMs, box2dBuild = bN.build.addMs + bN.build.buildMs;
  std::printf("  Box2D build / Platon build (add + build):        %6.1f  (goal >= 10)\n", box2dBuild / platonBuild);
  std::printf("  Box2D build (add + build) / Platon initialize(): %6.1f\n", box2dBuild / pN.build.buildMs);
  std::printf("  Platon memory / Box2D memory (RSS deltas):       %6.3f  (goal <= 0.5)\n",
              pN.build.rssBytes / bN.build.rssBytes);
  std::printf("  Platon memoryBytes() / Box2D RSS delta:          %6.3f\n", pN.build.ownBytes / bN.build.rssBytes);
}
