#include "platon/stage/level_check.h"

#include <algorithm>
#include <cmath>

#include "face_geometry.h"
#include "reach_search.h"
#include "walls_near.h"

namespace platon::stage {

bool goalReachable(const Level& level, const Stage& stage) { return searchReach(level, stage).reachable; }

CheckReport checkLevel(const Level& level, const Stage& stage) {
  CheckReport report;
  try {
    checkLevelOnStage(level, stage);
  } catch (const StageError& e) {
    report.errors.push_back({e.where(), e.reason()});
    return report;
  }
  std::string empty;
  int firstEmptyLine = 0, emptyCount = 0;
  for (size_t f = 0; f < level.faces.size(); ++f) {
    const LevelFace& face = level.faces[f];
    if (face.lines.empty() && static_cast<int>(f) != level.start.face && static_cast<int>(f) != level.goal.face) {
      empty += (empty.empty() ? "" : ", ") + std::to_string(f);
      if (!firstEmptyLine) firstEmptyLine = face.sourceLine;
      ++emptyCount;
    }
    const auto& corners = stage.faces[f].corners;
    for (const LevelLine& l : face.lines)
      for (size_t k = 0; k < corners.size(); ++k) {
        const physics::Vec2 a = corners[k], b = corners[(k + 1) % corners.size()];
        const double len = std::hypot(double(b.x) - a.x, double(b.y) - a.y);
        if (std::abs(side(a, b, l.a.x, l.a.y)) / len > 1 || std::abs(side(a, b, l.b.x, l.b.y)) / len > 1) continue;
        if (!counts(l, Counting::Reach)) continue;
        report.warnings.push_back({{level.file, l.sourceLine, l.sourceColumn},
                                   "the segment lies along edge " + std::to_string(k) + " of face " + std::to_string(f) +
                                       ": it blocks the way to face " + std::to_string(stage.faces[f].neighbours[k].face)});
      }
  }
  if (emptyCount)
    report.warnings.push_back(Finding{SourcePosition{level.file, firstEmptyLine, 1},
                                      (emptyCount == 1 ? "face " + empty + " has" : "faces " + empty + " have") + " no lines"});
  const ReachAnswer reach = searchReach(level, stage);
  if (reach.finestCell > kFinestCell)
    report.warnings.push_back({{level.file, level.goal.sourceLine, level.goal.sourceColumn},
                               "the reachability search used cells of " + std::to_string(int(reach.finestCell)) +
                                   " units near walls (the level's walls are very long): a gap narrower than " +
                                   std::to_string(int(2 * kPlayerRadius + 3 * reach.finestCell)) + " units may count as closed"});
  if (!reach.reachable)
    report.errors.push_back({{level.file, level.goal.sourceLine, level.goal.sourceColumn},
                             "no path reaches the goal from the start (walls seal it off; see docs/level-format.md, "
                             "\"platon check\")"});
  return report;
}

}  // namespace platon::stage
