// The editor's edit to playable: on a cube level of 10^4 random short segments (and 10^3, 10^5),
// one edit as the editor makes it (a segment drawn: the level written over its text keeping every
// other line, read back and compared; then the world built, the picture's stage made and the
// check run), against the baseline of the same level loaded from its text as the game does
// (parse, check on the stage, build), measured in the same run. Goal: edit to playable (the world
// built and drawable) within one 60 Hz frame, 16 ms, at 10^4 segments; the check's findings are
// part of the same frame. Also the editor's own picture per frame (its overlays and palette into a
// draw list, its view): the game's render budget is the frame, so it must be a small part of it.
//
// usage: build/bench/edit_latency [--runs N]
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "platon/editor/editor.h"
#include "platon/testing/rng.h"
#include "spread.h"

using namespace platon;
using Clock = std::chrono::steady_clock;

namespace {

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// A cube of face 4096 with `segments` short random segments spread over its faces, the start and
// goal on face 0's floor, clear of them.
std::string levelText(int segments, uint64_t seed) {
  platon::testing::Rng rng{seed};
  std::string text = "# a busy cube\nHEXAHEDRON\n0 600 400   # start\n0 3400 400   # goal\n4096\n";
  for (int f = 0; f < 6; ++f) {
    text += "%   # face " + std::to_string(f) + "\n";
    if (f == 0) text += "100 200 3996 200   # the floor\n";
    for (int i = 0; i < segments / 6; ++i) {
      const int x = rng.between(50, 4040), y = rng.between(f == 0 ? 800 : 50, 4040);
      const int dx = rng.between(-40, 40), dy = rng.between(1, 40);
      text += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(std::clamp(x + dx, 1, 4095)) + " " +
              std::to_string(std::min(y + dy, 4095)) + "\n";
    }
  }
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 21;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc) runs = std::max(3, std::atoi(argv[++i]));
  std::printf("edit to playable (ms, median (min-max) of %d edits), against loading the same level as the game does\n",
              runs);
  std::printf("%9s %22s %22s %22s %22s %8s %16s\n", "segments", "edit (write+read)", "playable (+world,view)",
              "+ check", "game's load (baseline)", "ratio", "editor picture");
  for (const int segments : {1000, 10000, 100000}) {
    const std::string text = levelText(segments, 7);
    editor::LevelDocument document("busy.level", text, stage::gameTags());
    stage::Stage solid = stage::platonicStageOf(document.level());
    editor::Editor editor(std::move(document), std::move(solid), 22938);
    std::vector<double> edit, playable, checked, load, picture;
    platon::testing::Rng rng{11};
    for (int r = 0; r < runs; ++r) {
      // The game's load of the level as it stands (the baseline), then one edit, as in the editor.
      const std::string now = editor.document().text();
      auto t = Clock::now();
      {
        stage::Level level = stage::parseLevel(now, "busy.level");
        stage::Stage s = stage::platonicStageOf(level);
        stage::checkLevelOnStage(level, s);
        physics::World world;
        stage::buildLevel(level, s, world, 0, 22938);
        for (size_t f = 0; f < s.faceCount(); ++f) world.mapPart(s.part(f)).initialize();
      }
      load.push_back(msSince(t));
      const int x = rng.between(100, 3900), y = rng.between(900, 3900);
      const stage::LevelLine line{{x, y}, {x + 64, y}, false, 0};
      t = Clock::now();
      editor.document().edit("draw a segment", [&](stage::Level& l) { l.faces[3].lines.push_back(line); });
      edit.push_back(msSince(t));
      t = Clock::now();
      editor.rebuild();
      checked.push_back(msSince(t) + edit.back());
      playable.push_back(editor.lastBuildMilliseconds() + edit.back());
      t = Clock::now();
      core::DrawList list(true);
      editor.draw(list);
      const core::View view = editor.view();
      picture.push_back(msSince(t));
      if (view.stage == nullptr) return 1;
    }
    const bench::Spread p = bench::Spread::of(playable), l = bench::Spread::of(load);
    std::printf("%9d %22s %22s %22s %22s %8.2f %16s\n", segments, bench::Spread::of(edit).show("%.2f").c_str(),
                p.show("%.2f").c_str(), bench::Spread::of(checked).show("%.2f").c_str(), l.show("%.2f").c_str(),
                p.median / l.median, bench::Spread::of(picture).show("%.3f").c_str());
  }
  std::printf("goal: playable <= 16 ms at 10,000 segments (one 60 Hz frame)\n");
  return 0;
}
