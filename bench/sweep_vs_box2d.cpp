// Sweep throughput and accuracy: Platon's exact integer sweep against Box2D 2.4.1 (b2ShapeCast and
// b2TimeOfImpact) on the same random convex-polygon-vs-segment queries, at growing distances from
// the origin.
//
// Reference: platon::physics::sweep, itself cross-checked against an independent long-double
// ray-cast time of impact. Each engine's stop position is where it would leave the polygon:
//   Platon  origin + enter * motion rounded to whole units the way World rounds a stopped move;
//   Box2D   its float position after the cast (p0 + lambda * r, or b2Sweep::GetTransform(t)).
// A query with no reported hit stops at the end of the motion. Box2D sees the same geometry
// converted to float metres, with the radius it gives every polygon and edge (b2_polygonRadius).
//
// Usage: sweep_vs_box2d [--quick]
#include <algorithm>
#include <array>
#include <box2d/b2_common.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_time_of_impact.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "platon/physics/convex.h"
#include "platon/physics/sweep.h"
#include "platon/testing/rng.h"

namespace {

using namespace platon::physics;
using ld = long double;

// A power of two, so unit coordinates convert exactly to float (up to 2^24 units) and long double.
constexpr int kUnitsPerMetre = 1024;
constexpr double kPi = 3.14159265358979323846;
// Overlap deeper than this (1 nm) counts as a penetration; long double noise is far below it.
constexpr ld kPenetrationMetres = 1e-9L;
// b2ShapeCast aims at this distance between the shapes' cores (sigma in b2_distance.cpp: the two
// radii minus one b2_polygonRadius); a start already closer counts as initial overlap, no hit.
constexpr float kCastTargetMetres = b2_polygonRadius;

using platon::testing::Rng;

struct Query {
  Vec2 origin;                    // polygon position, world units
  uint32_t first = 0, count = 0;  // its vertices in QuerySet::local and ::world
  Vec2w motion;
  Segment seg;
};

struct QuerySet {
  std::vector<Query> queries;
  std::vector<Vec2> local;  // polygon vertices relative to the origin (the entity's shape)
  std::vector<Vec2> world;  // origin + local: what Platon's sweep reads
  std::span<const Vec2> polygon(const Query& q) const { return {world.data() + q.first, q.count}; }
  std::span<const Vec2> shape(const Query& q) const { return {local.data() + q.first, q.count}; }
};

Vec2 unitsAt(double x, double y) {
  return {static_cast<int32_t>(std::llround(x)), static_cast<int32_t>(std::llround(y))};
}

// 3-8 vertices around the origin (so the origin is inside), 0.25-1 m across, squashed and turned.
std::vector<Vec2> randomShape(Rng& rng) {
  for (;;) {
    const int n = rng.between(3, 8);
    const double radius = rng.uniform(0.125, 0.5) * kUnitsPerMetre;
    const double squash = rng.uniform(0.5, 1.0), turn = rng.uniform(0, 2 * kPi);
    std::vector<Vec2> points;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * kPi * (k + rng.uniform(-0.2, 0.2)) / n;  // gaps stay below half a turn
      const double r = radius * rng.uniform(0.7, 1.0);
      const double x = r * std::cos(a), y = r * std::sin(a) * squash;
      points.push_back(unitsAt(x * std::cos(turn) - y * std::sin(turn), x * std::sin(turn) + y * std::cos(turn)));
    }
    std::vector<Vec2> hull = convexHull(std::move(points));
    if (hull.size() < 3) continue;
    (void)Convex(hull);  // throws if Platon would reject the shape
    return hull;
  }
}

