// Checking levels against their stage and building them into a world.
#include "platon/stage/level.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "face_geometry.h"
#include "platon/files/read_file.h"
#include "walls_near.h"

namespace platon::stage {
namespace {

std::string pointText(physics::Vec2 p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

std::vector<physics::Vec2> goalSquare(const Level& level) {
  const int32_t h = goalHalfSide(level);
  const physics::Vec2 g = level.goal.position;
  return {{g.x - h, g.y - h}, {g.x + h, g.y - h}, {g.x + h, g.y + h}, {g.x - h, g.y + h}};
}

void checkPoint(const Level& level, const Stage& stage, const LevelPoint& p, const char* what) {
  const SourcePosition at{level.file, p.sourceLine, p.sourceColumn};
  if (p.face < 0 || p.face >= static_cast<int>(stage.faceCount()))
    throw StageError(at, std::string(what) + " face " + std::to_string(p.face) + " does not exist (the stage has " +
                             std::to_string(stage.faceCount()) + " faces)");
  const auto& corners = stage.faces[static_cast<size_t>(p.face)].corners;
  if (!insidePolygon(corners, p.position.x, p.position.y))
    throw StageError(at,
                     std::string(what) + " " + pointText(p.position) + " is outside face " + std::to_string(p.face));
  // The face's own lines, and its neighbours' across the edges the point is near, laid flat beside
  // it: the player's disk reaches over an edge onto the next face. A neighbour's lines are
  // measured from the point carried into that face's frame (one point moved, not every line), and
  // only when the point is within the clearance of the shared edge: a line across the edge line
  // is at least as far from the point as the edge is. A line whose bounding box is farther than
  // the clearance is passed over without a distance (the check is one pass over the level).
  auto tooClose = [&](const LevelLine& l, double x, double y) {
    if (!counts(l, *level.tags, Counting::Clearance)) return -1.0;
    const double lo = kStartClearance;
    if (x < std::min(l.a.x, l.b.x) - lo || x > std::max(l.a.x, l.b.x) + lo || y < std::min(l.a.y, l.b.y) - lo ||
        y > std::max(l.a.y, l.b.y) + lo)
      return -1.0;
    const double d = pointSegmentDistance(x, y, l.a.x, l.a.y, l.b.x, l.b.y);
    return d < kStartClearance ? d : -1.0;
  };
  auto refuse = [&](const LevelLine& l, double d, int face) {
    const std::string across = face == p.face ? "" : " (on face " + std::to_string(face) + ", across the edge)";
    throw StageError(at, std::string(what) + " " + pointText(p.position) +
                             " is inside a wall: " + std::to_string(static_cast<int>(d)) +
                             " units from the segment on line " + std::to_string(l.sourceLine) + across +
                             " (the player needs " + std::to_string(kStartClearance) + ")");
  };
  const size_t f = static_cast<size_t>(p.face);
  for (const LevelLine& l : level.faces[f].lines)
    if (const double d = tooClose(l, p.position.x, p.position.y); d >= 0) refuse(l, d, p.face);
  for (size_t k = 0; k < corners.size(); ++k) {
    if (distanceToSegment(p.position.x, p.position.y, corners[k], corners[(k + 1) % corners.size()]) >= kStartClearance)
      continue;
    const int g = stage.faces[f].neighbours[k].face;
    double x = p.position.x, y = p.position.y;
    unfoldAcross(stage, f, k).inverse().apply(x, y);
    for (const LevelLine& l : level.faces[static_cast<size_t>(g)].lines)
      if (const double d = tooClose(l, x, y); d >= 0) refuse(l, d, g);
  }
}

// Inside or on the border of a convex counter-clockwise polygon, for many points: the edges'
// directions worked out once (the same arithmetic as insidePolygon).
class InsideTest {
 public:
  explicit InsideTest(const std::vector<physics::Vec2>& corners) {
    for (size_t i = 0; i < corners.size(); ++i) {
      const physics::Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
      edges_.push_back({double(a.x), double(a.y), double(b.x) - a.x, double(b.y) - a.y});
    }
  }
  bool inside(physics::Vec2 p) const {
    for (const Edge& e : edges_)
      if (e.dx * (p.y - e.ay) - e.dy * (p.x - e.ax) < 0) return false;
    return true;
  }

 private:
  struct Edge {
    double ax, ay, dx, dy;
  };
  std::vector<Edge> edges_;
};

}  // namespace

bool operator==(const LevelLine& a, const LevelLine& b) {
  return a.a == b.a && a.b == b.b && a.oneWay == b.oneWay && a.tag == b.tag;
}
bool operator==(const LevelPoint& a, const LevelPoint& b) { return a.face == b.face && a.position == b.position; }
bool operator==(const LevelFace& a, const LevelFace& b) { return a.lines == b.lines && a.gravityQ16 == b.gravityQ16; }

bool operator==(const Level& a, const Level& b) {
  return a.solid == b.solid && a.mesh == b.mesh && a.start == b.start && a.startMillidegrees == b.startMillidegrees &&
         a.goal == b.goal && a.size == b.size && a.faces == b.faces;
}

int32_t goalHalfSide(const Level& level) { return std::min(kGoalHalfSide, level.size / 16); }

void checkLevelOnStage(const Level& level, const Stage& stage) {
  if (level.faces.size() != stage.faceCount())
    throw StageError({level.file, level.endLine, 1}, "the stage has " + std::to_string(stage.faceCount()) +
                                                         " faces; the file describes " +
                                                         std::to_string(level.faces.size()));
  for (size_t f = 0; f < level.faces.size(); ++f) {
    const auto& corners = stage.faces[f].corners;
    const InsideTest face(corners);
    for (const LevelLine& l : level.faces[f].lines)
      for (const physics::Vec2 p : {l.a, l.b})
        if (!face.inside(p)) {
          std::string shape;
          for (const physics::Vec2 c : corners) shape += " " + pointText(c);
          throw StageError({level.file, l.sourceLine, p == l.a ? l.sourceColumn : l.endColumn},
                           "the segment leaves face " + std::to_string(f) + ": " + pointText(p) +
                               " is outside it (its corners:" + shape + ")");
        }
  }
  checkPoint(level, stage, level.start, "start");
  checkPoint(level, stage, level.goal, "goal");
  for (const physics::Vec2 c : goalSquare(level))
    if (!insidePolygon(stage.faces[static_cast<size_t>(level.goal.face)].corners, c.x, c.y))
      throw StageError({level.file, level.goal.sourceLine, level.goal.sourceColumn},
                       "the goal's square (" + std::to_string(2 * goalHalfSide(level)) +
                           " units wide) reaches over the edge of face " + std::to_string(level.goal.face));
}

Stage platonicStageOf(const Level& level) {
  if (!level.solid) throw StageError({level.file, 1, 1}, "a mesh level needs its mesh loaded (the meshes system)");
  return platonicStage(*level.solid, level.size);
}

void buildLevel(const Level& level, Stage& stage, physics::World& world, physics::MapPartId firstPart,
                int64_t defaultGravityQ16) {
  addStageToWorld(stage, world, firstPart);
  for (size_t f = 0; f < level.faces.size(); ++f) {
    physics::MapPart& part = world.mapPart(stage.part(f));
    const LevelFace& face = level.faces[f];
    part.setGravity(face.gravityQ16.value_or(physics::Vec2w{0, -defaultGravityQ16}));
    part.reserve(part.lines().size() + face.lines.size() + 4);
    // Runs of solid lines with one tag go in bulk (the physics checks them once, together).
    std::vector<physics::Segment> run;
    for (size_t i = 0; i < face.lines.size();) {
      const LevelLine& l = face.lines[i];
      if (l.oneWay) {
        part.oneWay(l.a, l.b, l.tag);
        ++i;
        continue;
      }
      run.clear();
      size_t j = i;
      for (; j < face.lines.size() && !face.lines[j].oneWay && face.lines[j].tag == l.tag; ++j)
        run.push_back({face.lines[j].a, face.lines[j].b});
      part.lines(run, l.tag);
      i = j;
    }
  }
  const std::vector<physics::Vec2> square = goalSquare(level);
  physics::MapPart& goalPart = world.mapPart(stage.part(static_cast<size_t>(level.goal.face)));
  for (size_t i = 0; i < square.size(); ++i)
    goalPart.line(square[i], square[(i + 1) % square.size()], level.tags->number("goal"));
}

std::string readLevelFile(const std::string& path) {
  try {
    return files::readBoundedFile(path, kMaxLevelFileBytes);
  } catch (const files::FileError& e) {
    throw StageError({path, 0, 0}, "the level file: " + e.reason());
  }
}

}  // namespace platon::stage
