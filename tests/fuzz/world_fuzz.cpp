// libFuzzer target: whole worlds built from fuzzer bytes (rooms, random lines, a warp pair, random
// shapes, inserts, velocities, rotations, rules that pierce, bounce or throw), stepped frame by
// frame. After every frame: no instance overlaps a solid line, every instance lies in the
// coordinate range, velocities stay within setVelocity's limit, and no entity that had an
// instance lost them all. API calls may refuse bad input only with physics::Error; anything else
// is a bug.
//
// A failure re-runs the input with tracing on, which prints the calls as C++ (also available as
// PLATON_FUZZ_TRACE=1 world_fuzz <input file>).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fuzzer/FuzzedDataProvider.h>
#include <iostream>
#include <string>
#include <vector>

#include "platon/physics/world.h"

using namespace platon::physics;

namespace platon::physics {  // for the trace: values print as C++ initializers
std::ostream& operator<<(std::ostream& o, Vec2 v) { return o << "{" << v.x << ", " << v.y << "}"; }
std::ostream& operator<<(std::ostream& o, Vec2w v) { return o << "{" << v.x << ", " << v.y << "}"; }
}  // namespace platon::physics

namespace {

constexpr int kMaxFrames = 48;  // keeps one input well under 50 ms even with ASan
constexpr int64_t kLimit = kCoordLimit;

bool gTrace = std::getenv("PLATON_FUZZ_TRACE") != nullptr;
const uint8_t* gData = nullptr;
size_t gSize = 0;
void run(const uint8_t* data, size_t size);

template <class... T>
void trace(const T&... parts) {
  if (gTrace) (std::cerr << ... << parts) << "\n";
}

[[noreturn]] void fail(const std::string& what) {
  std::cerr << "world_fuzz FAILURE: " << what << "\n";
  if (!gTrace) {  // replay the same input, printing every call up to the failure
    gTrace = true;
    std::cerr << "replaying the input as C++ calls:\n";
    run(gData, gSize);
  }
  __builtin_trap();
}

// An API call that may refuse its input: only physics::Error is allowed.
template <class F>
bool attempt(const char* what, F&& call) {
  try {
    call();
    return true;
  } catch (const Error& e) {
    trace("  // ", what, " refused: ", e.what());
    return false;
  } catch (const std::exception& e) {
    fail(std::string(what) + " threw a non-Error exception: " + e.what());
  }
}

Vec2 clampToRange(Vec2w p) {
  return {static_cast<int32_t>(std::clamp(p.x, -kLimit, kLimit)),
          static_cast<int32_t>(std::clamp(p.y, -kLimit, kLimit))};
}

// Turns fuzzer bytes into values. Most are relative to the room's half-size, so that entities fit
// in it, lines cross it and motions reach its walls and warp edge at every scale; a few are
// absolute, up to past the API's limits (those must be refused with an Error).
class Decoder {
 public:
  Decoder(const uint8_t* data, size_t size) : in_(data, size) {}
  int64_t range(int64_t lo, int64_t hi) { return in_.ConsumeIntegralInRange(lo, hi); }
  bool flag() { return in_.ConsumeBool(); }
  bool oneIn(int n) { return range(1, n) == 1; }
  template <class T>
  T any() {
    return in_.ConsumeIntegral<T>();
  }
  int shift(int max) { return static_cast<int>(range(0, max)); }
  // A signed value at scale 2^shift plus fine noise: small and huge magnitudes are equally easy.
  int64_t scaled(int shift) { return (int64_t{any<int16_t>()} << shift) + any<int8_t>(); }

  int64_t half = 4;  // the room's half-size
  // Mostly inside the room, sometimes anywhere in range.
  Vec2 point() {
    if (oneIn(4)) {
      const int s = shift(16);
      return clampToRange({scaled(s), scaled(s)});
    }
    return {static_cast<int32_t>(range(-half, half)), static_cast<int32_t>(range(-half, half))};
  }
  // A Q16 rate up to the room's size per frame, scaled down by up to 2^maxDown; sometimes an
  // absolute one up to 2^(15 + 40 - 16) units, far past the limit of 2^30.
  Vec2w rateQ16(int maxDown) {
    if (oneIn(8)) {
      const int s = shift(40);
      return {scaled(s), scaled(s)};
    }
    const int down = shift(maxDown);
    return {range(-(half << 16), half << 16) >> down, range(-(half << 16), half << 16) >> down};
  }

