// The five solids as stages: their shape, frames and warps, and bodies crossing every edge.
#include "platon/stage/stage.h"

#include <cmath>

#include <gtest/gtest.h>

#include "platon/stage/stage_error.h"

using namespace platon;
using physics::Vec2;

namespace {

double length(Vec2 a, Vec2 b) { return std::hypot(double(b.x) - a.x, double(b.y) - a.y); }

TEST(Platonic, EverySolidIsValidWithEqualEdges) {
  for (const stage::Solid solid : stage::kSolids)
    for (const double edge : {64.0, 1000.0, 4096.0, 1e6}) {
      const stage::Polyhedron p = stage::platonicSolid(solid, edge);
      EXPECT_NO_THROW(stage::validatePolyhedron(p, 1e-9 * edge)) << stage::solidName(solid);
      EXPECT_EQ(static_cast<int>(p.faces.size()), stage::faceCount(solid));
      for (const auto& f : p.faces)
        for (size_t i = 0; i < f.size(); ++i)
          EXPECT_NEAR((p.vertices[size_t(f[i])] - p.vertices[size_t(f[(i + 1) % f.size()])]).norm(), edge, 1e-9 * edge);
    }
}

TEST(Platonic, NamesRoundTrip) {
  for (const stage::Solid solid : stage::kSolids) EXPECT_EQ(stage::solidFromName(stage::solidName(solid)), solid);
  EXPECT_FALSE(stage::solidFromName("CUBE"));
}

// Corner 0 at the origin, corner 1 on +x, whole units; every edge within rounding of the solid's;
// the 3D frame puts every corner where the solid has it; face 0 looks along +z with its floor
// horizontal; neighbours are mutual.
TEST(Stage, FramesAndNeighbours) {
  for (const stage::Solid solid : stage::kSolids)
    for (const int32_t edge : {64, 999, 4096, 100000}) {
      SCOPED_TRACE(std::string(stage::solidName(solid)) + " edge " + std::to_string(edge));
      const stage::Stage s = stage::platonicStage(solid, edge);
      ASSERT_EQ(static_cast<int>(s.faceCount()), stage::faceCount(solid));
      EXPECT_NEAR(s.faces[0].normal.z(), 1.0, 1e-12);
      EXPECT_NEAR(s.faces[0].xAxis.y(), 0.0, 1e-12);
      for (size_t f = 0; f < s.faceCount(); ++f) {
        const stage::StageFace& face = s.faces[f];
        EXPECT_EQ(face.corners[0], (Vec2{0, 0}));
        EXPECT_EQ(face.corners[1].y, 0);
        const size_t n = face.corners.size();
        for (size_t i = 0; i < n; ++i) {
          EXPECT_NEAR(length(face.corners[i], face.corners[(i + 1) % n]), edge, 1.5);
          const auto [g, j] = face.neighbours[i];
          ASSERT_GE(g, 0);
          EXPECT_NE(size_t(g), f);
          EXPECT_EQ(s.faces[size_t(g)].neighbours[size_t(j)].face, int(f));
          EXPECT_EQ(s.faces[size_t(g)].neighbours[size_t(j)].edge, int(i));
          // The shared edge meets in 3D: this face's corner i is the neighbour's corner j + 1.
          const stage::StageFace& other = s.faces[size_t(g)];
          const Vec2 a = face.corners[i], b = other.corners[(size_t(j) + 1) % other.corners.size()];
          EXPECT_LT((face.toWorld(a.x, a.y) - other.toWorld(b.x, b.y)).norm(), 1.5);
        }
        EXPECT_NEAR(face.normal.dot(face.xAxis), 0, 1e-12);
        EXPECT_GT(face.normal.dot(face.origin - s.centre), 0);
      }
    }
}

// "Down" on the side faces of the cube is the world's -y, and walking right (across edge 1) from
// face 0 goes round the belt 0, 1, 2, 3 and back to 0 without turning.
TEST(Stage, CubeBeltAndDown) {
  const stage::Stage s = stage::platonicStage(stage::Solid::Hexahedron, 4096);
  int face = 0;
  for (int step = 0; step < 4; ++step) {
    EXPECT_EQ(face, step);
    EXPECT_NEAR(s.faces[size_t(face)].yAxis.y(), 1.0, 1e-12);
    EXPECT_EQ(s.faces[size_t(face)].neighbours[1].edge, 3);  // enters by the next face's left edge
    face = s.faces[size_t(face)].neighbours[1].face;
  }
  EXPECT_EQ(face, 0);
}

// Every warp's target edge warps straight back, and the two copies differ by rounding only.
TEST(Stage, EveryEdgeWarpsToItsNeighbourAndBack) {
  for (const stage::Solid solid : stage::kSolids) {
    physics::World world;
    stage::Stage s = stage::platonicStage(solid, 1000);
    stage::addStageToWorld(s, world, 10);
    for (size_t f = 0; f < s.faceCount(); ++f) {
      const physics::MapPart& part = world.mapPart(s.part(f));
      ASSERT_EQ(part.warps().size(), s.faces[f].corners.size());
      for (size_t w = 0; w < part.warps().size(); ++w) {
        const physics::Warp& warp = part.warps()[w];
        const physics::Segment here = part.segments()[w];
        const physics::MapPart& other = world.mapPart(warp.target);
        int back = 0;
        for (size_t v = 0; v < other.warps().size(); ++v)
          if (other.warps()[v].target == s.part(f) && other.segments()[v].a == warp.targetSegment.b &&
              other.segments()[v].b == warp.targetSegment.a && other.warps()[v].targetSegment.a == here.b &&
              other.warps()[v].targetSegment.b == here.a)
            ++back;
        EXPECT_EQ(back, 1) << stage::solidName(solid) << " face " << f << " edge " << w;
      }
    }
  }
}

}  // namespace
