// One entity patrolling maps of 10^2, 10^4 and 10^6 segments of constant local density, in Platon
// and in Box2D 2.4.1 built two ways: as a Box2D user builds a level (each room's outline one
// b2ChainShape loop, each platform a b2PolygonShape box) and as bare two-sided b2EdgeShape
// fixtures, one per segment. Each map is built in forked processes of its own, so the RSS delta
// measures that engine alone, in the order a loader meets the pieces (room by room) and shuffled;
// the patrols are then timed side by side, every case in turn, several runs.
//
// The map is a block of identical-size rooms (24 x 8 m, 100 segments each: a rolling floor, walls,
// a ceiling and 14 box platforms), so a bigger map covers a bigger area at the same density. Each
// room's layout depends only on its index; the entity patrols room 0, which is the same in every map
// and closed, so the motion is the same whatever the map's size.
//
// Usage: map_scaling [--quick] [--frames=N] [--runs=N]
#include <algorithm>
#include <box2d/box2d.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "platon/physics/world.h"
#include "platon/testing/rng.h"
#include "spread.h"

namespace {

using namespace platon::physics;
using platon::bench::Spread;
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

// ---- The map -------------------------------------------------------------------------------------

// A room: its outline (floor left to right, right wall, ceiling, left wall: counter-clockwise, the
// room inside) and its platforms (boxes, corners counter-clockwise).
struct Room {
  std::vector<Vec2> outline;
  std::vector<std::array<Vec2, 4>> platforms;
};

Room makeRoom(int room, int columns) {
  Rng rng{0x9a7e0000ULL + static_cast<uint64_t>(room) * 0x100000001b3ULL};
  const int row = room / columns, column = room % columns;
  const double x0 = column * kPitchX, y0 = row * kPitchY;
  auto at = [&](double x, double y) { return units(x0 + x, y0 + y); };
  Room r;
  // Floor: a rolling polyline 0-0.45 m high, slopes under 15 degrees, so the entity runs over it.
  double h = 0.2;
  for (int i = 0; i <= kFloorSegments; ++i) {
    r.outline.push_back(at(i * kRoomW / kFloorSegments, h));
    h = std::clamp(h + rng.uniform(-0.15, 0.15), 0.0, 0.45);
  }
  // Walls and a ceiling close the room: neighbours never change the patrol in room 0.
  r.outline.insert(r.outline.end(), {at(kRoomW, kRoomH), at(kRoomW / 2, kRoomH), at(0, kRoomH)});
  // Platforms: closed boxes 1-3 m wide, bottoms 1.6-6 m up; the low ones are within a jump.
  for (int p = 0; p < kPlatforms; ++p) {
    const double w = rng.uniform(1, 3), x = rng.uniform(1, kRoomW - 1 - w);
    const double y = rng.uniform(1.6, 6), t = rng.uniform(0.2, 0.4);
    r.platforms.push_back({at(x, y), at(x + w, y), at(x + w, y + t), at(x, y + t)});
  }
  return r;
}

// Rooms laid out in a roughly square block, in the order a loader meets them (row by row).
std::vector<Room> makeMap(int rooms) {
  const int columns = std::max(1, static_cast<int>(std::lround(std::sqrt(rooms * kPitchY / kPitchX))));
  std::vector<Room> out;
  out.reserve(static_cast<size_t>(rooms));
  for (int r = 0; r < rooms; ++r) out.push_back(makeRoom(r, columns));
  return out;
}

// Every segment: the outline's and the platforms' sides.
std::vector<Segment> segmentsOf(const std::vector<Room>& rooms) {
  std::vector<Segment> out;
  out.reserve(rooms.size() * kSegmentsPerRoom);
  for (const Room& r : rooms) {
    for (size_t i = 0; i < r.outline.size(); ++i) out.push_back({r.outline[i], r.outline[(i + 1) % r.outline.size()]});
    for (const auto& p : r.platforms)
      for (size_t i = 0; i < 4; ++i) out.push_back({p[i], p[(i + 1) % 4]});
  }
  return out;
}

enum class Engine { Platon, Box2DChains, Box2DEdges };
const char* nameOf(Engine e) {
  return e == Engine::Platon ? "Platon" : e == Engine::Box2DChains ? "Box2D chains" : "Box2D edges";
}

// ---- The patrol ------------------------------------------------------------------------------------

// The same commands for every engine: run at kSpeed, turn at the patrol ends, jump every second.
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
  double addMs = 0;      // Platon: MapPart::lines(); Box2D: CreateFixture calls
  double buildMs = 0;    // Platon: MapPart::initialize(); Box2D: first Step's pair search (dt = 0)
  double ownBytes = -1;  // Platon: MapPart::memoryBytes(); Box2D: not reported
  double rssBytes = 0;   // RSS after building minus before, in a fresh process
  double totalMs() const { return addMs + buildMs; }
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
  Build build(const std::vector<Room>& rooms, bool shuffled) {
    std::vector<Segment> segments = segmentsOf(rooms);
    if (shuffled) std::shuffle(segments.begin(), segments.end(), std::mt19937_64(7));
    Build b;
    MapPart& part = world_.createMapPart(1);
    auto t0 = Clock::now();
    part.lines(segments);  // a loader hands over the lines it has read, in bulk
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
  explicit Box2DMap(Engine style) : style_(style) {}

  Build build(const std::vector<Room>& rooms, bool shuffled) {
    Build b;
    const b2BodyDef groundDef;
    b2Body* ground = world_.CreateBody(&groundDef);
    auto t0 = Clock::now();
    if (style_ == Engine::Box2DEdges) {
      std::vector<Segment> segments = segmentsOf(rooms);
      if (shuffled) std::shuffle(segments.begin(), segments.end(), std::mt19937_64(7));
      t0 = Clock::now();
      for (const Segment& s : segments) {
        b2EdgeShape edge;
        edge.SetTwoSided(metres(s.a), metres(s.b));  // Platon's lines block from both sides
        ground->CreateFixture(&edge, 0.0f);
      }
    } else {
      // A room's outline is one chain, wound clockwise: Box2D's chains collide on their right side,
      // here the inside of the room. A platform is a box. Shuffled: the fixtures' order.
      std::vector<std::pair<size_t, int>> pieces;  // room, -1 for its outline or the platform index
      for (size_t r = 0; r < rooms.size(); ++r)
        for (int p = -1; p < kPlatforms; ++p) pieces.push_back({r, p});
      if (shuffled) std::shuffle(pieces.begin(), pieces.end(), std::mt19937_64(7));
      std::vector<b2Vec2> loop;
      t0 = Clock::now();
      for (const auto& [r, p] : pieces) {
        if (p < 0) {
          loop.clear();
          for (auto v = rooms[r].outline.rbegin(); v != rooms[r].outline.rend(); ++v) loop.push_back(metres(*v));
          b2ChainShape chain;
          chain.CreateLoop(loop.data(), static_cast<int32>(loop.size()));
          ground->CreateFixture(&chain, 0.0f);
        } else {
          b2Vec2 corners[4];
          for (int k = 0; k < 4; ++k)
            corners[k] = metres(rooms[r].platforms[static_cast<size_t>(p)][static_cast<size_t>(k)]);
          b2PolygonShape box;
          box.Set(corners, 4);
          ground->CreateFixture(&box, 0.0f);
        }
      }
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
  Engine style_;
  b2World world_{{0, static_cast<float>(-kGravity)}};
};

// ---- Measuring ---------------------------------------------------------------------------------------

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

struct Case {
  int segments;
  Engine engine;
  bool shuffled;
  std::vector<Build> builds{};     // one per run, each in a fresh process, as a game loads a level
  std::vector<double> patrolNs{};  // ns per frame, one per run
  Motion motion{};                 // the last patrol
  Spread buildMs() const {
    std::vector<double> v;
    for (const Build& b : builds) v.push_back(b.totalMs());
    return Spread::of(v);
  }
  double rssBytes() const {
    std::vector<double> v;
    for (const Build& b : builds) v.push_back(b.rssBytes);
    return Spread::of(v).median;
  }
};

Build buildOnce(const Case& c, const std::vector<Room>& rooms) {
  return inChild([&] {
    const double rss0 = rssBytes();
    Build r;
    if (c.engine == Engine::Platon) {
      PlatonMap map;
      r = map.build(rooms, c.shuffled);
      r.rssBytes = rssBytes() - rss0;
    } else {
      Box2DMap map(c.engine);
      r = map.build(rooms, c.shuffled);
      r.rssBytes = rssBytes() - rss0;
    }
    return r;
  });
}

void printRow(const Case& c) {
  char own[32] = "-", overlaps[32] = "-";
  if (c.builds.front().ownBytes >= 0) std::snprintf(own, sizeof own, "%.2f", c.builds.front().ownBytes / 1e6);
  if (c.motion.overlaps >= 0) std::snprintf(overlaps, sizeof overlaps, "%ld", c.motion.overlaps);
  std::printf("%9d %-13s %-9s %26s %8s %8.2f %24s %7.1f %7.2f,%5.2f %6ld %8s\n", c.segments, nameOf(c.engine),
              c.shuffled ? "shuffled" : "ordered", c.buildMs().show("%.2f").c_str(), own, c.rssBytes() / 1e6,
              Spread::of(c.patrolNs).show().c_str(), c.motion.travelled, c.motion.finalX, c.motion.finalY,
              c.motion.stuckFrames, overlaps);
}

const Case& find(const std::vector<Case>& cases, int segments, Engine e, bool shuffled) {
  for (const Case& c : cases)
    if (c.segments == segments && c.engine == e && c.shuffled == shuffled) return c;
  std::abort();
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  int frames = 10000, runs = 5;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0)
      quick = true, frames = 600, runs = 2;
    else if (std::strncmp(argv[i], "--frames=", 9) == 0)
      frames = std::max(1, std::atoi(argv[i] + 9));
    else if (std::strncmp(argv[i], "--runs=", 7) == 0)
      runs = std::max(1, std::atoi(argv[i] + 7));
    else
      return std::fprintf(stderr, "usage: map_scaling [--quick] [--frames=N] [--runs=N]\n"), 2;
  }
  const std::vector<int> sizes = quick ? std::vector<int>{100, 10000} : std::vector<int>{100, 10000, 1000000};
  std::printf(
      "Map scaling: rooms of %gx%g m with %d segments each (rolling floor, walls, ceiling, %d box "
      "platforms),\n%d units per metre; one octagon (circumradius %g m) patrols room 0 at %g m/s, "
      "jumping every %d frames, gravity %g m/s^2, %d frames at %g Hz\n",
      kRoomW, kRoomH, kSegmentsPerRoom, kPlatforms, kUnitsPerMetre, kRadius, kSpeed, kJumpEvery, kGravity, frames, kHz);
  std::printf(
      "Platon: MapPart::lines() with every segment, then initialize(). Box2D chains: each room's outline one "
      "b2ChainShape loop, each platform a b2PolygonShape (as a Box2D user builds a level); Box2D edges: one "
      "two-sided b2EdgeShape per segment. Box2D's build: CreateFixture calls plus the first Step's pair "
      "search; Step(1/60, 8, 3) per frame.\nordered: the pieces room by room, as a loader meets them; "
      "shuffled: in random order. Each build in a fresh process: ms median (min-max) over %d builds, RSS "
      "delta (median). ns/frame: median (min-max) over %d patrols by a fresh entity, every case in turn.\n"
      "moved / final / stuck / overlaps: the last patrol (overlaps = World::countOverlaps() after its last "
      "frame)\n\n",
      runs, runs);

  std::vector<Case> cases;
  for (const int segments : sizes)
    for (const bool shuffled : {false, true})
      for (const Engine e : {Engine::Platon, Engine::Box2DChains, Engine::Box2DEdges})
        cases.push_back({segments, e, shuffled});
  // Builds: every case once per run, in turn.
  for (int run = 0; run < runs; ++run)
    for (const int segments : sizes) {
      const std::vector<Room> rooms = makeMap(segments / kSegmentsPerRoom);
      for (Case& c : cases)
        if (c.segments == segments) c.builds.push_back(buildOnce(c, rooms));
    }
  // Patrols: every map built once here, then patrolled in turn.
  std::vector<std::unique_ptr<PlatonMap>> platonMaps(cases.size());
  std::vector<std::unique_ptr<Box2DMap>> box2dMaps(cases.size());
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::vector<Room> rooms = makeMap(cases[i].segments / kSegmentsPerRoom);
    if (cases[i].engine == Engine::Platon)
      (platonMaps[i] = std::make_unique<PlatonMap>())->build(rooms, cases[i].shuffled);
    else
      (box2dMaps[i] = std::make_unique<Box2DMap>(cases[i].engine))->build(rooms, cases[i].shuffled);
  }
  for (int run = 0; run < runs; ++run)
    for (size_t i = 0; i < cases.size(); ++i) {
      cases[i].motion = platonMaps[i] ? platonMaps[i]->patrol(frames) : box2dMaps[i]->patrol(frames);
      cases[i].patrolNs.push_back(cases[i].motion.nsPerFrame);
    }