// One query near `centre`: a segment, a point on it to aim at, and a motion of 0.1-10 m (log-uniform)
// that reaches the aim point at a fraction 0.2-1.25 of the motion, so most queries hit. Starts that
// already touch the segment are drawn again.
void addQuery(QuerySet& set, Rng& rng, double centre) {
  const std::vector<Vec2> shape = randomShape(rng);
  const double len = rng.uniform(0.5, 5.0) * kUnitsPerMetre, dir = rng.uniform(0, 2 * kPi);
  const double cx = centre + rng.uniform(-5, 5) * kUnitsPerMetre, cy = centre + rng.uniform(-5, 5) * kUnitsPerMetre;
  const Segment seg{unitsAt(cx - 0.5 * len * std::cos(dir), cy - 0.5 * len * std::sin(dir)),
                    unitsAt(cx + 0.5 * len * std::cos(dir), cy + 0.5 * len * std::sin(dir))};
  const double u = rng.uniform(0.05, 0.95);
  const double ax = seg.a.x + u * (seg.b.x - seg.a.x), ay = seg.a.y + u * (seg.b.y - seg.a.y);
  std::vector<Vec2> polygon(shape.size());
  for (;;) {
    const double dist = std::exp(rng.uniform(std::log(0.1), std::log(10.0))) * kUnitsPerMetre;
    const double heading = rng.uniform(0, 2 * kPi), reach = rng.uniform(0.2, 1.25);
    const Vec2 origin = unitsAt(ax - reach * dist * std::cos(heading), ay - reach * dist * std::sin(heading));
    for (size_t i = 0; i < shape.size(); ++i) polygon[i] = {origin.x + shape[i].x, origin.y + shape[i].y};
    if (touchesOrOverlaps(polygon, seg)) continue;
    const Vec2w motion{std::llround(dist * std::cos(heading)), std::llround(dist * std::sin(heading))};
    set.queries.push_back(
        {origin, static_cast<uint32_t>(set.local.size()), static_cast<uint32_t>(shape.size()), motion, seg});
    set.local.insert(set.local.end(), shape.begin(), shape.end());
    set.world.insert(set.world.end(), polygon.begin(), polygon.end());
    return;
  }
}

QuerySet makeQueries(size_t count, double offsetMetres) {
  Rng rng{0x5eed2024};  // the same shapes and motions at every offset
  QuerySet set;
  for (size_t i = 0; i < count; ++i) addQuery(set, rng, offsetMetres * kUnitsPerMetre);
  return set;
}

// ---- Box2D inputs: the same geometry in float metres --------------------------------------------

b2Vec2 metres(Vec2 p) { return {static_cast<float>(p.x) / kUnitsPerMetre, static_cast<float>(p.y) / kUnitsPerMetre}; }
b2Vec2 metres(Vec2w v) {
  return {static_cast<float>(static_cast<double>(v.x) / kUnitsPerMetre),
          static_cast<float>(static_cast<double>(v.y) / kUnitsPerMetre)};
}

// The edge is proxy A on a static body at the origin (world-coordinate vertices, as level geometry
// usually is); the polygon is proxy B at its body position with local vertices. Both carry
// b2_polygonRadius, the m_radius of b2PolygonShape and b2EdgeShape.
struct Box2DQueries {
  std::vector<b2Vec2> polygons, edges;  // proxies point into these
  std::vector<b2ShapeCastInput> casts;
  std::vector<b2TOIInput> tois;
};

Box2DQueries makeBox2D(const QuerySet& set) {
  Box2DQueries b;
  for (const Vec2 v : set.local) b.polygons.push_back(metres(v));
  for (const Query& q : set.queries) b.edges.insert(b.edges.end(), {metres(q.seg.a), metres(q.seg.b)});
  for (size_t i = 0; i < set.queries.size(); ++i) {
    const Query& q = set.queries[i];
    b2DistanceProxy edge, polygon;
    edge.Set(&b.edges[2 * i], 2, b2_polygonRadius);
    polygon.Set(&b.polygons[q.first], static_cast<int32>(q.count), b2_polygonRadius);
    b2ShapeCastInput cast;
    cast.proxyA = edge;
    cast.proxyB = polygon;
    cast.transformA.SetIdentity();
    cast.transformB.Set(metres(q.origin), 0.0f);
    cast.translationB = metres(q.motion);
    b.casts.push_back(cast);
    b2TOIInput toi;
    toi.proxyA = edge;
    toi.proxyB = polygon;
    toi.sweepA = {b2Vec2(0, 0), b2Vec2(0, 0), b2Vec2(0, 0), 0, 0, 0};
    toi.sweepB = {b2Vec2(0, 0), cast.transformB.p, cast.transformB.p + cast.translationB, 0, 0, 0};
    toi.tMax = 1.0f;
    b.tois.push_back(toi);
  }
  return b;
}

// ---- Timed loops: each folds every result into a checksum so no work can be dropped ------------

