// World::countOverlaps, the invariant's check: every test, fuzzer and scenario asks it each frame.
// It reads the world's state only (instances' vertices, lines, platforms, the rules' pierce), none
// of the solver's indexes, so a fault there cannot hide from it. Its cost is what the bodies meet:
// bodies against the lines near them (line boxes indexed once per part, lines never change after
// initialize) and against each other (a grid over the bodies alone, made for the call); never a
// pair of lines.
#include <algorithm>
#include <bit>
#include <map>

#include "line_boxes.h"
#include "platon/physics/world.h"
#include "world_impl.h"

namespace platon::physics {
namespace {

// An instance in the part, with its vertices and box.
struct Body {
  Box box;
  const Entity* entity;
  const Instance* instance;
  std::vector<Vec2> verts;
};

Box boxOf(std::span<const Vec2> points) { return sweptBox(points, {0, 0}); }
Box boxOf(const Segment& s) { return boxOf(std::array<Vec2, 2>{s.a, s.b}); }

// The part's solid fixed lines (one-way lines hold nothing inside them).
LineBoxes fixedLines(const MapPart& part) {
  std::vector<LineBoxes::Item> items;
  for (LineIndex l = 0; l < part.lines().size(); ++l)
    if (part.lines()[l].kind != LineKind::OneWay) items.push_back({boxOf(part.segments()[l]), l});
  return LineBoxes(std::move(items));
}

// Whether the pair overlaps where it counts: two bodies solid to each other, their interiors met.
bool overlapping(const Body& a, const Body& b) {
  if (a.box.x1 < b.box.x0 || b.box.x1 < a.box.x0 || a.box.y1 < b.box.y0 || b.box.y1 < a.box.y0) return false;
  if (a.entity == b.entity) return false;
  return solidPair(a.entity->filter, b.entity->filter) && overlapsInterior(a.verts, b.verts);
}

// The bodies of one part that overlap each other, added to `count`; the pairs looked at returned.
// A uniform grid built for this call (the solver's index is not asked): its cell is twice the
// median body's size, so a pile of n bodies costs O(n) however tall or wide it is (a sweep along x
// alone met each body of a tall pile with the whole column above and below it). A pair is looked
// at in one cell only: the one holding the larger of their boxes' low corners. A body over more
// than kMostCells cells (a giant among small ones) is met against every body instead.
size_t bodyPairs(const std::vector<Body>& bodies, size_t& count) {
  if (bodies.size() < 2) return 0;
  std::vector<int64_t> sizes;
  sizes.reserve(bodies.size());
  for (const Body& b : bodies) sizes.push_back(std::max(b.box.x1 - b.box.x0, b.box.y1 - b.box.y0));
  std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2), sizes.end());
  const int64_t cell = std::max<int64_t>(2 * sizes[sizes.size() / 2], 1);
  constexpr int64_t kMostCells = 16;
  auto cellOf = [&](int64_t v) { return v >= 0 ? v / cell : -((-v + cell - 1) / cell); };  // floor
  struct Filed {
    int64_t cx, cy;
    uint32_t body;
  };
  std::vector<Filed> filed;
  std::vector<uint32_t> giants;
  filed.reserve(bodies.size() * 2);
  for (uint32_t i = 0; i < bodies.size(); ++i) {
    const Box& b = bodies[i].box;
    const int64_t x0 = cellOf(b.x0), x1 = cellOf(b.x1), y0 = cellOf(b.y0), y1 = cellOf(b.y1);
    if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMostCells) {
      giants.push_back(i);
      continue;
    }
    for (int64_t cx = x0; cx <= x1; ++cx)
      for (int64_t cy = y0; cy <= y1; ++cy) filed.push_back({cx, cy, i});
  }
  // Grouped by a hash of the cell (a counting sort: linear); cells that share a bucket are told
  // apart below, where a pair counts only if both entries are in the pair's own cell.
  const size_t buckets = std::bit_ceil(std::max<size_t>(2 * filed.size(), 16));
  auto bucketOf = [&](const Filed& f) {
    const uint64_t h =
        static_cast<uint64_t>(f.cx) * 0x9E3779B97F4A7C15ull ^ static_cast<uint64_t>(f.cy) * 0xC2B2AE3D27D4EB4Full;
    return static_cast<size_t>(h >> 32) & (buckets - 1);
  };
  std::vector<uint32_t> start(buckets + 1, 0);
  for (const Filed& f : filed) ++start[bucketOf(f) + 1];
  for (size_t k = 1; k <= buckets; ++k) start[k] += start[k - 1];
  std::vector<Filed> grouped(filed.size());
  {
    std::vector<uint32_t> next(start.begin(), start.end() - 1);
    for (const Filed& f : filed) grouped[next[bucketOf(f)]++] = f;
  }
  size_t looked = 0;
  for (size_t k = 0; k < buckets; ++k)
    for (uint32_t i = start[k]; i < start[k + 1]; ++i)
      for (uint32_t j = i + 1; j < start[k + 1]; ++j) {
        const Filed &p = grouped[i], &q = grouped[j];
        const Body& a = bodies[p.body];
        const Body& b = bodies[q.body];
        // The pair's own cell: where the larger low corner lies (inside both boxes' cells).
        const int64_t cx = cellOf(std::max(a.box.x0, b.box.x0)), cy = cellOf(std::max(a.box.y0, b.box.y0));
        if (p.cx != cx || p.cy != cy || q.cx != cx || q.cy != cy) continue;
        ++looked;
        if (overlapping(a, b)) ++count;
      }
  for (size_t g = 0; g < giants.size(); ++g)
    for (uint32_t i = 0; i < bodies.size(); ++i) {
      // A giant against every body, a pair of giants once.
      const bool giant = std::binary_search(giants.begin(), giants.end(), i);
      if (i == giants[g] || (giant && i < giants[g])) continue;
      ++looked;
      if (overlapping(bodies[giants[g]], bodies[i])) ++count;
    }
  return looked;
}

}  // namespace