 private:
  FuzzedDataProvider in_;
};

// Rules with decoded behaviour. pierce() depends only on the line, so it never changes while an
// instance overlaps the line.
class FuzzRules : public Rules {
 public:
  World* world = nullptr;
  uint8_t pierceTags = 0;  // bit k: solid lines with tag k pierce
  bool solidWarps = false, noSlide = false, keepNormalVelocity = false, bounce = false, throwOnContact = false;
  bool threw = false;
  Fraction restitution;  // 0: slide; else bounce, elastic at 1, gaining above

  bool pierce(EntityId, const LineRef& line) override {
    if (line.kind == LineKind::Warp) return !solidWarps;
    return line.index != kWorldBoundLine && ((pierceTags >> (line.tag & 7)) & 1);
  }
  void contact(const Contact& c, ContactResponse& response) override {
    response.slide = !noSlide;
    response.removeNormalVelocity = !keepNormalVelocity;
    response.restitution = restitution;
    if (bounce) {  // callbacks may set velocities
      const Vec2w v = world->entity(c.entity).velocity();
      world->setVelocity(c.entity, {-v.x, -v.y});
    }
    if (throwOnContact) {  // a script error: solve() finishes the frame, then rethrows it
      threw = true;
      throw Error("script error in contact");
    }
  }
};

constexpr MapPartId kParts[2] = {1, 2};

// Part 1 is the box (-R, -R)..(R, R); part 2 the same box turned by `turn`. With a warp, part 1's
// right edge is part 2's edge `edge`, following the convention of map_part.h.
void buildMap(Decoder& in, World& world, FuzzRules& rules) {
  const int partCount = in.flag() ? 2 : 1;
  const bool warp = partCount == 2 && in.flag();
  const int64_t half = in.half = std::clamp<int64_t>((int64_t{in.any<uint16_t>()} + 1) << in.shift(16), 4, kLimit);
  const Angle turn = in.flag() ? static_cast<Angle>(in.range(0, 3) * kQuarterTurn) : in.any<Angle>();
  const int64_t edge = in.range(0, 3);
  trace("World world;  // room half-size ", half, ", part 2 turned by ", turn);
  const Vec2w box[4] = {{-half, -half}, {half, -half}, {half, half}, {-half, half}};  // counter-clockwise
  Vec2 corners[2][4];
  for (int k = 0; k < 4; ++k) {
    corners[0][k] = clampToRange(box[k]);
    corners[1][k] = clampToRange(rotateWide(rotationOf(turn), box[k]));
  }
  for (int p = 0; p < partCount; ++p) {
    MapPart& part = world.createMapPart(kParts[p]);
    trace("MapPart& part", p + 1, " = world.createMapPart(", kParts[p], ");");
    const auto line = [&](Vec2 a, Vec2 b, uint32_t tag) {
      trace("part", p + 1, ".line(", a, ", ", b, ", ", tag, ");");
      attempt("line", [&] { part.line(a, b, tag); });
    };
    const bool walls = warp || in.flag();  // without walls the range's edge is the wall
    for (int k = 0; k < 4 && walls; ++k) {
      const Vec2 a = corners[p][k], b = corners[p][(k + 1) % 4];
      const bool isWarp = warp && k == (p == 0 ? 1 : edge);
      if (!isWarp) {
        line(a, b, 0);
        continue;
      }
      // Part 1's edge a -> b is part 2's edge q[edge + 1] -> q[edge]; part 2's warp runs back.
      const Vec2 t0 = p == 0 ? corners[1][(edge + 1) % 4] : corners[0][2];
      const Vec2 t1 = p == 0 ? corners[1][edge] : corners[0][1];
      trace("part", p + 1, ".warp(", a, ", ", b, ", ", kParts[1 - p], ", ", t0, ", ", t1, ");");
      attempt("warp", [&] { part.warp(a, b, kParts[1 - p], t0, t1); });
    }
    for (int64_t n = in.range(0, 12); n > 0; --n) {
      const Vec2 a = in.point();
      Vec2 b = in.point();
      switch (in.range(0, 3)) {  // the hard cases: axis-aligned, short, sharing an endpoint
        case 0:
          b.y = a.y;
          break;
        case 1:
          b = clampToRange(Vec2w{a.x + in.range(-8, 8), a.y + in.range(-8, 8)});
          break;
        case 2:
          if (!part.segments().empty()) b = part.segments().back().b;
          break;
        default:
          break;
      }
      line(a, b, static_cast<uint32_t>(in.range(0, 7)));
    }
    const Vec2w gravity = in.rateQ16(20);
    trace("part", p + 1, ".setGravity(", gravity, ");");
    attempt("setGravity", [&] { part.setGravity(gravity); });
  }
  for (int p = 0; p < partCount; ++p) {
    trace("part", p + 1, ".initialize();");
    attempt("initialize", [&] { world.mapPart(kParts[p]).initialize(); });
  }
  rules.pierceTags = in.any<uint8_t>();
  rules.solidWarps = in.oneIn(8);
  rules.noSlide = in.oneIn(4);
  rules.keepNormalVelocity = in.oneIn(4);
  rules.bounce = in.oneIn(4);
  rules.throwOnContact = in.oneIn(8);
  if (in.oneIn(3)) rules.restitution = {in.range(0, 5), in.range(1, 4)};
  // Before any insert: pierce() must not change while an instance overlaps the line.
  world.setRules(&rules);
  trace("world.setRules(&rules);  // pierceTags ", int{rules.pierceTags}, " solidWarps ", rules.solidWarps, " noSlide ",
        rules.noSlide, " keepNormalVelocity ", rules.keepNormalVelocity, " bounce ", rules.bounce, " throwOnContact ",
        rules.throwOnContact, " restitution ", rules.restitution.num, "/", rules.restitution.den);
}

std::vector<Vec2> decodeShape(Decoder& in) {
  const int64_t size = std::clamp<int64_t>(in.half >> in.range(1, 16), 1, kShapeLimit);
  if (in.oneIn(8)) {  // a regular polygon, up to the vertex limit
    const int n = static_cast<int>(in.range(3, kMaxConvexVertices));
    const auto radius = static_cast<int32_t>(in.range(1, size));
    std::vector<Vec2> out;
    attempt("Convex::regular", [&] {
      const Convex c = Convex::regular(n, radius);
      out.assign(c.vertices().begin(), c.vertices().end());
    });
    return out;
  }
  const bool absolute = in.oneIn(8);  // up to 2^30: past kShapeLimit, which must be refused
  const int shift = in.shift(15);
  std::vector<Vec2> points;
  for (int64_t n = in.range(3, 10); n > 0; --n) {
    const int64_t x = absolute ? in.scaled(shift) : in.range(-size, size);
    const int64_t y = absolute ? in.scaled(shift) : in.range(-size, size);
    points.push_back({static_cast<int32_t>(x), static_cast<int32_t>(y)});
  }
  return in.oneIn(8) ? points : convexHull(points);  // raw points test the validation
}

struct Scene {
  World& world;
  Decoder& in;
  std::vector<EntityId> ids;
  std::vector<PlatformId> platforms;

