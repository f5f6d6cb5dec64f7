#include "platon/stage/level_check.h"

#include "face_geometry.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace platon::stage {
namespace {

struct Grid {
  double cell = 0;
  int32_t x0 = 0, y0 = 0;
  int width = 0, height = 0;
  std::vector<uint8_t> state;  // 0 outside the face, 1 free, 2 blocked

  int index(double x, double y) const {
    const int i = static_cast<int>(std::floor((x - x0) / cell)), j = static_cast<int>(std::floor((y - y0) / cell));
    if (i < 0 || j < 0 || i >= width || j >= height) return -1;
    return j * width + i;
  }
  double cx(int i) const { return x0 + (i % width + 0.5) * cell; }
  double cy(int i) const { return y0 + (i / width + 0.5) * cell; }
};

bool blocks(const LevelLine& l) {
  return !l.oneWay && !playerPassesThrough(l.tag) && !(l.tag > kTagDoor && l.tag < kTagDoor + 1000);  // doors: open
}

std::vector<Grid> buildGrids(const Level& level, const Stage& stage) {
  const double cell = std::max(8.0, level.size / 64.0);
  const double reach = kStartClearance - cell / 2;  // optimistic: a cell is free if its centre may be
  std::vector<Grid> grids;
  for (size_t f = 0; f < stage.faceCount(); ++f) {
    const auto& corners = stage.faces[f].corners;
    Grid g;
    g.cell = cell;
    int32_t x1 = INT32_MIN, y1 = INT32_MIN;
    g.x0 = g.y0 = INT32_MAX;
    for (const auto c : corners) g.x0 = std::min(g.x0, c.x), g.y0 = std::min(g.y0, c.y), x1 = std::max(x1, c.x), y1 = std::max(y1, c.y);
    g.width = static_cast<int>(std::ceil((x1 - g.x0) / cell));
    g.height = static_cast<int>(std::ceil((y1 - g.y0) / cell));
    g.state.assign(static_cast<size_t>(g.width) * static_cast<size_t>(g.height), 0);
    for (int i = 0; i < g.width * g.height; ++i) g.state[static_cast<size_t>(i)] = insidePolygon(corners, g.cx(i), g.cy(i)) ? 1 : 0;
    for (const LevelLine& l : level.faces[f].lines) {
      if (!blocks(l)) continue;
      const double lx = std::min(l.a.x, l.b.x) - reach, hx = std::max(l.a.x, l.b.x) + reach;
      const double ly = std::min(l.a.y, l.b.y) - reach, hy = std::max(l.a.y, l.b.y) + reach;
      for (double y = std::max<double>(g.y0, ly); y <= hy + cell; y += cell)
        for (double x = std::max<double>(g.x0, lx); x <= hx + cell; x += cell) {
          const int i = g.index(x, y);
          if (i < 0 || g.state[static_cast<size_t>(i)] != 1) continue;
          if (distanceToSegment(g.cx(i), g.cy(i), l.a, l.b) < reach) g.state[static_cast<size_t>(i)] = 2;
        }
    }
    grids.push_back(std::move(g));
  }
  return grids;
}

}  // namespace

