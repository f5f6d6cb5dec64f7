#include "platon/stage/stage.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "platon/stage/stage_error.h"

namespace platon::stage {
namespace {

struct Frame {
  int floorEdge = 0;  // index in the polyhedron's cycle
  Eigen::Vector3d normal;
};

Eigen::Vector3d corner(const Polyhedron& p, size_t face, size_t i) {
  const auto& cycle = p.faces[face];
  return p.vertices[static_cast<size_t>(cycle[i % cycle.size()])];
}

// How near two directions (unit vectors, cosines) or two positions (over the solid's size) may be
// and count as a tie: a mesh file's 32-bit floats carry about 1e-7 of noise (more after a node's
// rotation), which must not pick a floor or face 0 (docs/level-format.md).
constexpr double kTie = 1e-6;

// The face's "down": the world's -y laid onto the face; for a face looking straight up or down
// (its normal within 1e-6 of +-y), the world's -z laid onto it (away from the default camera).
Eigen::Vector3d downOn(const Eigen::Vector3d& normal) {
  const double flat = kTie;
  Eigen::Vector3d down = -Eigen::Vector3d::UnitY() + normal.y() * normal;
  if (down.norm() < flat) down = -Eigen::Vector3d::UnitZ() + normal.z() * normal;
  return down.normalized();
}

// The floor: the edge whose outward direction in the face's plane points most along "down"; of
// edges within 1e-6 of the best (a corner pointing straight down), the first in the face's cycle
// (a mesh face's cycle starts at the corner the file's triangles use first).
Frame frameOf(const Polyhedron& p, size_t face) {
  Frame frame{0, faceNormal(p, face)};
  const Eigen::Vector3d down = downOn(frame.normal);
  const size_t n = p.faces[face].size();
  std::vector<double> facing(n);
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d along = (corner(p, face, i + 1) - corner(p, face, i)).normalized();
    facing[i] = along.cross(frame.normal).dot(down);  // outward = along x normal
  }
  const double best = *std::max_element(facing.begin(), facing.end());
  while (facing[static_cast<size_t>(frame.floorEdge)] < best - kTie) ++frame.floorEdge;
  return frame;
}

// Face 0 looks most along +z (ties within 1e-6: lowest centre, then leftmost, within 1e-6 of the
// solid's size; then the first in the polyhedron's order). Then: the right-hand neighbour (across
// edge 1) of the face numbered last, while it has no number; when it has one, the first face in
// number order with a face not numbered yet across its edges 1, 2, ..., 0.
std::vector<size_t> numbering(const Polyhedron& p, const std::vector<Frame>& frames,
                              const std::vector<std::vector<std::pair<size_t, int>>>& across) {
  const size_t count = p.faces.size();
  const double near = kTie * sizeOf(p);
  size_t first = 0;
  for (size_t f = 1; f < count; ++f) {
    const double dz = frames[f].normal.z() - frames[first].normal.z();
    const Eigen::Vector3d a = faceCentre(p, f), b = faceCentre(p, first);
    if (dz > kTie ||
        (dz > -kTie && (a.y() < b.y() - near || (std::abs(a.y() - b.y()) <= near && a.x() < b.x() - near))))
      first = f;
  }
  std::vector<size_t> order{first};
  std::vector<bool> numbered(count, false);
  numbered[first] = true;
  size_t open = 0;
  // across[f][k]: the face across the frame's edge k of face f (k = 0 is the floor).
  while (order.size() < count) {
    const size_t right = across[order.back()][1].first;
    if (!numbered[right]) {
      numbered[right] = true;
      order.push_back(right);
      continue;
    }
    // Faces before `open` have every neighbour numbered and keep it so: start there (linear, not
    // quadratic, in the faces of a big mesh).
    bool found = false;
    for (size_t i = open; i < order.size() && !found; ++i) {
      const size_t n = across[order[i]].size();
      for (size_t k = 1; k <= n && !found; ++k) {
        const size_t next = across[order[i]][k % n].first;
        if (numbered[next]) continue;
        numbered[next] = true;
        order.push_back(next);
        found = true;
      }
      if (!found) open = i + 1;
    }
  }
  return order;
}

// Rounded to whole units, a face must stay a convex polygon, and the two copies of an edge must
// stay as long as the physics library accepts for a warp (within 1% or 2 units).
void checkWholeUnits(const Stage& stage) {
  for (size_t f = 0; f < stage.faceCount(); ++f) {
    const auto& c = stage.faces[f].corners;
    const size_t n = c.size();
    for (size_t i = 0; i < n; ++i) {
      const physics::Vec2 a = c[i], b = c[(i + 1) % n], d = c[(i + 2) % n];
      const int64_t turn = (int64_t{b.x} - a.x) * (int64_t{d.y} - b.y) - (int64_t{b.y} - a.y) * (int64_t{d.x} - b.x);
      if (turn <= 0)
        throw StageError({}, "face " + std::to_string(f) +
                                 " is too small or too thin to lay out in whole units (corner " +
                                 std::to_string((i + 1) % n) + " is not convex once rounded): make the stage larger");
      const auto [g, j] = stage.faces[f].neighbours[i];
      const auto& o = stage.faces[static_cast<size_t>(g)].corners;
      const double here = std::hypot(double(b.x) - a.x, double(b.y) - a.y);
      const physics::Vec2 p = o[static_cast<size_t>(j)], q = o[(static_cast<size_t>(j) + 1) % o.size()];
      const double there = std::hypot(double(q.x) - p.x, double(q.y) - p.y);
      if (std::abs(here - there) > std::max(2.0, 0.01 * std::max(here, there)))
        throw StageError({}, "the edge between faces " + std::to_string(f) + " and " + std::to_string(g) +
                                 " comes out " + std::to_string(here) + " and " + std::to_string(there) +
                                 " units long in whole units: make the stage larger");
    }
  }
}

}  // namespace

