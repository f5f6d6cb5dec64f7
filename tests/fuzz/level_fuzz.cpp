// libFuzzer target: the level parser and everything after it. Any text is either refused with a
// StageError that names the file and a line, or loads: it writes back to the same level, checks on
// its stage, builds into a world without the physics library refusing anything, and plays a few
// frames. Anything else (another exception, a crash, a sanitizer report) is a bug.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_bug.h"
#include "platon/stage/level_check.h"

using namespace platon;

namespace {

// The game's rules for what the player passes through (scripts/rules/game.lua): edges, the goal,
// checkpoints and switches; doors stay shut. The level check counts lines as walls the same way.
class TriggerRules final : public physics::Rules {
 public:
  bool pierce(physics::EntityId, const physics::LineRef& line) override {
    return line.kind == physics::LineKind::Warp || stage::gameTags()->playerPasses(line.tag);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  stage::Level level;
  try {
    level = stage::parseLevel(text, "f.level");
  } catch (const stage::StageError& e) {
    if (e.where().file != "f.level" || e.where().line <= 0)
      bug(std::string("a refusal without a position: ") + e.what(), text);
    return 0;
  }
  if (!(stage::parseLevel(stage::writeLevel(level), "f.level") == level)) bug("writeLevel does not round-trip", text);
  if (!level.solid) return 0;  // a mesh level: the mesh is another fuzzer's
  stage::Stage stage = stage::platonicStageOf(level);
  try {
    stage::checkLevelOnStage(level, stage);
  } catch (const stage::StageError& e) {
    if (e.where().line <= 0) bug(std::string("a refusal without a position: ") + e.what(), text);
    return 0;
  }
  try {
    physics::World world;
    TriggerRules rules;
    world.setRules(&rules);
    stage::buildLevel(level, stage, world, 0, 22938);
    for (size_t f = 0; f < stage.faceCount(); ++f) world.mapPart(stage.part(f)).initialize();
    const physics::EntityId player = world.createEntity(physics::Convex::regular(16, 96));
    world.insert(player, stage.part(static_cast<size_t>(level.start.face)), level.start.position, 0);
    for (int frame = 0; frame < 20; ++frame) world.solve();
    if (world.countOverlaps() != 0) bug("the player overlaps a line", text);
    (void)stage::checkLevel(level, stage);
  } catch (const std::exception& e) {
    bug(std::string("a checked level failed to build or play: ") + e.what(), text);
  }
  return 0;
}