  EntityId pick() { return ids[in.range(0, static_cast<int64_t>(ids.size()) - 1)]; }
  MapPartId part() { return kParts[world.findMapPart(2) ? in.range(0, 1) : 0]; }
  std::string name(EntityId id) const { return "e" + std::to_string(id.index); }

  void insert(EntityId id) {
    const MapPartId p = part();
    const Vec2 origin = in.point();
    const Angle angle = in.any<Angle>();
    trace("world.insert(", name(id), ", ", p, ", ", origin, ", ", angle, ");");
    attempt("insert", [&] { world.insert(id, p, origin, angle); });
  }
  void setVelocity(EntityId id) {
    const Vec2w v = in.rateQ16(16);
    trace("world.setVelocity(", name(id), ", ", v, ");");
    attempt("setVelocity", [&] { world.setVelocity(id, v); });
  }
  // Rotation is swept in sub-steps of about 2 / sqrt(radius) radians (world_slide.cpp), each
  // costing about one vertex count of work; big turns of big shapes would make an input take
  // seconds. This caps a turn at about `work` vertex-steps.
  int64_t affordableTurn(EntityId id, int64_t turn, double work) const {
    if (!world.valid(id)) return turn;
    const Convex& shape = world.entity(id).shape();
    int64_t radius2 = 1;
    for (const Vec2 v : shape.vertices()) radius2 = std::max(radius2, dot(wide(v), wide(v)));
    const double steps = work / shape.size(),
                 radians = steps * 2.0 / std::sqrt(std::sqrt(static_cast<double>(radius2)));
    const auto most = static_cast<int64_t>(std::min(radians / (2 * 3.141592653589793) * 4294967296.0, 2147483647.0));
    return std::clamp(turn, -most, most);
  }
  void setAngularVelocity(EntityId id) {
    const int32_t w = static_cast<int32_t>(affordableTurn(id, in.scaled(in.shift(15)), 256));
    trace("world.setAngularVelocity(", name(id), ", ", w, ");");
    attempt("setAngularVelocity", [&] { world.setAngularVelocity(id, w); });
  }
  void rotate(EntityId id) {
    const Angle a = world.valid(id)
                        ? static_cast<Angle>(world.entity(id).angle() + affordableTurn(id, in.any<int32_t>(), 2048))
                        : in.any<Angle>();
    trace("world.rotate(", name(id), ", ", a, ");");
    attempt("rotate", [&] { world.rotate(id, a); });
  }
  void eraseOrInsert(EntityId id) {
    const MapPartId p = part();
    if (world.valid(id) && world.entity(id).instanceIn(p)) {
      trace("world.erase(", name(id), ", ", p, ");");
      attempt("erase", [&] { world.erase(id, p); });
    } else {
      insert(id);
    }
  }
  void destroy(EntityId id) {
    trace("world.destroyEntity(", name(id), ");");
    attempt("destroyEntity", [&] { world.destroyEntity(id); });
  }
  // A platform of one to three lines (solid or one-way) somewhere in a part, or a new motion for one.
  void platform() {
    if (!platforms.empty() && in.flag()) {
      const PlatformId p = platforms[in.range(0, static_cast<int64_t>(platforms.size()) - 1)];
      if (in.flag()) {  // a turn about a point, up to the largest a frame (and past it: refused)
        const Vec2 pivot = in.point();
        const int32_t spin =
            static_cast<int32_t>(in.range(-(int64_t{1} << 28) - 1, (int64_t{1} << 28) + 1) >> in.shift(20));
        trace("world.setPlatformSpin(p", p.index, ", ", pivot, ", ", spin, ");");
        attempt("setPlatformSpin", [&] { world.setPlatformSpin(p, pivot, spin); });
        return;
      }
      const Vec2 v{static_cast<int32_t>(in.range(-64, 64) << in.shift(8)),
                   static_cast<int32_t>(in.range(-64, 64) << in.shift(8))};
      trace("world.setPlatformMotion(p", p.index, ", ", v, ");");
      attempt("setPlatformMotion", [&] { world.setPlatformMotion(p, v); });
      return;
    }
    std::vector<PlatformLine> lines;
    for (int64_t n = in.range(1, 3); n > 0; --n)
      lines.push_back({{in.point(), in.point()}, 0, in.flag() ? LineKind::OneWay : LineKind::Solid});
    const MapPartId p = part();
    trace("// world.createPlatform(", p, ", ", lines.size(), " lines);");
    attempt("createPlatform", [&] { platforms.push_back(world.createPlatform(p, lines)); });
  }
  // Which entities meet which: two category bits, so solid pairs, overlap pairs and pushes all occur.
  void setFilter(EntityId id) {
    const EntityFilter f{1u << in.range(0, 1), static_cast<uint32_t>(in.range(0, 3)),
                         static_cast<uint32_t>(in.range(0, 3)), in.range(0, 1) == 1};
    trace("world.setFilter(", name(id), ", {", f.category, ", ", f.solidWith, ", ", f.overlapWith, ", ", f.pushable,
          "});");
    attempt("setFilter", [&] { world.setFilter(id, f); });  // refused if it would overlap
  }

