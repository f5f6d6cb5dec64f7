#include "platon/physics/map_part.h"

#include <algorithm>

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

void MapPart::checkSegment(Vec2 p0, Vec2 p1, const char* what, size_t index) const {
  if (inRange(p0) && inRange(p1) && p0 != p1) return;
  const std::string line = partName(id_) + " " + what + " " + std::to_string(index);
  if (p0 == p1) throw Error(line + ": zero length at " + toString(p0));
  throw Error(line + ": endpoint " + toString(inRange(p0) ? p1 : p0) +
              " is outside the coordinate range |x|,|y| <= 2^30 - 1");
}

LineIndex MapPart::add(Line line, Segment segment) {
  lines_.push_back(line);
  segments_.push_back(segment);
  low_ = {std::min({low_.x, segment.a.x, segment.b.x}), std::min({low_.y, segment.a.y, segment.b.y})};
  high_ = {std::max({high_.x, segment.a.x, segment.b.x}), std::max({high_.y, segment.a.y, segment.b.y})};
  return static_cast<LineIndex>(lines_.size() - 1);
}

LineIndex MapPart::line(Vec2 p0, Vec2 p1, uint32_t tag) {
  checkOpen("line");
  checkSegment(p0, p1, "line", lines_.size());
  return add({tag, LineKind::Solid, UINT32_MAX}, {p0, p1});
}

LineIndex MapPart::lines(std::span<const Segment> segments, uint32_t tag) {
  checkOpen("line");
  // One pass checks every segment and grows the box; nothing is added unless all are good.
  Vec2 low = low_, high = high_;
  for (size_t k = 0; k < segments.size(); ++k) {
    const Segment& s = segments[k];
    checkSegment(s.a, s.b, "line", lines_.size() + k);
    low = {std::min({low.x, s.a.x, s.b.x}), std::min({low.y, s.a.y, s.b.y})};
    high = {std::max({high.x, s.a.x, s.b.x}), std::max({high.y, s.a.y, s.b.y})};
  }
  const LineIndex first = static_cast<LineIndex>(lines_.size());
  lines_.insert(lines_.end(), segments.size(), Line{tag, LineKind::Solid, UINT32_MAX});
  segments_.insert(segments_.end(), segments.begin(), segments.end());
  low_ = low, high_ = high;
  return first;
}

LineIndex MapPart::oneWay(Vec2 p0, Vec2 p1, uint32_t tag) {
  checkOpen("one-way line");
  checkSegment(p0, p1, "one-way line", lines_.size());
  return add({tag, LineKind::OneWay, UINT32_MAX}, {p0, p1});
}

LineIndex MapPart::warp(Vec2 p0, Vec2 p1, MapPartId target, Vec2 t0, Vec2 t1, uint32_t tag) {
  checkOpen("warp");
  if (target == id_)
    throw Error(partName(id_) + " warp " + std::to_string(lines_.size()) + ": a warp cannot target its own part");
  checkSegment(p0, p1, "warp", lines_.size());
  checkSegment(t0, t1, "warp target of", lines_.size());
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
  warps_.push_back(w);
  add({tag, LineKind::Warp, static_cast<uint32_t>(warps_.size() - 1)}, {p0, p1});
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
  if (lines_.size() > (size_t{1} << 30))
    throw Error(partName(id_) + ": too many lines (" + std::to_string(lines_.size()) + "; 2^30 at most)");
  grid_->build(segments_, low_, high_);
  findFaceLoop();
  initialized_ = true;
}

void MapPart::findFaceLoop() {
  std::vector<LineIndex> warpLines;
  for (LineIndex i = 0; i < lines_.size(); ++i)
    if (lines_[i].kind == LineKind::Warp) warpLines.push_back(i);
  if (warpLines.size() < 3) return;
  std::vector<LineIndex> loop{warpLines[0]};
  while (loop.size() < warpLines.size()) {
    const Vec2 end = segments_[loop.back()].b;
    LineIndex next = UINT32_MAX;
    for (const LineIndex i : warpLines)
      if (segments_[i].a == end) next = next == UINT32_MAX ? i : UINT32_MAX - 1;  // two ways on: no loop
    if (next >= UINT32_MAX - 1 || std::find(loop.begin(), loop.end(), next) != loop.end()) return;
    loop.push_back(next);
  }
  if (segments_[loop.back()].b != segments_[loop.front()].a) return;
  for (size_t k = 0; k < loop.size(); ++k) {  // every corner turns left: convex, counter-clockwise
    const Segment s = segments_[loop[k]], t = segments_[loop[(k + 1) % loop.size()]];
    if (cross(s.b - s.a, t.b - t.a) <= 0) return;
  }
  faceLoop_ = std::move(loop);
}

size_t MapPart::memoryBytes() const {
  return lines_.capacity() * sizeof(Line) + segments_.capacity() * sizeof(Segment) + warps_.capacity() * sizeof(Warp) +
         grid_->memoryBytes();
}

}  // namespace platon::physics