// Platon's sweep reads world vertices; like Box2D, which takes a shape and a transform, each query
// places the entity's shape at its position inside the timed loop.
uint64_t runPlaton(const QuerySet& set) {
  uint64_t sum = 0;
  std::array<Vec2, 8> placed;
  for (const Query& q : set.queries) {
    const std::span<const Vec2> shape = set.shape(q);
    for (size_t k = 0; k < shape.size(); ++k) placed[k] = {q.origin.x + shape[k].x, q.origin.y + shape[k].y};
    const Sweep s = sweep(std::span<const Vec2>(placed.data(), shape.size()), q.motion, q.seg);
    if (s.hitsWithinFrame()) sum += static_cast<uint64_t>(s.enter.num) * 31 + static_cast<uint64_t>(s.enter.den);
  }
  return sum;
}

uint64_t floatBits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

uint64_t runShapeCast(const Box2DQueries& b) {
  uint64_t sum = 0;
  for (const b2ShapeCastInput& in : b.casts) {
    b2ShapeCastOutput out;
    if (b2ShapeCast(&out, &in)) sum += floatBits(out.lambda);
  }
  return sum;
}

uint64_t runTimeOfImpact(const Box2DQueries& b) {
  uint64_t sum = 0;
  for (const b2TOIInput& in : b.tois) {
    b2TOIOutput out;
    b2TimeOfImpact(&out, &in);
    sum += floatBits(out.t) + out.state;
  }
  return sum;
}

// One timed loop: ns per query in every run (the engines take turns, run by run), and the checksum
// every run must agree on.
struct Timing {
  std::vector<double> ns;
  double totalNs = 0;
  uint64_t checksum = 0;

  template <class Run>
  void time(size_t queries, Run run) {
    const auto t0 = std::chrono::steady_clock::now();
    const uint64_t sum = run();
    const double elapsed = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
    if (!ns.empty() && sum != checksum) std::printf("warning: checksum changed between runs\n");
    checksum = sum;
    ns.push_back(elapsed / static_cast<double>(queries));
    totalNs += elapsed;
  }
  double median() const {
    std::vector<double> v = ns;
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
  }
  double low() const { return ns.empty() ? 0 : *std::min_element(ns.begin(), ns.end()); }
  double high() const { return ns.empty() ? 0 : *std::max_element(ns.begin(), ns.end()); }
};

// ---- Accuracy, in long double metres ------------------------------------------------------------

struct P {
  ld x, y;
};
P operator+(P a, P b) { return {a.x + b.x, a.y + b.y}; }
P operator-(P a, P b) { return {a.x - b.x, a.y - b.y}; }
P operator*(ld k, P a) { return {k * a.x, k * a.y}; }
ld dotP(P a, P b) { return a.x * b.x + a.y * b.y; }
ld crossP(P a, P b) { return a.x * b.y - a.y * b.x; }
P toP(Vec2 v) { return {static_cast<ld>(v.x), static_cast<ld>(v.y)}; }
P toP(Vec2w v) { return {static_cast<ld>(v.x), static_cast<ld>(v.y)}; }
P unitsToMetres(P p) { return (1.0L / kUnitsPerMetre) * p; }

// Penetration depth of the polygon into the segment: the shortest push that separates them, over the
// separating axes (the polygon's edge normals and the segment's normal); <= 0 when apart or touching.
ld overlapDepth(const std::vector<P>& poly, P a, P b) {
  ld depth = std::numeric_limits<ld>::infinity();
  auto axis = [&](P d) {
    const P n{-d.y, d.x};
    const ld len = std::sqrt(dotP(n, n));
    ld lo = std::numeric_limits<ld>::infinity(), hi = -lo;
    for (const P& v : poly) lo = std::min(lo, dotP(n, v)), hi = std::max(hi, dotP(n, v));
    const ld sLo = std::min(dotP(n, a), dotP(n, b)), sHi = std::max(dotP(n, a), dotP(n, b));
    depth = std::min(depth, std::min(hi - sLo, sHi - lo) / len);  // the shorter way out on this axis
  };
  for (size_t i = 0; i < poly.size(); ++i) axis(poly[(i + 1) % poly.size()] - poly[i]);
  axis(b - a);
  return depth;
}

// Independent check of the reference: the first t in [0, 1] at which the closed polygon, moving by
// m, touches the closed segment, from rays (polygon vertices against the segment, segment ends moving
// by -m against the polygon's edges). Parallel rays are skipped: grazing contacts never open an
// interior overlap, which is what Platon reports.
std::optional<ld> rayTimeOfImpact(const std::vector<P>& poly, P m, P a, P b) {
  std::optional<ld> best;
  auto ray = [&](P p, P dir, P q0, P q1) {
    const P e = q1 - q0;
    const ld den = crossP(dir, e);
    if (den == 0) return;
    const ld t = crossP(q0 - p, e) / den, u = crossP(q0 - p, dir) / den;
    if (t >= 0 && t <= 1 && u >= 0 && u <= 1 && (!best || t < *best)) best = t;
  };
  for (const P& v : poly) ray(v, m, a, b);
  for (size_t i = 0; i < poly.size(); ++i)
    for (const P& e : {a, b}) ray(e, -1.0L * m, poly[i], poly[(i + 1) % poly.size()]);
  return best;
}

