#include "platon/stage/level_check.h"

#include <algorithm>
#include <cmath>

#include "face_geometry.h"
#include "reach_search.h"
#include "walls_near.h"

namespace platon::stage {
namespace {

// How wide a face is: the least, over its edges, of how far its farthest corner lies from the
// edge's line (what a disk must fit across).
double widthOf(const StageFace& face) {
  const auto& c = face.corners;
  double width = INFINITY;
  for (size_t k = 0; k < c.size(); ++k) {
    const physics::Vec2 a = c[k], b = c[(k + 1) % c.size()];
    const double length = std::hypot(double(b.x) - a.x, double(b.y) - a.y);
    double farthest = 0;
    for (const physics::Vec2 p : c) farthest = std::max(farthest, side(a, b, p.x, p.y) / length);
    width = std::min(width, farthest);
  }
  return width;
}

// One warning for the faces no default player fits across (a needle of a mesh, or a tiny stage).
void warnNarrowFaces(const Level& level, const Stage& stage, CheckReport& report) {
  std::vector<size_t> narrow;
  size_t narrowest = 0;
  for (size_t f = 0; f < stage.faceCount(); ++f) {
    if (widthOf(stage.faces[f]) >= 2 * kPlayerRadius) continue;
    if (narrow.empty() || widthOf(stage.faces[f]) < widthOf(stage.faces[narrowest])) narrowest = f;
    narrow.push_back(f);
  }
  if (narrow.empty()) return;
  std::string list;
  for (size_t i = 0; i < narrow.size() && i < 10; ++i) list += (i ? ", " : "") + std::to_string(narrow[i]);
  if (narrow.size() > 10) list += " and " + std::to_string(narrow.size() - 10) + " more";
  const std::string width = std::to_string(static_cast<int>(widthOf(stage.faces[narrowest])));
  const std::string message =
      narrow.size() == 1
          ? "face " + list + " is " + width + " units wide, narrower than the default player (192 units across)"
          : "faces " + list + " are narrower than the default player (192 units across); the narrowest, face " +
                std::to_string(narrowest) + ", is " + width + " units wide";
  report.warnings.push_back(Finding{SourcePosition{level.file, level.faces[narrow[0]].sourceLine, 1}, message});
}

// Why the search could not tell: what it would have needed, and what a "no" with coarse cells means.
std::string undecidedReach(const Level& level, const ReachAnswer& reach) {
  const int cell = static_cast<int>(reach.finestCell);
  return "could not decide whether a path reaches the goal: the level's " + std::to_string(reach.walls) +
         " walls on faces of " + std::to_string(level.size) + " units need more cells of " +
         std::to_string(static_cast<int>(kFinestCell)) +
         " units than the reachability search keeps, so it stopped at cells of " + std::to_string(cell) +
         " units near walls, and with those it found no path; it may be behind a gap narrower than " +
         std::to_string(static_cast<int>(2 * kPlayerRadius + 3 * reach.finestCell)) +
         " units (play the level to be sure)";
}

}  // namespace

bool goalReachable(const Level& level, const Stage& stage) { return searchReach(level, stage).reachable; }

CheckReport checkLevel(const Level& level, const Stage& stage) {
  CheckReport report;
  warnNarrowFaces(level, stage, report);  // also when the level is refused: it may be why
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
        if (!counts(l, *level.tags, Counting::Reach)) continue;
        report.warnings.push_back({{level.file, l.sourceLine, l.sourceColumn},
                                   "the segment lies along edge " + std::to_string(k) + " of face " +
                                       std::to_string(f) + ": it blocks the way to face " +
                                       std::to_string(stage.faces[f].neighbours[k].face)});
      }
  }
  if (emptyCount)
    report.warnings.push_back(
        Finding{SourcePosition{level.file, firstEmptyLine, 1},
                (emptyCount == 1 ? "face " + empty + " has" : "faces " + empty + " have") + " no lines"});
  const ReachAnswer reach = searchReach(level, stage);
  const SourcePosition goal{level.file, level.goal.sourceLine, level.goal.sourceColumn};
  if (!reach.decided())
    report.warnings.push_back({goal, undecidedReach(level, reach)});
  else if (!reach.reachable)
    report.errors.push_back({goal,
                             "no path reaches the goal from the start (walls seal it off; see docs/level-format.md, "
                             "\"platon check\")"});
  return report;
}

}  // namespace platon::stage
