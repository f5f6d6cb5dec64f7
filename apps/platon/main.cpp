// Until the game lands: a headless run on a cube. A ball rolls along platforms on the cube's faces;
// every time it crosses an edge, the face it is on, and with it "down", changes.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "commands.h"
#include "platon/core/scene.h"

using namespace platon;
using physics::Vec2;

namespace {

constexpr int64_t kUnit = 65536;  // one unit per frame, in the velocity's Q16

// Keeps the ball rolling along its face's x axis, turning back every 500 frames, and reports each
// edge it crosses. The invariant is checked on every frame.
class Roller : public core::System {
 public:
  explicit Roller(physics::EntityId ball) : ball_(ball) {}

  void beforeStep(core::Scene& scene, const core::InputFrame&) override {
    const physics::Vec2w v = scene.world().entity(ball_).velocity();
    if (v.x > -8 * kUnit && v.x < 8 * kUnit)
      scene.world().setVelocity(ball_, {(scene.frame() / 500) % 2 ? -24 * kUnit : 24 * kUnit, v.y});
  }

  void afterStep(core::Scene& scene) override {
    if (scene.world().countOverlaps() != 0) {
      std::printf("frame %llu: INVARIANT BROKEN: an instance overlaps a solid line\n",
                  static_cast<unsigned long long>(scene.frame()));
      std::exit(1);
    }
    const physics::EntityView e = scene.world().entity(ball_);
    if (e.part() == face_) return;
    face_ = e.part();
    ++crossings_;
    std::printf("frame %5llu: crossed onto face %u at (%d, %d), velocity (%.2f, %.2f) units/frame\n",
                static_cast<unsigned long long>(scene.frame()), face_, e.position().x, e.position().y,
                static_cast<double>(e.velocity().x) / kUnit, static_cast<double>(e.velocity().y) / kUnit);
  }

  int crossings() const { return crossings_; }

 private:
  physics::EntityId ball_;
  physics::MapPartId face_ = 0;
  int crossings_ = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) {
    const std::string_view first = argv[1];
    if (first == "--help" || first == "-h" || first == "help") return platon::app::printCommands(true), 0;
    if (const platon::app::Command* command = platon::app::findCommand(first)) {
      for (int i = 2; i < argc; ++i)
        if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
          std::fputs(command->usage, stdout);
          return 0;
        }
      return command->run(argc - 1, argv + 1);
    }
  }
  int frames = 3000;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
      frames = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr, "platon: no command '%s'\n", argv[i]);
      platon::app::printCommands(false);
      return 2;
    }
  }
  core::Scene scene;
  physics::World& world = scene.world();
  constexpr int32_t kEdge = 4096;
  stage::Stage cube = stage::platonicStage(stage::Solid::Hexahedron, kEdge);
  stage::addStageToWorld(cube, world, 0);
  scene.setStage(std::move(cube));
  for (size_t i = 0; i < scene.stage()->faceCount(); ++i) {
    physics::MapPart& face = world.mapPart(scene.stage()->part(i));
    // A floor with a gap, and a ramp: enough to fall off, roll and climb onto another face.
    face.line({256, 512}, {2600, 512});
    face.line({3000, 512}, {3800, 900});
    face.line({1200, 1800}, {2400, 1800});
    face.setGravity({0, -6000});  // "down" is -y in every face's own frame
    face.initialize();
  }
  const physics::EntityId ball = world.createEntity(physics::Convex::regular(16, 96));
  world.insert(ball, scene.stage()->part(0), {600, 700}, 0);
  world.setVelocity(ball, {24 * kUnit, 0});
  auto roller = std::make_unique<Roller>(ball);
  const Roller& stats = *roller;
  scene.addSystem(std::move(roller));

  std::printf("Platon headless demo: a ball on a cube of %d-unit faces, %d frames\n", kEdge, frames);
  core::InputEdges input;
  for (int f = 1; f <= frames; ++f) scene.step(input.next(0));
  const physics::EntityView e = world.entity(ball);
  std::printf("after %d frames: face %u, position (%d, %d), %d edge crossings, no overlap on any frame\n", frames,
              e.part(), e.position().x, e.position().y, stats.crossings());
  std::printf("state hash %016llx\n", static_cast<unsigned long long>(world.stateHash()));
  return 0;
}