ld pointSegmentDistance(P p, P a, P b) {
  const P d = b - a;
  const ld t = std::clamp(dotP(p - a, d) / dotP(d, d), 0.0L, 1.0L);
  const P gap = a + t * d - p;
  return std::sqrt(dotP(gap, gap));
}

// Distance between a polygon and a segment that do not intersect: some vertex or endpoint is closest.
ld distance(const std::vector<P>& poly, P a, P b) {
  ld best = std::numeric_limits<ld>::infinity();
  for (size_t i = 0; i < poly.size(); ++i) {
    const P v = poly[i], w = poly[(i + 1) % poly.size()];
    best =
        std::min({best, pointSegmentDistance(v, a, b), pointSegmentDistance(a, v, w), pointSegmentDistance(b, v, w)});
  }
  return best;
}

// Whether the straight path from `start` to `stop` touches the segment clearly before its end: with
// a stop position that does not overlap, the polygon went through the segment.
bool passesThrough(std::span<const Vec2> shape, P start, P stop, P a, P b) {
  std::vector<P> poly;
  for (const Vec2 v : shape) poly.push_back(start + unitsToMetres(toP(v)));
  const P path = stop - start;
  const std::optional<ld> t = rayTimeOfImpact(poly, path, a, b);
  return t && (1 - *t) * std::sqrt(dotP(path, path)) > kPenetrationMetres;
}

struct Outcome {
  bool hit = false;
  P stop;  // polygon position the engine would store, metres
};

// Outcomes of one engine, kept apart for queries that start clear of the segment and those that
// start within Box2D's skin of it (where b2ShapeCast reports no hit by design: "initial overlap").
struct Stats {
  struct Counts {
    size_t queries = 0, misses = 0, falseHits = 0, penetrations = 0, throughs = 0;
    size_t skinHits = 0;  // hits where the exact motion passes within Box2D's skin of the segment
  } clear, skin;
  size_t gaps = 0;
  ld gapSum = 0, gapMax = -std::numeric_limits<ld>::infinity(), gapMin = std::numeric_limits<ld>::infinity(),
     depthMax = 0;

  // gap: how far short of the exact contact the polygon stopped, along the motion (negative: past it).
  void add(bool exactHit, ld exactT, const Query& q, std::span<const Vec2> shape, const Outcome& o, bool near,
           bool grazes) {
    Counts& c = near ? skin : clear;
    ++c.queries;
    c.misses += exactHit && !o.hit;
    c.falseHits += !exactHit && o.hit && !grazes;
    c.skinHits += !exactHit && o.hit && grazes;
    std::vector<P> poly;
    for (const Vec2 v : shape) poly.push_back(o.stop + unitsToMetres(toP(v)));
    const P a = unitsToMetres(toP(q.seg.a)), b = unitsToMetres(toP(q.seg.b));
    const ld depth = overlapDepth(poly, a, b);
    if (depth > kPenetrationMetres)
      ++c.penetrations, depthMax = std::max(depthMax, depth);
    else
      c.throughs += passesThrough(shape, unitsToMetres(toP(q.origin)), o.stop, a, b);
    if (!exactHit || !o.hit) return;
    const P m = unitsToMetres(toP(q.motion));
    const P contact = unitsToMetres(toP(q.origin)) + exactT * m;
    const ld gap = dotP(contact - o.stop, m) / std::sqrt(dotP(m, m)) * 1000;  // mm
    ++gaps, gapSum += gap, gapMax = std::max(gapMax, gap), gapMin = std::min(gapMin, gap);
  }
};

P fromFloat(b2Vec2 v) { return {static_cast<ld>(v.x), static_cast<ld>(v.y)}; }

struct Accuracy {
  Stats platon, shapeCast, toi;
  size_t exactHits = 0, refDisagreements = 0, toiFailed = 0, castUnconverged = 0;
  size_t nearStarts = 0;           // queries starting within b2ShapeCast's target distance of the segment
  size_t platonExactOverlaps = 0;  // Platon's stop positions checked with the exact overlapsInterior
};

