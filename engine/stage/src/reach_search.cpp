#include "reach_search.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "face_geometry.h"
#include "walls_near.h"

namespace platon::stage {
namespace {

// Walls this far from a shared edge are laid out on the neighbour's side: beyond the player's
// radius plus the start's and goal's free disks (kSeedReach), no disk centred on the face reaches them.
constexpr double kSeedReach = 64;
constexpr double kEdgeMargin = kPlayerRadius + 2 * kSeedReach + 16;

struct TooManyCells {};

// Which cells are free, joined across cell sides, faces' edges, start and goal.
class Joins {
 public:
  int add() {
    parent_.push_back(static_cast<int>(parent_.size()));
    return parent_.back();
  }
  int root(int a) {
    while (parent_[size_t(a)] != a) a = parent_[size_t(a)] = parent_[size_t(parent_[size_t(a)])];
    return a;
  }
  void join(int a, int b) { parent_[size_t(root(a))] = root(b); }

 private:
  std::vector<int> parent_;
};

// One face's quadtree: a node is split while some wall comes within the player's radius of its
// square and does not cover it whole, down to the finest cell; leaves are free or not.
class FaceTree {
 public:
  struct Node {
    Box box;
    int child = -1;  // the first of four: low x low y, high x low y, low x high y, high x high y
    int free = -1;   // a free leaf's join index
  };

  FaceTree(const std::vector<physics::Vec2>& corners, std::vector<FlatWall> walls, double finest, Joins& joins, size_t& budget)
      : corners_(corners), walls_(std::move(walls)), finest_(finest), joins_(joins), budget_(budget) {
    Box square{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const auto c : corners) square = {std::min(square.x0, double(c.x)), std::min(square.y0, double(c.y)),
                                           std::max(square.x1, double(c.x)), std::max(square.y1, double(c.y))};
    const double side = std::max(square.x1 - square.x0, square.y1 - square.y0);
    nodes_.push_back({{square.x0, square.y0, square.x0 + side, square.y0 + side}});
    std::vector<int> all(walls_.size());
    std::iota(all.begin(), all.end(), 0);
    build(0, all);
    linkInside(0);
  }

  const std::vector<Node>& nodes() const { return nodes_; }

  // The free leaves whose squares come within `reach` of the convex polygon `shape` (in this
  // face's frame), with each one's join index.
  void leavesNear(const std::vector<std::pair<double, double>>& shape, double reach, std::vector<int>& out) const {
    near(0, shape, reach, out);
  }

  // The free leaves along the segment a -> b, with the stretch of it (0 to 1) each covers.
  struct Stretch {
    double from, to;
    int free;
  };
  void leavesAlong(physics::Vec2 a, physics::Vec2 b, std::vector<Stretch>& out) const { along(0, a, b, out); }

 private:
  bool meetsFace(const Box& b) const {
    const double xs[4] = {b.x0, b.x1, b.x1, b.x0}, ys[4] = {b.y0, b.y0, b.y1, b.y1};
    for (size_t i = 0; i < corners_.size(); ++i) {
      const physics::Vec2 a = corners_[i], c = corners_[(i + 1) % corners_.size()];
      bool allOutside = true;
      for (int k = 0; k < 4 && allOutside; ++k) allOutside = side(a, c, xs[k], ys[k]) < 0;
      if (allOutside) return false;
    }
    Box hull{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const auto c : corners_) hull = {std::min(hull.x0, double(c.x)), std::min(hull.y0, double(c.y)), std::max(hull.x1, double(c.x)), std::max(hull.y1, double(c.y))};
    return hull.distanceTo(b) <= 0;
  }

  void build(int node, const std::vector<int>& candidates) {
    if (++budget_ > kMostCells) throw TooManyCells{};
    const Box box = nodes_[size_t(node)].box;
    std::vector<int> near;
    for (const int w : candidates) {
      const FlatWall& l = walls_[size_t(w)];
      constexpr double reach2 = kPlayerRadius * kPlayerRadius;
      if (segmentBoxDistance2(l.ax, l.ay, l.bx, l.by, box) >= reach2) continue;
      // A wall within reach of all four corners covers the square (the disk-swept wall is convex).
      bool covers = true;
      const double xs[4] = {box.x0, box.x1, box.x1, box.x0}, ys[4] = {box.y0, box.y0, box.y1, box.y1};
      for (int k = 0; k < 4 && covers; ++k) covers = pointSegmentDistance2(xs[k], ys[k], l.ax, l.ay, l.bx, l.by) < reach2;
      if (covers) return;  // a blocked leaf
      near.push_back(w);
    }
    if (near.empty()) {
      nodes_[size_t(node)].free = joins_.add();
      return;
    }
    if (box.x1 - box.x0 <= finest_) return;  // a wall within reach of part of it: blocked, to be safe
    const double mx = (box.x0 + box.x1) / 2, my = (box.y0 + box.y1) / 2;
    const int first = static_cast<int>(nodes_.size());
    nodes_[size_t(node)].child = first;
    const Box quarters[4] = {{box.x0, box.y0, mx, my}, {mx, box.y0, box.x1, my}, {box.x0, my, mx, box.y1}, {mx, my, box.x1, box.y1}};
    for (const Box& q : quarters) nodes_.push_back({q});
    for (int c = 0; c < 4; ++c)
      if (meetsFace(quarters[c])) build(first + c, near);
  }

