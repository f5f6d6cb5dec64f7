// World::countOverlaps, the invariant's check: every test, fuzzer and scenario asks it each frame.
// It reads the world's state only (instances' vertices, lines, platforms, the rules' pierce), none
// of the solver's indexes, so a fault there cannot hide from it. Its cost is what the bodies meet:
// bodies against the lines near them (line boxes indexed once per part, lines never change after
// initialize) and against each other (a sweep over the bodies alone); never a pair of lines.
#include <algorithm>
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
    // Bodies against bodies: swept by their left sides.
    std::sort(bodies.begin(), bodies.end(), [](const Body& a, const Body& b) { return a.box.x0 < b.box.x0; });
    for (size_t i = 0; i < bodies.size(); ++i)
      for (size_t j = i + 1; j < bodies.size() && bodies[j].box.x0 <= bodies[i].box.x1; ++j) {
        ++done;
        const Body& a = bodies[i];
        const Body& b = bodies[j];
        if (a.box.y1 < b.box.y0 || b.box.y1 < a.box.y0 || a.entity == b.entity) continue;
        if (solidPair(a.entity->filter, b.entity->filter) && overlapsInterior(a.verts, b.verts)) ++count;
      }
  }
  if (work) *work = done;
  return count;
}

}  // namespace platon::physics
