// Entities and their instances: plain data, read through World::entity(), changed through World.
#pragma once
#include <vector>

#include "platon/physics/convex.h"
#include "platon/physics/ids.h"
#include "platon/physics/region.h"

namespace platon::physics {

// One copy of an entity in one map part. While an entity straddles a warp edge it has an instance
// on each side; instance 0 (the anchor) defines the entity's frame.
struct Instance {
  MapPartId part = 0;
  Vec2 position;           // the entity origin in the part's coordinates
  Angle frame = 0;         // rotation from the entity frame into this part (0 for the anchor)
  Rotation rotation;       // rotationOf(frame)
  // Where a non-anchor instance should be, in Q30 (2^30 per unit): the anchor's position mapped
  // through the warps. Each sub-move aims at it, so rounding never accumulates into drift.
  Vec2w idealQ30;
  std::vector<Vec2> shape; // vertices relative to position: the entity shape turned by angle + frame
  std::vector<LineIndex> overlapping;  // pierceable lines whose interior this instance overlaps
  std::vector<LineIndex> blockedWarps; // warps that could not be crossed this frame (act solid)
  Region region;
};

// Two instances joined through a warp edge; the pair lives while the entity straddles the edge.
struct WarpLink {
  MapPartId fromPart = 0;
  LineIndex warpLine = 0;  // in fromPart
  MapPartId toPart = 0;
  // Each side's contact with its edge: 0 apart, 1 touching, 2 overlapping.
  uint8_t fromState = 0;
  uint8_t toState = 0;
};

// A velocity held within the largest move per frame (2^30 units, in Q16), component by component.
// Projections along sloped lines and turns into another frame can push one component up to sqrt(2)
// times past it; the world clamps there so every velocity it holds is one setVelocity accepts.
inline Vec2w clampVelocityQ16(Vec2w v) {
  const int64_t limit = int64_t{kMaxMove} << 16;
  return {v.x < -limit ? -limit : (v.x > limit ? limit : v.x), v.y < -limit ? -limit : (v.y > limit ? limit : v.y)};
}

// The instance's vertices in its part's coordinates.
inline void worldVertices(const Instance& inst, std::vector<Vec2>& out) {
  out.resize(inst.shape.size());
  for (size_t i = 0; i < inst.shape.size(); ++i)
    out[i] = {inst.position.x + inst.shape[i].x, inst.position.y + inst.shape[i].y};
}
inline std::vector<Vec2> worldVertices(const Instance& inst) {
  std::vector<Vec2> out;
  worldVertices(inst, out);
  return out;
}

struct Entity {
  explicit Entity(Convex s) : shape(std::move(s)) {}

  Convex shape;               // as created, unrotated
  Angle angle = 0;            // rotation of the shape in the entity (anchor) frame
  Vec2w velocityQ16;          // 1/65536 units per frame, entity frame
  Vec2w subunitQ17;           // motion below one unit (1/131072 units), carried to the next frame
  int32_t angularVelocity = 0;  // binary-angle units per frame
  bool gravity = true;        // the anchor part's gravity applies
  uint64_t userData = 0;
  std::vector<Instance> instances;
  std::vector<WarpLink> links;

  const Instance* instanceIn(MapPartId part) const {
    for (const Instance& i : instances)
      if (i.part == part) return &i;
    return nullptr;
  }
};

}  // namespace platon::physics