Accuracy measureAccuracy(const QuerySet& set, const Box2DQueries& b) {
  Accuracy acc;
  for (size_t i = 0; i < set.queries.size(); ++i) {
    const Query& q = set.queries[i];
    const Sweep s = sweep(set.polygon(q), q.motion, q.seg);
    const bool hit = s.hitsWithinFrame();
    const ld t = hit ? static_cast<ld>(s.enter.num) / static_cast<ld>(s.enter.den) : 1;
    acc.exactHits += hit;

    std::vector<P> poly;
    for (const Vec2 v : set.polygon(q)) poly.push_back(toP(v));
    const bool near = distance(poly, toP(q.seg.a), toP(q.seg.b)) < kCastTargetMetres * kUnitsPerMetre;
    acc.nearStarts += near;
    // A motion that misses the segment but passes within Box2D's skin of it: a hit by Box2D's design.
    bool grazes = false;
    if (!hit) {
      std::vector<Vec2> swept(set.polygon(q).begin(), set.polygon(q).end());
      for (const Vec2 v : set.polygon(q))
        swept.push_back({static_cast<int32_t>(v.x + q.motion.x), static_cast<int32_t>(v.y + q.motion.y)});
      std::vector<P> hull;
      for (const Vec2 v : convexHull(swept)) hull.push_back(toP(v));
      grazes = distance(hull, toP(q.seg.a), toP(q.seg.b)) < kCastTargetMetres * kUnitsPerMetre;
    }
    const std::optional<ld> ref = rayTimeOfImpact(poly, toP(q.motion), toP(q.seg.a), toP(q.seg.b));
    const bool refHit = ref && *ref < 1;
    acc.refDisagreements += refHit != hit || (hit && std::fabs(*ref - t) > 1e-12L);

    const Vec2w step = hit ? roundedStep(q.motion, s.enter, &s.enterAxis) : q.motion;
    const Vec2 stop{static_cast<int32_t>(q.origin.x + step.x), static_cast<int32_t>(q.origin.y + step.y)};
    std::vector<Vec2> moved;
    for (const Vec2 v : set.shape(q)) moved.push_back({stop.x + v.x, stop.y + v.y});
    acc.platonExactOverlaps += overlapsInterior(moved, q.seg);
    acc.platon.add(hit, t, q, set.shape(q), {hit, unitsToMetres(toP(stop))}, near, grazes);

    const b2ShapeCastInput& in = b.casts[i];
    b2ShapeCastOutput cast;
    const bool castHit = b2ShapeCast(&cast, &in);
    acc.castUnconverged += castHit && cast.iterations >= 20;
    const float lambda = castHit ? cast.lambda : 1.0f;
    acc.shapeCast.add(hit, t, q, set.shape(q), {castHit, fromFloat(in.transformB.p + lambda * in.translationB)}, near,
                      grazes);

    b2TOIOutput toi;
    b2TimeOfImpact(&toi, &b.tois[i]);
    acc.toiFailed += toi.state == b2TOIOutput::e_failed;
    const bool toiHit = toi.state != b2TOIOutput::e_separated;
    b2Transform xf;
    b.tois[i].sweepB.GetTransform(&xf, toiHit ? toi.t : 1.0f);
    acc.toi.add(hit, t, q, set.shape(q), {toiHit, fromFloat(xf.p)}, near, grazes);
  }
  return acc;
}

