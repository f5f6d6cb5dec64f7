// Turning an entity about its origin, in sub-steps small enough that the hull of the shapes before
// and after each one covers the area it sweeps.
#include <algorithm>

#include "bounds.h"
#include "fixed_point.h"
#include "world_impl.h"

namespace platon::physics {

// Sub-steps for turning a shape of squared radius `radius2` by `delta` binary-angle units: small
// enough that a vertex's arc leaves its chord by under half a unit. The arc of radius r through
// angle a leaves its chord by r (1 - cos(a / 2)) ~ r a^2 / 8, so a <= 2 / sqrt(r): the count is
// ceil(|delta| * pi * r^(1/2) / 2^32), in exact integers (r^(1/2) and pi in Q32 and Q40). No cap:
// the largest legal shape (radius 2^29.5) needs about 43,000 sub-steps for a half turn, and a cap
// would let its far end swing through a short line between two of them.
int64_t rotationSubSteps(int64_t radius2, int64_t delta) {
  const uint64_t rootQ32 = isqrt(static_cast<u128>(radius2) << 64);                            // r in Q32
  const uint64_t fourthRootQ32 = isqrt(static_cast<u128>(rootQ32) << 32);                      // r^(1/2) in Q32
  constexpr uint64_t kPiQ40 = 3454217652358ull;                                                // pi * 2^40, rounded
  const u128 scaled = static_cast<u128>(delta < 0 ? -delta : delta) * fourthRootQ32 * kPiQ40;  // < 2^120
  const u128 unit = static_cast<u128>(1) << (32 + 32 + 40);
  const int64_t steps = static_cast<int64_t>((scaled + unit - 1) / unit);
  return std::max<int64_t>(steps, 1);
}

bool WorldImpl::rotateBy(Entity& e, int64_t delta) {
  if (delta == 0 || e.instances.empty()) return true;
  int64_t radius2 = 1;
  for (const Vec2 v : e.shape.vertices()) radius2 = std::max(radius2, dot(wide(v), wide(v)));
  const int64_t steps = rotationSubSteps(radius2, delta);
  bool blocked = false;
  for (int64_t j = 1; j <= steps && !blocked; ++j) {
    const Angle angle = static_cast<Angle>(e.angle + static_cast<Angle>(delta * j / steps - delta * (j - 1) / steps));
    std::vector<std::vector<Vec2>> shapes(e.instances.size());
    for (size_t i = 0; i < e.instances.size() && !blocked; ++i)
      blocked = !rotationStepFits(e, e.instances[i], angle, shapes[i]);
    if (blocked) break;
    for (size_t i = 0; i < e.instances.size(); ++i)
      setShape(e.instances[i], std::move(shapes[i]), e.shape, static_cast<Angle>(angle + e.instances[i].frame));
    e.angle = angle;
  }
  updatePierceState(e, {});
  std::vector<Vec2w> noNormals;
  Move none{e, {}, noNormals, {}, {}};
  updateLinks(none);
  reindex(e);
  return !blocked;
}

// Whether one sub-step of a turn, to `angle`, is free for the instance: the hull of its shape before
// and after meets no line that blocks it, no platform's line and no solid body (what it meets is
// told to the rules as a touch). `next` is the turned shape.
bool WorldImpl::rotationStepFits(Entity& e, Instance& inst, Angle angle, std::vector<Vec2>& next) {
  try {
    const Convex c = e.shape.rotated(static_cast<Angle>(angle + inst.frame));
    next.assign(c.vertices().begin(), c.vertices().end());
  } catch (const Error&) {
    return false;
  }
  std::vector<Vec2> both = inst.shape;
  both.insert(both.end(), next.begin(), next.end());
  std::vector<Vec2> hull = convexHull(both);
  for (Vec2& v : hull) {
    v = {inst.position.x + v.x, inst.position.y + v.y};
    if (!inRange(v)) return false;
  }
  coverBox(inst, sweptBox(hull, {}));  // the lines near the swept hull
  const std::vector<Vec2> before = worldVertices(inst);
  std::optional<Contact> met = rotationLineHit(e, inst, hull, before);
  if (!met) met = rotationBodyHit(e, inst, hull);
  if (!met) return true;
  callRules([&](Rules& r) { r.touchContact(*met); });
  return false;
}

// The first line of the part, or of a platform, that the swept hull overlaps: its contact.
std::optional<Contact> WorldImpl::rotationLineHit(Entity& e, Instance& inst, const std::vector<Vec2>& hull,
                                                  const std::vector<Vec2>& before) {
  const MapPart& p = part(inst.part);
  const auto lines = inst.region.lines();
  for (size_t k = 0; k < lines.size(); ++k)
    if (blocks(e, inst, k, before) && overlapsInterior(hull, p.segments()[lines[k]]))
      return makeContact(e, inst, lines[k], Fraction::zero(), {}, {});
  std::optional<LineIndex> met;
  forEachPlatformLine(inst.part, sweptBox(hull, {}), [&](const PlatformLine& l, LineIndex key) {
    if (met || (l.kind == LineKind::OneWay && !wholyInFront(before, l.segment))) return;
    if (overlapsInterior(hull, l.segment)) met = key;
  });
  if (!met) return std::nullopt;
  return makeContact(e, inst, *met, Fraction::zero(), {}, {});
}

// The first solid body the swept hull overlaps: its contact.
std::optional<Contact> WorldImpl::rotationBodyHit(Entity& e, const Instance& inst, const std::vector<Vec2>& hull) {
  std::vector<Vec2> other;
  std::optional<EntityId> met;
  forEachSolidNear(e, inst.part, sweptBox(hull, {}), [&](const Entity& o, const Instance& oi) {
    if (met) return;
    worldVertices(oi, other);
    if (overlapsInterior(hull, other)) met = o.id;
  });
  if (!met) return std::nullopt;
  Contact c = makeContact(e, inst, kNoLine, Fraction::zero(), {}, {});
  c.other = *met;
  return c;
}

}  // namespace platon::physics
