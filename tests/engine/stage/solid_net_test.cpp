#include "platon/stage/solid_net.h"

#include <set>

#include <gtest/gtest.h>

using namespace platon;
using physics::Vec2;

// Every edge warps to a neighbour whose matching edge warps straight back.
TEST(SolidNet, EveryEdgeWarpsToItsNeighbourAndBack) {
  for (const auto type : {stage::SolidType::Tetrahedron, stage::SolidType::Hexahedron}) {
    physics::World world;
    const stage::SolidNet net = stage::buildSolidNet(world, type, 1000, 10);
    for (const physics::MapPartId id : net.parts) {
      const physics::MapPart& part = world.mapPart(id);
      ASSERT_EQ(part.warps().size(), net.corners[id - 10].size());
      for (size_t w = 0; w < part.warps().size(); ++w) {
        const physics::Warp& warp = part.warps()[w];
        const physics::Segment here = part.segments()[w];
        const physics::MapPart& other = world.mapPart(warp.target);
        int back = 0;
        for (size_t v = 0; v < other.warps().size(); ++v)
          if (other.warps()[v].target == id && other.segments()[v].a == warp.targetSegment.b &&
              other.segments()[v].b == warp.targetSegment.a && other.warps()[v].targetSegment.a == here.b &&
              other.warps()[v].targetSegment.b == here.a)
            ++back;
        EXPECT_EQ(back, 1) << "face " << id << " edge " << w;
      }
    }
  }
}

// A ball thrown across a cube's faces with each face's own gravity never overlaps a line and
// always has an instance somewhere.
TEST(SolidNet, BallTravelsAroundTheCube) {
  physics::World world;
  const stage::SolidNet net = stage::buildSolidNet(world, stage::SolidType::Hexahedron, 4096, 0);
  for (const physics::MapPartId id : net.parts) {
    world.mapPart(id).line({256, 512}, {2600, 512});
    world.mapPart(id).setGravity({0, -6000});
    world.mapPart(id).initialize();
  }
  const physics::EntityId ball = world.createEntity(physics::Convex::regular(16, 96));
  world.insert(ball, 0, {600, 700}, 0);
  world.setVelocity(ball, {24 * 65536, 0});
  std::set<physics::MapPartId> visited;
  for (int f = 0; f < 3000; ++f) {
    world.solve();
    ASSERT_EQ(world.countOverlaps(), 0u);
    ASSERT_TRUE(world.entity(ball).inserted());
    visited.insert(world.entity(ball).instance(0).part);
  }
  EXPECT_GE(visited.size(), 3u);
}