Stage stageFromPolyhedron(const Polyhedron& p) {
  const double size = sizeOf(p);
  validatePolyhedron(p, 1e-6 * size);  // a mesh file's floats hold about 7 digits
  const size_t count = p.faces.size();
  std::vector<Frame> frames(count);
  for (size_t f = 0; f < count; ++f) frames[f] = frameOf(p, f);

  // across[f][k] for frame edge k (cycle edge floorEdge + k): the neighbour and its cycle edge.
  std::map<std::pair<int, int>, std::pair<size_t, int>> edgeOwner;
  for (size_t f = 0; f < count; ++f)
    for (size_t i = 0; i < p.faces[f].size(); ++i)
      edgeOwner[{p.faces[f][i], p.faces[f][(i + 1) % p.faces[f].size()]}] = {f, static_cast<int>(i)};
  std::vector<std::vector<std::pair<size_t, int>>> across(count);
  for (size_t f = 0; f < count; ++f) {
    const auto& cycle = p.faces[f];
    for (size_t k = 0; k < cycle.size(); ++k) {
      const size_t i = (static_cast<size_t>(frames[f].floorEdge) + k) % cycle.size();
      across[f].push_back(edgeOwner.at({cycle[(i + 1) % cycle.size()], cycle[i]}));
    }
  }
  const std::vector<size_t> order = numbering(p, frames, across);
  std::vector<int> numberOf(count);
  for (size_t n = 0; n < count; ++n) numberOf[order[n]] = static_cast<int>(n);

  Stage stage;
  for (size_t n = 0; n < count; ++n) {
    const size_t f = order[n];
    const size_t sides = p.faces[f].size();
    const auto floor = static_cast<size_t>(frames[f].floorEdge);
    StageFace face;
    face.sourceFace = static_cast<int>(f);
    face.normal = frames[f].normal;
    face.origin = corner(p, f, floor);
    face.xAxis = (corner(p, f, floor + 1) - face.origin).normalized();
    face.yAxis = face.normal.cross(face.xAxis);
    for (size_t k = 0; k < sides; ++k) {
      const Eigen::Vector3d d = corner(p, f, floor + k) - face.origin;
      const double x = std::round(d.dot(face.xAxis)), y = std::round(d.dot(face.yAxis));
      if (std::abs(x) > (1 << 29) || std::abs(y) > (1 << 29))
        throw StageError({},
                         "face " + std::to_string(n) + " is too large for the physics coordinate range (2^29 units)");
      face.corners.push_back({static_cast<int32_t>(x), static_cast<int32_t>(y)});
      const auto [g, i] = across[f][k];
      const int gFloor = frames[g].floorEdge;
      const int gSides = static_cast<int>(p.faces[g].size());
      face.neighbours.push_back({numberOf[g], ((i - gFloor) % gSides + gSides) % gSides});
    }
    stage.faces.push_back(std::move(face));
    stage.centre += faceCentre(p, f);
  }
  stage.centre /= static_cast<double>(count);
  checkWholeUnits(stage);
  return stage;
}

void addStageToWorld(Stage& stage, physics::World& world, physics::MapPartId firstPart) {
  stage.firstPart = firstPart;
  for (size_t f = 0; f < stage.faces.size(); ++f) world.createMapPart(stage.part(f));
  // Edge i (u -> v) of face f is edge j (v -> u) of its neighbour g: its warp target runs u -> v
  // in g's frame, that is from g's corner j + 1 to its corner j.
  for (size_t f = 0; f < stage.faces.size(); ++f) {
    const StageFace& face = stage.faces[f];
    const size_t n = face.corners.size();
    for (size_t i = 0; i < n; ++i) {
      const auto [g, j] = face.neighbours[i];
      const StageFace& other = stage.faces[static_cast<size_t>(g)];
      const size_t m = other.corners.size();
      world.mapPart(stage.part(f))
          .warp(face.corners[i], face.corners[(i + 1) % n], stage.part(static_cast<size_t>(g)),
                other.corners[(static_cast<size_t>(j) + 1) % m], other.corners[static_cast<size_t>(j)]);
    }
  }
}

Stage platonicStage(Solid solid, int32_t edge) { return stageFromPolyhedron(platonicSolid(solid, edge)); }

}  // namespace platon::stage
