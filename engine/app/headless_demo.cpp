// Until the game lands: a headless run of the physics on a cube. A ball rolls along platforms on
// the cube's faces; every time it crosses an edge, the face it is on, and with it "down", changes.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "level/solid_net.h"

using namespace platon;
using physics::Vec2;

int main(int argc, char** argv) {
  int frames = 3000;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
      frames = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--frames N]\n", argv[0]);
      return 2;
    }
  }
  physics::World world;
  constexpr int32_t kEdge = 4096;
  const level::SolidNet cube = level::buildSolidNet(world, level::SolidType::Hexahedron, kEdge, 0);
  for (const physics::MapPartId id : cube.parts) {
    physics::MapPart& face = world.mapPart(id);
    // A floor with a gap, and a ramp: enough to fall off, roll and climb onto another face.
    face.line({256, 512}, {2600, 512});
    face.line({3000, 512}, {3800, 900});
    face.line({1200, 1800}, {2400, 1800});
    face.setGravity({0, -6000});  // "down" is -y in every face's own frame
    face.initialize();
  }
  const physics::EntityId ball = world.createEntity(physics::Convex::regular(16, 96));
  world.insert(ball, cube.parts[0], {600, 700}, 0);
  world.setVelocity(ball, {24 * 65536, 0});

  std::printf("Platon headless demo: a ball on a cube of %d-unit faces, %d frames\n", kEdge, frames);
  physics::MapPartId face = cube.parts[0];
  int crossings = 0;
  for (int f = 1; f <= frames; ++f) {
    world.solve();
    const physics::EntityView e = world.entity(ball);
    if (world.countOverlaps() != 0) {
      std::printf("frame %d: INVARIANT BROKEN: an instance overlaps a solid line\n", f);
      return 1;
    }
    // Keep it rolling: push along the face's x axis when it is slow.
    if (e.velocity().x > -8 * 65536 && e.velocity().x < 8 * 65536)
      world.setVelocity(ball, {(f / 500) % 2 ? -24 * 65536 : 24 * 65536, e.velocity().y});
    if (e.instance(0).part != face) {
      face = e.instance(0).part;
      ++crossings;
      const Vec2 p = e.instance(0).position;
      std::printf("frame %5d: crossed onto face %u at (%d, %d), velocity (%.2f, %.2f) units/frame\n", f, face, p.x, p.y,
                  static_cast<double>(e.velocity().x) / 65536.0, static_cast<double>(e.velocity().y) / 65536.0);
    }
  }
  const physics::EntityView e = world.entity(ball);
  std::printf("after %d frames: face %u, position (%d, %d), %d edge crossings, no overlap on any frame\n", frames,
              e.instance(0).part, e.instance(0).position.x, e.instance(0).position.y, crossings);
  std::printf("state hash %016llx\n", static_cast<unsigned long long>(world.stateHash()));
  return 0;
}
