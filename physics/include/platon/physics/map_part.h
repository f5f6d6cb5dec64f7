// A map part: the lines of one face of the solid, in that face's own 2D coordinates.
#pragma once
#include <memory>
#include <span>
#include <vector>

#include "platon/physics/angle.h"
#include "platon/physics/ids.h"
#include "platon/physics/sweep.h"

namespace platon::physics {

class Grid;  // internal: which lines pass through which cell
struct WorldImpl;

// Solid: stops every entity (unless Rules::pierce lets it through). Warp: an edge shared with
// another part. OneWay: a platform you can jump up through and stand on: solid only to an instance
// wholly on its front (left of p0 -> p1, "up" for a line drawn left to right) when it comes near;
// from behind, or while overlapping it, it lets the instance through.
enum class LineKind : uint8_t { Solid, Warp, OneWay };

// A line's geometry is segments()[index]; this is the rest of it.
struct Line {
  uint32_t tag = 0;  // free for rules and scripts: material, trigger id, ...
  LineKind kind = LineKind::Solid;
  uint32_t warp = UINT32_MAX;  // index into warps() when kind == Warp
};

// A warp line p0 -> p1 is the same edge as target t0 -> t1 in another part: crossing it moves the
// entity there. Convention: a face lies to the left of its warp lines (counter-clockwise order),
// so the target face lies to the right of t0 -> t1, and its own warp back is t1 -> t0.
struct Warp {
  MapPartId target = 0;
  Segment targetSegment;
  Angle turn = 0;     // rotation from this part's frame into the target's
  Rotation rotation;  // rotationOf(turn), cached
};

class MapPart {
 public:
  MapPartId id() const { return id_; }

  // Adds a solid line; returns its index. Throws on zero length, range, or after initialize().
  LineIndex line(Vec2 p0, Vec2 p1, uint32_t tag = 0);
  // Adds solid lines in bulk, as a loader holds them; returns the first one's index. All are checked
  // first: one bad segment adds none.
  LineIndex lines(std::span<const Segment> segments, uint32_t tag = 0);
  // Adds a one-way line, solid from its left side only (see LineKind::OneWay).
  LineIndex oneWay(Vec2 p0, Vec2 p1, uint32_t tag = 0);
  // Adds a warp line to part `target`, where the same edge runs t0 -> t1. The two edges should be
  // equally long (a solid's edges are); they may differ by rounding, up to 1% or 2 units.
  LineIndex warp(Vec2 p0, Vec2 p1, MapPartId target, Vec2 t0, Vec2 t1, uint32_t tag = 0);
  // Gravity in this part's frame, in 1/65536 units per frame per frame; at most 2^30 units per
  // frame per frame in each component.
  void setGravity(Vec2w gravityQ16);
  Vec2w gravity() const { return gravity_; }

  // Room for `count` lines in all: a loader that knows the count saves the vectors' regrowth.
  void reserve(size_t count);

  // Builds the grid; lines cannot be added afterwards. The world checks that every warp's target
  // part exists when it next inserts or solves (targets may be created after this part).
  void initialize();
  bool initialized() const { return initialized_; }

  std::span<const Line> lines() const { return lines_; }
  std::span<const Segment> segments() const { return segments_; }
  std::span<const Warp> warps() const { return warps_; }
  // When the part's warp lines close into one convex counter-clockwise loop (a face of a solid, as
  // the stage builds them), that loop's line indices in order, from initialize() on; else empty.
  // The world keeps an entity on such a face when it goes through a corner (docs/physics.md).
  std::span<const LineIndex> faceLoop() const { return faceLoop_; }
  size_t memoryBytes() const;

  MapPart(MapPart&&) noexcept;
  MapPart& operator=(MapPart&&) noexcept;
  ~MapPart();

 private:
  friend class World;
  friend struct WorldImpl;
  explicit MapPart(MapPartId id);
  void checkOpen(const char* what) const;
  void checkSegment(Vec2 p0, Vec2 p1, const char* what, size_t index) const;
  LineIndex add(Line line, Segment segment);
  void findFaceLoop();
  const Grid& grid() const { return *grid_; }

  MapPartId id_;
  bool initialized_ = false;
  Vec2w gravity_;
  std::vector<Line> lines_;
  std::vector<Segment> segments_;                                // parallel to lines_, packed for the sweep loops
  Vec2 low_{INT32_MAX, INT32_MAX}, high_{INT32_MIN, INT32_MIN};  // the box around them, kept as they come
  std::vector<Warp> warps_;
  std::vector<LineIndex> faceLoop_;
  std::unique_ptr<Grid> grid_;
};

}  // namespace platon::physics