  // Joins free leaves that share a stretch of a side: across the inner sides of every split node.
  void linkInside(int node) {
    const int c = nodes_[size_t(node)].child;
    if (c < 0) return;
    for (int k = 0; k < 4; ++k) linkInside(c + k);
    linkAcross(c, c + 1, true), linkAcross(c + 2, c + 3, true);
    linkAcross(c, c + 2, false), linkAcross(c + 1, c + 3, false);
  }
  // `a` left of `b` (sideways) or below it; descends to the leaves along their shared side.
  void linkAcross(int a, int b, bool sideways) {
    const Node &na = nodes_[size_t(a)], &nb = nodes_[size_t(b)];
    if (na.child < 0 && nb.child < 0) {
      if (na.free >= 0 && nb.free >= 0) joins_.join(na.free, nb.free);
      return;
    }
    // The children along the shared side: a's right (or top) pair, b's left (or bottom) pair.
    const int a1 = na.child < 0 ? a : na.child + (sideways ? 1 : 2), a2 = na.child < 0 ? a : na.child + 3;
    const int b1 = nb.child < 0 ? b : nb.child, b2 = nb.child < 0 ? b : nb.child + (sideways ? 2 : 1);
    linkAcross(a1, b1, sideways);
    linkAcross(a2, b2, sideways);
  }

  void near(int node, const std::vector<std::pair<double, double>>& shape, double reach, std::vector<int>& out) const {
    const Node& n = nodes_[size_t(node)];
    bool inside = shape.size() >= 3;  // the box's corner inside the (counter-clockwise) shape
    for (size_t i = 0; i < shape.size() && inside; ++i) {
      const auto [ax, ay] = shape[i];
      const auto [bx, by] = shape[(i + 1) % shape.size()];
      inside = (bx - ax) * (n.box.y0 - ay) - (by - ay) * (n.box.x0 - ax) >= 0;
    }
    double d = inside ? 0 : INFINITY;
    for (size_t i = 0; i < shape.size(); ++i) {
      const auto [ax, ay] = shape[i];
      const auto [bx, by] = shape[(i + 1) % shape.size()];
      d = std::min(d, segmentBoxDistance(ax, ay, bx, by, n.box));
    }
    if (d > reach) return;
    if (n.child >= 0) {
      for (int k = 0; k < 4; ++k) near(n.child + k, shape, reach, out);
    } else if (n.free >= 0) {
      out.push_back(n.free);
    }
  }

  void along(int node, physics::Vec2 a, physics::Vec2 b, std::vector<Stretch>& out) const {
    const Node& n = nodes_[size_t(node)];
    // Liang-Barsky: the part of a -> b inside the box.
    const double dx = double(b.x) - a.x, dy = double(b.y) - a.y;
    double t0 = 0, t1 = 1;
    const double p[4] = {-dx, dx, -dy, dy}, q[4] = {a.x - n.box.x0, n.box.x1 - a.x, a.y - n.box.y0, n.box.y1 - a.y};
    for (int i = 0; i < 4; ++i) {
      if (p[i] == 0) {
        if (q[i] < 0) return;
        continue;
      }
      const double t = q[i] / p[i];
      if (p[i] < 0) t0 = std::max(t0, t);
      else t1 = std::min(t1, t);
    }
    if (t0 > t1) return;
    if (n.child >= 0) {
      for (int k = 0; k < 4; ++k) along(n.child + k, a, b, out);
    } else if (n.free >= 0) {
      out.push_back({t0, t1, n.free});
    }
  }

