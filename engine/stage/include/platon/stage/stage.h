// A stage: a convex solid made ready to play on. Each face gets a 2D frame in whole units (its
// corners, counter-clockwise, corner 0 at the origin and corner 1 on +x: edge 0 is the face's
// floor), the map that places it in 3D, and its neighbour across every edge. The rule that picks
// each face's floor and the faces' numbering is in docs/level-format.md ("Faces and their frames").
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "platon/physics/world.h"
#include "platon/stage/polyhedron.h"

namespace platon::stage {

struct Neighbour {
  int face = -1;  // the face across this edge
  int edge = -1;  // the same edge's index in that face
};

struct StageFace {
  std::vector<physics::Vec2> corners;  // in the face's frame, counter-clockwise from outside
  std::vector<Neighbour> neighbours;   // across edge i, from corner i to corner i + 1
  // The face's frame in 3D: the face point (x, y) is at origin + x * xAxis + y * yAxis; normal
  // points out of the solid. Units are the level's in both.
  Eigen::Vector3d origin, xAxis, yAxis, normal;
  int sourceFace = -1;  // the polyhedron's face this one was made from

  Eigen::Vector3d toWorld(double x, double y) const { return origin + x * xAxis + y * yAxis; }
};

struct Stage {
  std::vector<StageFace> faces;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // the solid's centre (mean of its face centres)
  physics::MapPartId firstPart = 0;                  // face i is map part firstPart + i in the world

  size_t faceCount() const { return faces.size(); }
  physics::MapPartId part(size_t face) const { return firstPart + static_cast<physics::MapPartId>(face); }
};

// Frames, numbering and neighbours for the solid `p`, whose coordinates are in level units.
// Validates `p` first (validatePolyhedron) and throws StageError for a bad solid or one whose
// faces do not fit the physics coordinate range.
Stage stageFromPolyhedron(const Polyhedron& p);

// Creates one map part per face (ids firstPart, firstPart + 1, ...) with a warp line along every
// edge to the neighbour's copy of it, and records firstPart in `stage`. The caller adds the level's
// lines and initializes the parts.
void addStageToWorld(Stage& stage, physics::World& world, physics::MapPartId firstPart);

// A Platonic solid with edges `edge` units long as a stage (not yet in a world).
Stage platonicStage(Solid solid, int32_t edge);

}  // namespace platon::stage