void printRow(const char* name, const Timing& t, const Stats& s) {
  const std::string falseHits = std::to_string(s.clear.falseHits) + " (" + std::to_string(s.clear.skinHits) + ")";
  std::printf("  %-21s %7.1f [%5.1f-%5.1f] %7zu %10s %7zu %7zu | %6zu %7zu %7zu | %8.3Lf %8.3Lf %8.3Lf %9.3Lf\n", name,
              t.median(), t.low(), t.high(), s.clear.misses, falseHits.c_str(), s.clear.penetrations, s.clear.throughs,
              s.skin.misses, s.skin.penetrations, s.skin.throughs, s.gaps ? s.gapSum / s.gaps : 0.0L,
              s.gaps ? s.gapMax : 0.0L, s.gaps ? s.gapMin : 0.0L, s.depthMax * 1000);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const size_t count = quick ? 5000 : 50000;
  const int reps = quick ? 2 : 7;
  std::printf("Sweep: convex polygon (3-8 vertices, 0.25-1 m) vs segment (0.5-5 m), motion 0.1-10 m\n");
  std::printf(
      "%zu queries per offset; ns/query: median [min-max] of %d interleaved runs (b2TimeOfImpact: of those "
      "started within 3 s); scale %d units per metre (1 unit = %.3f mm), coordinate limit 2^30-1 = %d units = "
      "%.0f m\n",
      count, reps, kUnitsPerMetre, 1000.0 / kUnitsPerMetre, kCoordLimit,
      static_cast<double>(kCoordLimit) / kUnitsPerMetre);
  std::printf(
      "Box2D 2.4.1 (Debian's build: assertions on): polygon and edge radius b2_polygonRadius = %.3f m; "
      "b2ShapeCast stops at core distance ~%.3f m and reports no hit for a start closer than that (its "
      "\"initial overlap\", by design); b2TimeOfImpact, what b2World uses, stops at ~%.3f m\n",
      b2_polygonRadius, kCastTargetMetres, std::max(b2_linearSlop, 2 * b2_polygonRadius - 3 * b2_linearSlop));
  std::printf(
      "Platon's timed loop places the shape at its position for every query, as Box2D's takes a transform.\n"
      "miss: exact hit, engine none; false hit: engine hit, exact none (in brackets: the motion passes within "
      "Box2D's skin of the segment, a hit by its design); penetration: the engine's stop "
      "position overlaps the segment's interior by > 1 nm (long double SAT on the exact geometry);\n"
      "through: no such overlap, but the straight path from the exact start to the stop position crosses "
      "the segment (tunnelling); where an engine reports no hit the bench moves the whole motion.\n"
      "Columns left of | : queries starting clear of the skin; right of it: queries starting within "
      "%.0f mm of the segment (b2ShapeCast's initial overlap).\n"
      "gap: exact contact minus stop position along the motion, mm, over queries both call hits; depth: "
      "deepest penetration, mm\n",
      kCastTargetMetres * 1000);
  uint64_t checksum = 0;
  for (const double offset : {0.0, 1e3, 1e5, 1e6}) {
    const QuerySet set = makeQueries(count, offset);
    const Box2DQueries b = makeBox2D(set);
    // The engines take turns, so a busy neighbour on a shared machine slows them alike. Far from the
    // origin b2TimeOfImpact is thousands of times slower: it stops repeating after 3 s.
    Timing platon, cast, toi;
    for (int r = 0; r < reps; ++r) {
      platon.time(count, [&] { return runPlaton(set); });
      cast.time(count, [&] { return runShapeCast(b); });
      if (toi.totalNs < 3e9) toi.time(count, [&] { return runTimeOfImpact(b); });
    }
    checksum ^= platon.checksum ^ (cast.checksum << 1) ^ (toi.checksum << 2);
    const Accuracy acc = measureAccuracy(set, b);
    std::printf(
        "\noffset %.0e m = %.3e units (x and y); exact hits %zu of %zu; starts within the skin %zu; Platon vs "
        "long-double ray TOI disagreements: %zu\n",
        offset, offset * kUnitsPerMetre, acc.exactHits, count, acc.nearStarts, acc.refDisagreements);
    std::printf("  %-21s %21s %7s %10s %7s %7s | %6s %7s %7s | %8s %8s %8s %9s\n", "engine", "ns/query", "misses",
                "false(skin)", "penetr.", "through", "misses", "penetr.", "through", "gap mean", "gap max", "gap min",
                "depth max");
    printRow("Platon sweep", platon, acc.platon);
    printRow("Box2D b2ShapeCast", cast, acc.shapeCast);
    printRow("Box2D b2TimeOfImpact", toi, acc.toi);
    std::printf(
        "  Platon stop positions overlapping (exact integer check): %zu; b2ShapeCast hits at the "
        "20-iteration cap: %zu; b2TimeOfImpact e_failed: %zu\n",
        acc.platonExactOverlaps, acc.castUnconverged, acc.toiFailed);
    int castGoal = 0;
    for (size_t r = 0; r < platon.ns.size(); ++r) castGoal += cast.ns[r] >= 3 * platon.ns[r];
    std::printf(
        "  throughput ratio of medians Platon/b2ShapeCast = %.2fx (goal >= 3x: met in %d of %zu runs), "
        "Platon/b2TimeOfImpact = %.2fx\n",
        cast.median() / platon.median(), castGoal, platon.ns.size(), toi.median() / platon.median());
  }
  std::printf("\nchecksum %016llx\n", static_cast<unsigned long long>(checksum));
}
