// The five solids as stages: their shape, frames and warps, and bodies crossing every edge.
#include "platon/stage/stage.h"

#include <cmath>

#include <gtest/gtest.h>

#include "platon/stage/mesh.h"
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
    for (const int32_t edge : {64, 999, 4096, 100000, 1 << 24}) {  // the level format's whole range
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

namespace {

// A cube as 12 triangles (two per face), counter-clockwise from outside.
stage::MeshData cubeMesh() {
  stage::MeshData m;
  for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

std::string meshRefusal(const stage::MeshData& m) {
  try {
    stage::polyhedronFromMesh(m, 1000);
  } catch (const stage::StageError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(MeshBuilder, ACubeOfTrianglesBecomesSixSquares) {
  const stage::Polyhedron p = stage::polyhedronFromMesh(cubeMesh(), 1000);
  ASSERT_EQ(p.faces.size(), 6u);
  for (const auto& f : p.faces) EXPECT_EQ(f.size(), 4u);
  // Turned inside out (every triangle clockwise) it is turned back.
  stage::MeshData inside = cubeMesh();
  for (auto& t : inside.triangles) std::swap(t[1], t[2]);
  EXPECT_EQ(stage::polyhedronFromMesh(inside, 1000).faces.size(), 6u);
  // STL-style: every triangle with its own three points.
  stage::MeshData loose;
  for (const auto& t : cubeMesh().triangles) {
    const int base = static_cast<int>(loose.positions.size());
    for (const int v : t) loose.positions.push_back(cubeMesh().positions[size_t(v)]);
    loose.triangles.push_back({base, base + 1, base + 2});
  }
  EXPECT_EQ(stage::polyhedronFromMesh(loose, 1000).faces.size(), 6u);
}

TEST(MeshBuilder, EveryBrokenMeshSaysWhatIsWrongAndWhere) {
  stage::MeshData open = cubeMesh();
  open.triangles.pop_back();
  EXPECT_NE(meshRefusal(open).find("open mesh: the edge"), std::string::npos) << meshRefusal(open);
  stage::MeshData flipped = cubeMesh();
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  EXPECT_NE(meshRefusal(flipped).find("run the same way along the edge"), std::string::npos) << meshRefusal(flipped);
  stage::MeshData threeWay = cubeMesh();
  threeWay.positions.emplace_back(0.5, 0.5, 2);
  threeWay.triangles.push_back({4, 5, 8});  // a fin on the top edge 4 -> 5
  EXPECT_NE(meshRefusal(threeWay).find("non-manifold"), std::string::npos) << meshRefusal(threeWay);
  stage::MeshData dent = cubeMesh();
  dent.positions[7] = {0.6, 0.6, 0.6};  // a corner pushed in
  EXPECT_NE(meshRefusal(dent).find("not convex"), std::string::npos) << meshRefusal(dent);
  stage::MeshData flat = cubeMesh();
  flat.positions.emplace_back(0.5, 0, 0);  // on the edge from point 0 to point 1
  flat.triangles.push_back({0, 1, 8});
  EXPECT_EQ(meshRefusal(flat),
            "triangle 12 is degenerate: its corners (0, 0, 0), (1, 0, 0) and (0.5, 0, 0) lie on one line (no area)");
  stage::MeshData missing = cubeMesh();
  missing.triangles[5][2] = 99;
  EXPECT_EQ(meshRefusal(missing), "triangle 5 names vertex 99, which does not exist");
  stage::MeshData nan = cubeMesh();
  nan.positions[2].x() = std::nan("");
  EXPECT_EQ(meshRefusal(nan), "vertex 2 is not a finite point of sensible size (within 1e15)");
  EXPECT_EQ(meshRefusal({}), "a closed solid needs at least 4 triangles, the mesh has 0");
}

}  // namespace