  std::printf("%9s %-13s %-9s %26s %8s %8s %24s %7s %13s %6s %8s\n", "segments", "engine", "order", "build ms",
              "own MB", "RSS MB", "ns/frame", "moved m", "final x,y m", "stuck", "overlaps");
  for (const Case& c : cases) printRow(c);

  PlatonMap small;
  small.build(makeMap(sizes.front() / kSegmentsPerRoom), false);
  const Motion checked = small.patrol(frames, true);
  std::printf(
      "\n%d-segment map, World::countOverlaps() after every frame: %ld overlaps in %d frames "
      "(final position %.3f, %.3f m)\n",
      sizes.front(), checked.overlaps, frames, checked.finalX, checked.finalY);

  // The goals, against the Box2D a user writes (chains) and against bare edges; run i of one case
  // against run i of the other.
  const int largest = sizes.back();
  const Case &p0 = find(cases, sizes.front(), Engine::Platon, false), &pN = find(cases, largest, Engine::Platon, false);
  const size_t n = static_cast<size_t>(runs);
  std::printf("\nRatios (medians; in brackets the runs that met the goal)\n");
  std::printf("  Platon ns/frame, %d vs %d segments:               %6.2f  (goal <= 1.5: %s)\n", largest, sizes.front(),
              Spread::of(pN.patrolNs).median / Spread::of(p0.patrolNs).median,
              platon::bench::runsMet(n, [&](size_t i) { return pN.patrolNs[i] <= 1.5 * p0.patrolNs[i]; }).c_str());
  for (const Engine peer : {Engine::Box2DChains, Engine::Box2DEdges}) {
    const char* who = nameOf(peer);
    for (const int segments : sizes) {
      const Case &p = find(cases, segments, Engine::Platon, false), &b = find(cases, segments, peer, false);
      std::printf("  Platon frame / %s step, %7d segments:  %6.3f  (goal <= 0.5: %s)\n", who, segments,
                  Spread::of(p.patrolNs).median / Spread::of(b.patrolNs).median,
                  platon::bench::runsMet(n, [&](size_t i) { return p.patrolNs[i] <= 0.5 * b.patrolNs[i]; }).c_str());
    }
    for (const bool shuffled : {false, true}) {
      const Case &p = find(cases, largest, Engine::Platon, shuffled), &b = find(cases, largest, peer, shuffled);
      std::printf("  %s build / Platon build, %s:           %6.1f  (goal >= 10: %s)\n", who,
                  shuffled ? "shuffled" : "ordered ", b.buildMs().median / p.buildMs().median,
                  platon::bench::runsMet(n, [&](size_t i) {
                    return b.builds[i].totalMs() >= 10 * p.builds[i].totalMs();
                  }).c_str());
      std::printf("  Platon memory / %s memory (RSS), %s:   %6.3f  (goal <= 0.5: %s)\n", who,
                  shuffled ? "shuffled" : "ordered ", p.rssBytes() / b.rssBytes(),
                  platon::bench::runsMet(n, [&](size_t i) {
                    return p.builds[i].rssBytes <= 0.5 * b.builds[i].rssBytes;
                  }).c_str());
    }
  }
  std::printf(
      "  Insertion order, %d segments: shuffled / ordered build time: Platon %.2f, Box2D chains %.2f, Box2D "
      "edges %.2f\n",
      largest,
      find(cases, largest, Engine::Platon, true).buildMs().median /
          find(cases, largest, Engine::Platon, false).buildMs().median,
      find(cases, largest, Engine::Box2DChains, true).buildMs().median /
          find(cases, largest, Engine::Box2DChains, false).buildMs().median,
      find(cases, largest, Engine::Box2DEdges, true).buildMs().median /
          find(cases, largest, Engine::Box2DEdges, false).buildMs().median);
}
