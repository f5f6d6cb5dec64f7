// The sweep of a convex polygon against another convex polygon (entities meeting entities) against
// the independent exact reference (testing/reference_geometry.h: the obstacle hull{q - p}, clipped
// by the ray). Cases favour the coincidences that matter: shared vertices, edges along edges,
// touching at t = 0, motions along edges and aimed at the obstacle.
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "platon/physics/convex.h"
#include "platon/physics/sweep.h"
#include "platon/testing/reference_geometry.h"

using namespace platon::physics;
namespace ref = platon::testing::reference;

namespace {

int64_t uni(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  return std::uniform_int_distribution<int64_t>(lo, hi)(rng);
}

std::vector<Vec2> polygon(std::mt19937_64& rng, Vec2 centre, int64_t radius) {
  for (;;) {
    std::vector<Vec2> pts;
    for (int64_t k = uni(rng, 3, 10); k > 0; --k)
      pts.push_back({static_cast<int32_t>(centre.x + uni(rng, -radius, radius)),
                     static_cast<int32_t>(centre.y + uni(rng, -radius, radius))});
    pts = convexHull(pts);
    if (pts.size() >= 3) return pts;
  }
}

std::string describe(const std::vector<Vec2>& p, Vec2w m, const std::vector<Vec2>& q) {
  std::ostringstream o;
  o << "\n  polygon {";
  for (const Vec2 v : p) o << "{" << v.x << ", " << v.y << "}, ";
  o << "}\n  motion {" << m.x << ", " << m.y << "}\n  obstacle {";
  for (const Vec2 v : q) o << "{" << v.x << ", " << v.y << "}, ";
  o << "}";
  return o.str();
}

bool same(Fraction f, const ref::Rat<i128>& r) { return ref::Rat<i128>{f.num, f.den} == r; }

}  // namespace

TEST(PolygonSweep, MatchesReference) {
  std::mt19937_64 rng(0x5eed'0104);
  const ref::Rat<i128> zero{0, 1}, one{1, 1};
  int hits = 0, touching = 0, inside = 0, vertexEntries = 0, failures = 0;
  for (int i = 0; i < 30000 && failures < 10; ++i) {
    const int64_t r = int64_t{1} << uni(rng, 2, 20);
    const std::vector<Vec2> p = polygon(rng, {0, 0}, r);
    std::vector<Vec2> q;
    switch (uni(rng, 0, 3)) {
      case 0:  // anywhere near
        q = polygon(rng, {static_cast<int32_t>(uni(rng, -3 * r, 3 * r)), static_cast<int32_t>(uni(rng, -3 * r, 3 * r))},
                    r);
        break;
      case 1: {  // one of its vertices on one of ours: touching (or overlapping) at t = 0
        q = polygon(rng, {0, 0}, r);
        const Vec2 ours = p[uni(rng, 0, static_cast<int64_t>(p.size()) - 1)];
        const Vec2 theirs = q[uni(rng, 0, static_cast<int64_t>(q.size()) - 1)];
        for (Vec2& v : q) v = {v.x + ours.x - theirs.x, v.y + ours.y - theirs.y};
        break;
      }
      case 2: {  // our own shape, reflected through a point: edges that line up with ours
        const Vec2 at = p[0];
        for (auto it = p.rbegin(); it != p.rend(); ++it) q.push_back({2 * at.x - it->x, 2 * at.y - it->y});
        std::rotate(q.begin(), q.begin() + static_cast<long>(uni(rng, 0, static_cast<int64_t>(q.size()) - 1)), q.end());
        q = convexHull(q);
        break;
      }
      default:  // small and far, on our path
        q = polygon(rng, {static_cast<int32_t>(uni(rng, 2 * r, 6 * r)), static_cast<int32_t>(uni(rng, -r, r))},
                    std::max<int64_t>(1, r / 4));
        break;
    }
    if (q.size() < 3) continue;
    Vec2w m;
    switch (uni(rng, 0, 3)) {
      case 0:
        m = {uni(rng, -4 * r, 4 * r), uni(rng, -4 * r, 4 * r)};
        break;
      case 1: {  // along one of our edges
        const size_t k = static_cast<size_t>(uni(rng, 0, static_cast<int64_t>(p.size()) - 1));
        const Vec2w e = p[(k + 1) % p.size()] - p[k];
        m = {e.x * uni(rng, -3, 3), e.y * uni(rng, -3, 3)};
        break;
      }
      case 2:
        m = {q[0].x * uni(rng, 1, 3), q[0].y * uni(rng, 1, 3)};
        break;  // at the obstacle
      default:
        m = {uni(rng, -1, 1), uni(rng, -1, 1)};
        break;  // unit moves
    }
    std::string problems;
    const ref::RefSweep rs = ref::referenceSweep(p, m, q);
    const Sweep s = sweep(p, m, q);
    const bool nonEmpty = rs.overlaps && (!rs.bounded || rs.exit > zero);
    const bool hit = nonEmpty && rs.bounded && rs.enter >= zero && rs.enter < one;
    const bool in = nonEmpty && (!rs.bounded || rs.enter < zero);
    if (s.empty != !nonEmpty) problems += "\n  empty differs";
    if (s.hitsWithinFrame() != hit) problems += "\n  hitsWithinFrame differs";
    if (s.startsInside() != in) problems += "\n  startsInside differs";
    if (overlapsInterior(p, q) != rs.overlapsAtZero) problems += "\n  overlapsInterior differs";
    if (nonEmpty && !s.empty && rs.bounded) {
      if (!same(s.enter, rs.enter) || !same(s.exit, rs.exit)) problems += "\n  interval differs";
      bool ok = false;
      for (const Vec2w n : rs.enterNormals)
        ok = ok || (ref::crossExact(s.normal(), n) == 0 && ref::dotExact(s.normal(), n) > 0);
      if (!ok) problems += "\n  normal is not one the reference allows";
      vertexEntries += rs.enterNormals.size() > 1;
    }
    hits += hit, inside += in, touching += rs.touchesAtZero && !rs.overlapsAtZero;
    if (!problems.empty()) {
      ++failures;
      ADD_FAILURE() << "case " << i << describe(p, m, q) << problems;
    }
  }
  EXPECT_GT(hits, 3000);
  EXPECT_GT(inside, 3000);
  EXPECT_GT(touching, 1000);
  EXPECT_GT(vertexEntries, 500);
  std::printf("polygon sweeps: %d hits, %d starting inside, %d touching at t = 0, %d entering at a vertex\n", hits,
              inside, touching, vertexEntries);
}