  void createEntities() {
    for (int64_t n = in.range(1, 4); n > 0; --n) {
      const std::vector<Vec2> shape = decodeShape(in);
      if (gTrace) {
        std::cerr << "const EntityId e" << ids.size() << " = world.createEntity(Convex({";
        for (const Vec2 v : shape) std::cerr << v << ", ";
        std::cerr << "}));\n";
      }
      attempt("Convex", [&] { ids.push_back(world.createEntity(Convex(shape))); });
    }
    for (const EntityId id : ids) {
      insert(id);
      if (in.oneIn(4)) insert(id);  // a second instance, possibly in the other part
      setVelocity(id);
      if (in.flag()) setAngularVelocity(id);
      if (in.oneIn(4)) {
        trace("world.setGravityEnabled(", name(id), ", false);");
        world.setGravityEnabled(id, false);
      }
    }
  }

  void checkInvariants(int frame) {
    if (const size_t overlaps = world.countOverlaps(); overlaps != 0)
      fail("frame " + std::to_string(frame) + ": " + std::to_string(overlaps) + " instance/line overlaps");
    // Every velocity the world holds is one setVelocity would accept (at most 2^30 units a frame).
    const int64_t limitQ16 = int64_t{kMaxMove} << 16;
    for (const EntityId id : world.entities()) {
      const EntityView e = world.entity(id);
      if (std::max(std::abs(e.velocity().x), std::abs(e.velocity().y)) > limitQ16)
        fail("frame " + std::to_string(frame) + ": " + name(id) + " moves faster than setVelocity allows");
      for (const InstanceView inst : e.instances())
        for (const Vec2 v : inst.shape)
          if (std::max(std::abs(int64_t{inst.position.x} + v.x), std::abs(int64_t{inst.position.y} + v.y)) >
              kCoordLimit)
            fail("frame " + std::to_string(frame) + ": " + name(id) + " has a vertex out of range");
    }
  }

