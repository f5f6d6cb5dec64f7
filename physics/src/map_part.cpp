#include "platon/physics/map_part.h"

#include "fixed_point.h"
#include "grid.h"

namespace platon::physics {
namespace {
std::string partName(MapPartId id) { return "map part " + std::to_string(id); }
}  // namespace

MapPart::MapPart(MapPartId id) : id_(id), grid_(std::make_unique<Grid>()) {}
MapPart::MapPart(MapPart&&) noexcept = default;
MapPart& MapPart::operator=(MapPart&&) noexcept = default;
MapPart::~MapPart() = default;

void MapPart::checkOpen(const char* what) const {
  if (initialized_) throw Error(partName(id_) + ": cannot add a " + what + " after initialize()");
}

void MapPart::checkSegment(Vec2 p0, Vec2 p1, const char* what) const {
  if (inRange(p0) && inRange(p1) && p0 != p1) return;
  const std::string line = partName(id_) + " " + what + " " + std::to_string(lines_.size());
  if (p0 == p1) throw Error(line + ": zero length at " + toString(p0));
  throw Error(line + ": endpoint " + toString(inRange(p0) ? p1 : p0) +
              " is outside the coordinate range |x|,|y| <= 2^30 - 1");
}

LineIndex MapPart::line(Vec2 p0, Vec2 p1, uint32_t tag) {
  checkOpen("line");
  checkSegment(p0, p1, "line");
  lines_.push_back({tag, LineKind::Solid, UINT32_MAX});
  segments_.push_back({p0, p1});
  return static_cast<LineIndex>(lines_.size() - 1);
}

LineIndex MapPart::oneWay(Vec2 p0, Vec2 p1, uint32_t tag) {
  checkOpen("one-way line");
  checkSegment(p0, p1, "one-way line");
  lines_.push_back({tag, LineKind::OneWay, UINT32_MAX});
  segments_.push_back({p0, p1});
  return static_cast<LineIndex>(lines_.size() - 1);
}

LineIndex MapPart::warp(Vec2 p0, Vec2 p1, MapPartId target, Vec2 t0, Vec2 t1, uint32_t tag) {
  checkOpen("warp");
  checkSegment(p0, p1, "warp");
  checkSegment(t0, t1, "warp target of");
  const Vec2w d = p1 - p0, e = t1 - t0;
  // A plausibility check on the lengths (whole units, rounded down), not geometry.
  const int64_t ld = static_cast<int64_t>(isqrt(static_cast<u128>(dot(d, d))));
  const int64_t le = static_cast<int64_t>(isqrt(static_cast<u128>(dot(e, e))));
  if (100 * std::abs(ld - le) > 200 + std::max(ld, le))
    throw Error(partName(id_) + " warp " + std::to_string(lines_.size()) + ": edge lengths differ (" +
                std::to_string(ld) + " here, " + std::to_string(le) + " in part " + std::to_string(target) + ")");
  Warp w;
  w.target = target;
  w.targetSegment = {t0, t1};
  w.turn = static_cast<Angle>(angleOf(e) - angleOf(d));
  // Exact quarter turns when the edges are axis-aligned: cube faces stay exact.
  const Angle snapped = static_cast<Angle>((w.turn + (kQuarterTurn / 2)) / kQuarterTurn * kQuarterTurn);
  const bool axisAligned = (d.x == 0 || d.y == 0) && (e.x == 0 || e.y == 0);
  if (axisAligned) w.turn = snapped;
  w.rotation = rotationOf(w.turn);
  lines_.push_back({tag, LineKind::Warp, static_cast<uint32_t>(warps_.size())});
  segments_.push_back({p0, p1});
  warps_.push_back(w);
  return static_cast<LineIndex>(lines_.size() - 1);
}

void MapPart::reserve(size_t count) {
  lines_.reserve(count);
  segments_.reserve(count);
}

void MapPart::setGravity(Vec2w g) {
  const int64_t limit = int64_t{kMaxMove} << 16;
  if (g.x < -limit || g.x > limit || g.y < -limit || g.y > limit)
    throw Error(partName(id_) + ": gravity (" + std::to_string(g.x) + ", " + std::to_string(g.y) +
                ") / 65536 exceeds 2^30 units per frame per frame");
  gravity_ = g;
}

void MapPart::initialize() {
  if (initialized_) throw Error(partName(id_) + ": initialize() called twice");
  for (size_t i = 0; i < lines_.size(); ++i) {
    if (lines_[i].kind != LineKind::Warp) continue;
    const MapPartId target = warps_[lines_[i].warp].target;
    if (target == id_)
      throw Error(partName(id_) + " warp " + std::to_string(i) + ": a warp cannot target its own part");
  }
  if (lines_.size() >= UINT32_MAX - 1) throw Error(partName(id_) + ": too many lines");
  grid_->build(segments_);
  initialized_ = true;
}

size_t MapPart::memoryBytes() const {
  return lines_.capacity() * sizeof(Line) + segments_.capacity() * sizeof(Segment) + warps_.capacity() * sizeof(Warp) +
         grid_->memoryBytes();
}

}  // namespace platon::physics