  const std::vector<physics::Vec2>& corners_;
  std::vector<FlatWall> walls_;
  double finest_;
  Joins& joins_;
  size_t& budget_;
  std::vector<Node> nodes_;
};

using Shape = std::vector<std::pair<double, double>>;

Shape mapped(const Shape& shape, const FlatMap& map) {
  Shape out = shape;
  for (auto& [x, y] : out) map.apply(x, y);
  return out;
}

// The free leaves round a point: within its free disk (its distance to the nearest wall less the
// player's radius, at most kSeedReach), on its face and across the edges that disk reaches.
std::vector<int> leavesRound(const Stage& stage, const std::vector<FaceTree>& trees, const std::vector<std::vector<FlatWall>>& walls,
                             const LevelPoint& p) {
  const auto f = static_cast<size_t>(p.face);
  double clear = INFINITY;
  for (const FlatWall& w : walls[f]) clear = std::min(clear, pointSegmentDistance(p.position.x, p.position.y, w.ax, w.ay, w.bx, w.by));
  const double reach = std::min(kSeedReach, clear - kPlayerRadius);
  std::vector<int> out;
  if (reach < 0) return out;
  const Shape point{{double(p.position.x), double(p.position.y)}};
  trees[f].leavesNear(point, reach, out);
  const StageFace& face = stage.faces[f];
  for (size_t k = 0; k < face.corners.size(); ++k) {
    if (distanceToSegment(p.position.x, p.position.y, face.corners[k], face.corners[(k + 1) % face.corners.size()]) > reach) continue;
    trees[size_t(face.neighbours[k].face)].leavesNear(mapped(point, unfoldAcross(stage, f, k).inverse()), reach, out);
  }
  return out;
}

// The free leaves from which the player's disk meets the goal's square: on its face, and on the
// faces across the edges the square comes within the radius of.
std::vector<int> leavesMeetingGoal(const Level& level, const Stage& stage, const std::vector<FaceTree>& trees) {
  const auto f = static_cast<size_t>(level.goal.face);
  const double h = goalHalfSide(level), gx = level.goal.position.x, gy = level.goal.position.y;
  const Shape square{{gx - h, gy - h}, {gx + h, gy - h}, {gx + h, gy + h}, {gx - h, gy + h}};
  std::vector<int> out;
  trees[f].leavesNear(square, kPlayerRadius, out);
  const StageFace& face = stage.faces[f];
  for (size_t k = 0; k < face.corners.size(); ++k) {
    double d = INFINITY;
    for (const auto& [x, y] : square)
      d = std::min(d, distanceToSegment(x, y, face.corners[k], face.corners[(k + 1) % face.corners.size()]));
    if (d > kPlayerRadius) continue;
    trees[size_t(face.neighbours[k].face)].leavesNear(mapped(square, unfoldAcross(stage, f, k).inverse()), kPlayerRadius, out);
  }
  return out;
}

// Joins the free leaves on either side of every edge whose stretches of it overlap.
void linkEdges(const Stage& stage, const std::vector<FaceTree>& trees, Joins& joins) {
  for (size_t f = 0; f < stage.faceCount(); ++f) {
    const StageFace& face = stage.faces[f];
    for (size_t k = 0; k < face.corners.size(); ++k) {
      const auto [g, j] = face.neighbours[k];
      if (size_t(g) < f) continue;  // each edge once
      std::vector<FaceTree::Stretch> here, there;
      trees[f].leavesAlong(face.corners[k], face.corners[(k + 1) % face.corners.size()], here);
      const StageFace& other = stage.faces[size_t(g)];
      trees[size_t(g)].leavesAlong(other.corners[size_t(j)], other.corners[(size_t(j) + 1) % other.corners.size()], there);
      for (auto& s : there) s = {1 - s.to, 1 - s.from, s.free};  // the other face runs the edge the other way
      auto byStart = [](const FaceTree::Stretch& a, const FaceTree::Stretch& b) { return a.from < b.from; };
      std::sort(here.begin(), here.end(), byStart);
      std::sort(there.begin(), there.end(), byStart);
      for (size_t a = 0, b = 0; a < here.size() && b < there.size();) {
        if (std::max(here[a].from, there[b].from) <= std::min(here[a].to, there[b].to)) joins.join(here[a].free, there[b].free);
        here[a].to < there[b].to ? ++a : ++b;
      }
    }
  }
}

bool search(const Level& level, const Stage& stage, double finest) {
  Joins joins;
  size_t budget = 0;
  std::vector<std::vector<FlatWall>> walls;
  std::vector<FaceTree> trees;
  trees.reserve(stage.faceCount());
  for (size_t f = 0; f < stage.faceCount(); ++f) {
    walls.push_back(wallsNear(level, stage, f, kEdgeMargin, Counting::Reach));
    trees.emplace_back(stage.faces[f].corners, walls.back(), finest, joins, budget);
  }
  linkEdges(stage, trees, joins);
  const auto& goal = level.goal.position;
  const auto& start = level.start.position;
  if (level.start.face == level.goal.face) {  // the disk at the start already meets the square
    const double h = goalHalfSide(level);
    const Box square{double(goal.x) - h, double(goal.y) - h, double(goal.x) + h, double(goal.y) + h};
    if (square.distanceTo(start.x, start.y) <= kPlayerRadius) return true;
  }
  std::vector<int> from = leavesRound(stage, trees, walls, level.start);
  std::vector<int> roots;
  for (const int l : from) roots.push_back(joins.root(l));
  std::sort(roots.begin(), roots.end());
  for (const int l : leavesMeetingGoal(level, stage, trees))
    if (std::binary_search(roots.begin(), roots.end(), joins.root(l))) return true;
  return false;
}

}  // namespace

ReachAnswer searchReach(const Level& level, const Stage& stage) {
  // About eight cells go to every finest cell's length of wall (both sides of it, and the nodes
  // above them): start at a cell size that fits the budget, so that most levels search once.
  double length = 0;
  for (const LevelFace& face : level.faces)
    for (const LevelLine& l : face.lines)
      if (counts(l, Counting::Reach)) length += std::hypot(double(l.b.x) - l.a.x, double(l.b.y) - l.a.y);
  double start = kFinestCell;
  while (8 * length / start > 0.5 * double(kMostCells)) start *= 2;
  for (double finest = start;; finest *= 2) {
    try {
      return {search(level, stage, finest), finest};
    } catch (const TooManyCells&) {
    }
  }
}

}  // namespace platon::stage