  void step(int frame, FuzzRules& rules) {
    std::vector<EntityId> placed;  // entities with an instance must keep one
    for (const EntityId id : world.entities())
      if (world.entity(id).inserted()) placed.push_back(id);
    rules.threw = false;
    trace("world.solve();  // frame ", frame);
    try {
      world.solve();
    } catch (const Error& e) {
      if (!rules.threw) fail(std::string("solve() threw by itself: ") + e.what());
      trace("  // solve() rethrew the rules' error");
    }
    checkInvariants(frame);
    for (const EntityId id : placed)
      if (!world.entity(id).inserted())
        fail("frame " + std::to_string(frame) + ": " + name(id) + " lost all its instances");
  }
};

void run(const uint8_t* data, size_t size) {
  Decoder in(data, size);
  World world;
  FuzzRules rules;
  rules.world = &world;
  Scene scene{world, in, {}, {}};
  try {
    buildMap(in, world, rules);
    scene.createEntities();
    if (scene.ids.empty()) return;
    scene.checkInvariants(0);
    const int frames = static_cast<int>(in.range(1, kMaxFrames));
    for (int frame = 1; frame <= frames; ++frame) {
      for (int64_t n = in.range(0, 3); n > 0; --n) {  // a few calls between frames
        const EntityId id = scene.pick();
        switch (in.range(0, 9)) {
          case 9:
            scene.platform();
            break;
          case 0:
          case 1:
            scene.setVelocity(id);
            break;
          case 8:
            scene.setFilter(id);
            break;
          case 2:
            scene.setAngularVelocity(id);
            break;
          case 3:
          case 4:
            scene.rotate(id);
            break;
          case 5:
          case 6:
            scene.eraseOrInsert(id);
            break;
          default:
            scene.destroy(id);
            break;
        }
      }
      scene.step(frame, rules);
    }
  } catch (const Error& e) {
    fail(std::string("an Error escaped a call that was not expected to refuse: ") + e.what());
  } catch (const std::exception& e) {
    fail(std::string("non-Error exception: ") + e.what());
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  gData = data, gSize = size;
  run(data, size);
  return 0;
}