const LineBoxes& WorldImpl::overlapLines(const MapPart& part) const {
  auto& kept = overlapLineIndex[part.id()];
  if (kept && part.initialized()) return *kept;
  kept = std::make_unique<LineBoxes>(fixedLines(part));  // lines may still be added: made again next time
  return *kept;
}

size_t World::countOverlaps(size_t* work) const {
  const WorldImpl& w = *impl_;
  std::map<MapPartId, std::vector<Body>> parts;
  size_t done = 0;
  for (const WorldImpl::Slot& slot : w.slots) {
    const Entity* e = slot.entity.get();
    if (!e) continue;
    for (const Instance& inst : e->instances) {
      Body b{{}, e, &inst, worldVertices(inst)};
      b.box = boxOf(b.verts);
      parts[inst.part].push_back(std::move(b));
      ++done;
    }
  }
  size_t count = 0;
  for (auto& entry : parts) {
    const MapPartId partId = entry.first;  // a name of its own: lambdas below capture it (clang 14)
    std::vector<Body>& bodies = entry.second;
    const MapPart& part = w.part(partId);
    // Fixed lines: solid unless kept passable until the instance is clear (refreshPierce) or pierced.
    const LineBoxes& lines = w.overlapLines(part);
    for (const Body& b : bodies)
      done += lines.query(b.box, [&](uint32_t l) {
        if (!overlapsInterior(b.verts, part.segments()[l])) return;
        const std::vector<LineIndex>& kept = b.instance->overlapping;
        if (std::binary_search(kept.begin(), kept.end(), l)) return;
        const Line& line = part.lines()[l];
        if (w.rules->pierce(b.entity->id, {partId, l, line.tag, line.kind, {}})) return;
        ++count;
      });
    // Platforms' lines: solid where the platform meets the body.
    std::vector<LineBoxes::Item> platformItems;
    std::vector<std::pair<const PlatformLine*, const Platform*>> platformLines;
    w.forEachPlatformLine(partId, {INT64_MIN, INT64_MIN, INT64_MAX, INT64_MAX},
                          [&](const PlatformLine& l, LineIndex key) {
                            if (l.kind == LineKind::OneWay) return;
                            platformItems.push_back({boxOf(l.segment), static_cast<uint32_t>(platformLines.size())});
                            platformLines.emplace_back(&l, &w.platforms[(key & ~kPlatformLineBit) >> 16]);
                          });
    done += w.platforms.size() + platformItems.size();  // the platforms looked through, their lines indexed
    if (!platformItems.empty()) {
      const LineBoxes moving(std::move(platformItems));
      for (const Body& b : bodies)
        done += moving.query(b.box, [&](uint32_t k) {
          const auto [line, platform] = platformLines[k];
          if (overlapsInterior(b.verts, line->segment) && WorldImpl::platformMeets(*platform, *b.entity) == partId)
            ++count;
        });
    }
    done += bodyPairs(bodies, count);
  }
  if (work) *work = done;
  return count;
}

}  // namespace platon::physics