bool goalReachable(const Level& level, const Stage& stage) {
  const std::vector<Grid> grids = buildGrids(level, stage);
  std::vector<std::vector<bool>> seen(grids.size());
  for (size_t f = 0; f < grids.size(); ++f) seen[f].assign(grids[f].state.size(), false);
  std::deque<std::pair<size_t, int>> queue;
  auto visit = [&](size_t f, int i) {
    if (i < 0 || grids[f].state[static_cast<size_t>(i)] != 1 || seen[f][static_cast<size_t>(i)]) return;
    seen[f][static_cast<size_t>(i)] = true;
    queue.push_back({f, i});
  };
  const auto startFace = static_cast<size_t>(level.start.face);
  const Grid& sg = grids[startFace];
  const int start = sg.index(level.start.position.x, level.start.position.y);
  if (start >= 0) {  // the start's cell, even if the coarse grid marks it blocked
    seen[startFace][static_cast<size_t>(start)] = true;
    queue.push_back({startFace, start});
  }
  while (!queue.empty()) {
    const auto [f, i] = queue.front();
    queue.pop_front();
    const Grid& g = grids[f];
    const int x = i % g.width, y = i / g.width;
    if (x > 0) visit(f, i - 1);
    if (x + 1 < g.width) visit(f, i + 1);
    if (y > 0) visit(f, i - g.width);
    if (y + 1 < g.height) visit(f, i + g.width);
    // Across an edge: a cell within one cell of edge k reaches the neighbour's cell just inside
    // the same place on its copy of the edge.
    const StageFace& face = stage.faces[f];
    const size_t n = face.corners.size();
    for (size_t k = 0; k < n; ++k) {
      const physics::Vec2 a = face.corners[k], b = face.corners[(k + 1) % n];
      const double len = std::hypot(double(b.x) - a.x, double(b.y) - a.y);
      if (side(a, b, g.cx(i), g.cy(i)) / len > g.cell * 1.5) continue;
      const double t = std::clamp(((g.cx(i) - a.x) * (b.x - a.x) + (g.cy(i) - a.y) * (b.y - a.y)) / (len * len), 0.0, 1.0);
      const auto [nf, j] = face.neighbours[k];
      const StageFace& other = stage.faces[static_cast<size_t>(nf)];
      const size_t m = other.corners.size();
      const physics::Vec2 p = other.corners[(static_cast<size_t>(j) + 1) % m], q = other.corners[static_cast<size_t>(j)];
      // The neighbour's edge j runs q -> p (our b -> a): our point at t from a is at t from p
      // toward q, and the neighbour's inside is left of q -> p.
      const double ex = double(q.x) - p.x, ey = double(q.y) - p.y, el = std::hypot(ex, ey);
      const double px = p.x + t * ex, py = p.y + t * ey;
      const double inx = -(double(p.y) - q.y) / el, iny = (double(p.x) - q.x) / el;
      const size_t target = static_cast<size_t>(nf);
      visit(target, grids[target].index(px + inx * g.cell * 0.75, py + iny * g.cell * 0.75));
    }
  }
  const Grid& gg = grids[static_cast<size_t>(level.goal.face)];
  const int h = goalHalfSide(level);
  // The goal is reached when the player's disk meets its square: any seen cell near it.
  for (int i = 0; i < gg.width * gg.height; ++i) {
    if (!seen[static_cast<size_t>(level.goal.face)][static_cast<size_t>(i)]) continue;
    const double dx = std::max(0.0, std::abs(gg.cx(i) - level.goal.position.x) - h);
    const double dy = std::max(0.0, std::abs(gg.cy(i) - level.goal.position.y) - h);
    if (std::hypot(dx, dy) <= kStartClearance) return true;
  }
  return false;
}

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
        if (!blocks(l)) continue;
        report.warnings.push_back({{level.file, l.sourceLine, l.sourceColumn},
                                   "the segment lies along edge " + std::to_string(k) + " of face " + std::to_string(f) +
                                       ": it blocks the way to face " + std::to_string(stage.faces[f].neighbours[k].face)});
      }
  }
  if (emptyCount)
    report.warnings.push_back(Finding{SourcePosition{level.file, firstEmptyLine, 1},
                                      (emptyCount == 1 ? "face " + empty + " has" : "faces " + empty + " have") + " no lines"});
  if (!goalReachable(level, stage))
    report.errors.push_back({{level.file, level.goal.sourceLine, level.goal.sourceColumn},
                             "no path reaches the goal from the start (walls seal it off; see docs/level-format.md, "
                             "\"platon check\")"});
  return report;
}

}  // namespace platon::stage
