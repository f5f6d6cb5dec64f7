#include "reach_search.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <tuple>

#include "face_geometry.h"
#include "walls_near.h"

namespace platon::stage {
namespace {

constexpr double kReach2 = kPlayerRadius * kPlayerRadius;
constexpr size_t kRefineBytes =
    4u << 20;  // for each tree, round the start and round the goal, once the search stopped coarse

// How far from the start (or the goal) the search looks for free cells to slide to in a straight
// line: past the cells next to the walls round it, which are in doubt and so blocked (two cell
// diagonals), at least 64 and at most kSeedReachMost units. Walls that far plus the player's radius
// from a shared edge are laid out on the neighbour's side too (twice, with room to spare).
constexpr double kSeedReachLeast = 64, kSeedReachMost = 256;
constexpr double kEdgeMargin = kPlayerRadius + 2 * kSeedReachMost + 16;
double seedReach(double finest) {
  return std::clamp(2 * std::sqrt(2.0) * finest + 16, kSeedReachLeast, kSeedReachMost);
}

// Which leaves are joined (across cell sides, faces' edges, start and goal): union-find over the
// leaves' join indices, which the trees hand out as they grow.
class Joins {
 public:
  explicit Joins(int count) : parent_(size_t(count)) { std::iota(parent_.begin(), parent_.end(), 0); }
  int root(int a) {
    while (parent_[size_t(a)] != a) a = parent_[size_t(a)] = parent_[size_t(parent_[size_t(a)])];
    return a;
  }
  void join(int a, int b) { parent_[size_t(root(a))] = root(b); }

 private:
  std::vector<int> parent_;
};

// Which leaves a pass over the trees counts as open: the free ones (the search's answer), or the
// free ones and those left undecided where the search stopped coarse (an upper bound: if even
// then no path reaches the goal, none would with the finest cells either).
enum class Open { Free, FreeOrUndecided };

// A wall with whole-unit ends as a stretch of its line.
struct WallStretch {
  int64_t offset, from, to;  // the line's offset; the wall's stretch of it
  int32_t dx, dy;            // the line's reduced direction
  uint32_t wall;
};

// Wall i on its line; none for a wall whose ends are not whole units, or that is a point (levels
// refuse them; one made in code may have it).
std::optional<WallStretch> onLineOf(const FlatWall& w, uint32_t i) {
  auto whole = [](double v) { return v == std::floor(v) && std::abs(v) < (1 << 30); };
  if (!(whole(w.ax) && whole(w.ay) && whole(w.bx) && whole(w.by))) return std::nullopt;
  const int64_t ax = int64_t(w.ax), ay = int64_t(w.ay), bx = int64_t(w.bx), by = int64_t(w.by);
  int64_t dx = bx - ax, dy = by - ay;
  if (dx == 0 && dy == 0) return std::nullopt;
  const int64_t g = std::gcd(dx, dy);
  dx /= g, dy /= g;
  if (dx < 0 || (dx == 0 && dy < 0)) dx = -dx, dy = -dy;
  const int64_t ta = dx * ax + dy * ay, tb = dx * bx + dy * by;
  return WallStretch{dx * ay - dy * ax, std::min(ta, tb), std::max(ta, tb), int32_t(dx), int32_t(dy), i};
}

// The walls' order by line, then along it: first by a hash of the line (a radix sort, linear: a
// level of 10^6 walls must not wait for a comparison sort), then each run of one hash by line and
// stretch. Each entry is (hash, index into `lines`).
std::vector<std::pair<uint32_t, uint32_t>> wallsByLine(const std::vector<WallStretch>& lines) {
  auto lineHash = [](const WallStretch& l) {
    const uint64_t h = uint64_t(int64_t(l.dx)) * 0x9e3779b97f4a7c15ULL ^
                       uint64_t(int64_t(l.dy)) * 0xbf58476d1ce4e5b9ULL ^ uint64_t(l.offset) * 0x94d049bb133111ebULL;
    return uint32_t((h ^ (h >> 29)) >> 32);
  };
  std::vector<std::pair<uint32_t, uint32_t>> order(lines.size()), spare(lines.size());
  for (size_t i = 0; i < lines.size(); ++i) order[i] = {lineHash(lines[i]), uint32_t(i)};
  for (const int shift : {0, 16}) {
    std::vector<uint32_t> start(65537, 0);
    for (const auto& e : order) ++start[((e.first >> shift) & 0xffff) + 1];
    for (size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
    for (const auto& e : order) spare[start[(e.first >> shift) & 0xffff]++] = e;
    order.swap(spare);
  }
  for (size_t i = 0; i < order.size();) {
    size_t j = i + 1;
    while (j < order.size() && order[j].first == order[i].first) ++j;
    if (j - i > 1)
      std::sort(order.begin() + std::ptrdiff_t(i), order.begin() + std::ptrdiff_t(j),
                [&](const auto& a, const auto& b) {
                  const WallStretch &p = lines[a.second], &q = lines[b.second];
                  return std::tie(p.dx, p.dy, p.offset, p.from) < std::tie(q.dx, q.dy, q.offset, q.from);
                });
    i = j;
  }
  return order;
}

// Walls on one line that overlap or touch are one wall to the search (a level may draw a floor as
// thousands of short pieces, or the same piece many times): merged exactly, for the walls with
// whole-unit ends (the face's own; its neighbours' laid out are kept as they are).
std::vector<FlatWall> mergedWalls(std::vector<FlatWall> walls) {
  std::vector<WallStretch> lines;
  lines.reserve(walls.size());
  std::vector<FlatWall> out;
  for (size_t i = 0; i < walls.size(); ++i) {
    if (const std::optional<WallStretch> l = onLineOf(walls[i], uint32_t(i)))
      lines.push_back(*l);
    else
      out.push_back(walls[i]);
  }
  const std::vector<std::pair<uint32_t, uint32_t>> order = wallsByLine(lines);
  auto sameLine = [](const WallStretch& a, const WallStretch& b) {
    return a.dx == b.dx && a.dy == b.dy && a.offset == b.offset;
  };
  auto endAt = [&](const WallStretch& l, int64_t t, double& x, double& y) {  // the wall's end at stretch t
    const FlatWall& w = walls[l.wall];
    const bool a = int64_t(l.dx) * int64_t(w.ax) + int64_t(l.dy) * int64_t(w.ay) == t;
    x = a ? w.ax : w.bx, y = a ? w.ay : w.by;
  };
  for (size_t i = 0; i < order.size();) {
    const WallStretch& first = lines[order[i].second];
    const WallStretch* last = &first;  // the wall reaching farthest along the line so far
    size_t j = i + 1;
    for (; j < order.size() && sameLine(lines[order[j].second], first) && lines[order[j].second].from <= last->to; ++j)
      if (lines[order[j].second].to > last->to) last = &lines[order[j].second];
    FlatWall w = walls[first.wall];
    endAt(first, first.from, w.ax, w.ay);
    endAt(*last, last->to, w.bx, w.by);
    out.push_back(w);
    i = j;
  }
  return out;
}

// The stretch of the line (x0, y0) + t ((x1, y1) - (x0, y0)) within the player's radius of wall
// `w` (the open interval lo < t < hi; empty when lo >= hi): the wall's disk-swept shape is convex,
// the union of a disk round each end and the rectangle between, so the stretch is one interval,
// the hull of the three.
std::pair<double, double> withinReach(double x0, double y0, double x1, double y1, const FlatWall& w) {
  const double dx = x1 - x0, dy = y1 - y0, r = kPlayerRadius;
  double lo = INFINITY, hi = -INFINITY;
  auto add = [&](double a, double b) {
    if (a < b) lo = std::min(lo, a), hi = std::max(hi, b);
  };
  for (const auto& [cx, cy] : {std::pair{w.ax, w.ay}, std::pair{w.bx, w.by}}) {  // |p0 - c + t d|^2 < r^2
    const double a = dx * dx + dy * dy, b = 2 * (dx * (x0 - cx) + dy * (y0 - cy));
    const double c = (x0 - cx) * (x0 - cx) + (y0 - cy) * (y0 - cy) - r * r;
    if (a == 0) {
      if (c < 0) add(-INFINITY, INFINITY);
      continue;
    }
    const double disc = b * b - 4 * a * c;
    if (disc > 0) add((-b - std::sqrt(disc)) / (2 * a), (-b + std::sqrt(disc)) / (2 * a));
  }
  const double length = std::hypot(w.bx - w.ax, w.by - w.ay);
  if (length > 0) {  // along the wall 0 < u < length, across it -r < v < r
    const double ex = (w.bx - w.ax) / length, ey = (w.by - w.ay) / length;
    double a = -INFINITY, b = INFINITY;
    auto clip = [&](double f0, double df, double fLo, double fHi) {
      if (df == 0) {
        if (!(f0 > fLo && f0 < fHi)) a = INFINITY;
        return;
      }
      const double t0 = (fLo - f0) / df, t1 = (fHi - f0) / df;
      a = std::max(a, std::min(t0, t1)), b = std::min(b, std::max(t0, t1));
    };
    clip((x0 - w.ax) * ex + (y0 - w.ay) * ey, dx * ex + dy * ey, 0, length);
    clip((y0 - w.ay) * ex - (x0 - w.ax) * ey, dy * ex - dx * ey, -r, r);
    add(a, b);
  }
  return {lo, hi};
}

// One face's quadtree: a cell is split while some wall comes within the player's radius of its
// square and does not cover it whole, down to the finest cell; leaves are free, blocked, or (where
// the search stopped coarse) undecided. Nodes are lean (a square's place follows from the path to
// it), and the tree grows one level at a time (growTrees), so that what each level costs is known
// before it is grown.
class FaceTree {
 public:
  struct Node {
    int32_t child = -1;  // the first of four: low x low y, high x low y, low x high y, high x high y
    int32_t join = -1;   // a free leaf's join index; -1 blocked; -2 - i for an undecided leaf, doubts_[i]
  };
  struct Stretch {  // of an edge (0 to 1), covered by an open leaf
    double from, to;
    int join;
    int doubt;  // an undecided leaf's index in doubts_, or -1
  };
  struct Leaf {
    int join;
    Box box;
    bool ring;  // an undecided leaf the search's answer passes through round its rim (ringOpen)
  };

  FaceTree(const std::vector<physics::Vec2>& corners, std::vector<FlatWall> walls)
      : corners_(corners), walls_(std::move(walls)) {
    hull_ = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const auto c : corners)
      hull_ = {std::min(hull_.x0, double(c.x)), std::min(hull_.y0, double(c.y)), std::max(hull_.x1, double(c.x)),
               std::max(hull_.y1, double(c.y))};
    const double side = std::max(hull_.x1 - hull_.x0, hull_.y1 - hull_.y0);
    square_ = {hull_.x0, hull_.y0, hull_.x0 + side, hull_.y0 + side};
  }

  const std::vector<FlatWall>& walls() const { return walls_; }
  // What the tree holds: its nodes (and a join index each in both passes' union-finds), its cells
  // in doubt and their walls.
  size_t bytes() const {
    return nodes_.capacity() * kNodeBytes + doubts_.capacity() * (sizeof(Doubt) + sizeof(int)) +
           near_.capacity() * sizeof(int32_t);
  }
  // The side of the cells in doubt, waiting to be split (0: none), and what splitting them adds.
  double cellInDoubt() const { return doubts_.empty() ? 0 : cell_; }
  size_t splitBytes() const { return 4 * doubts_.size() * kNodeBytes; }

  // The root against every wall; `joins` counts the join indices handed out.
  void plant(int& joins) {
    nodes_.assign(1, Node{});
    cell_ = square_.x1 - square_.x0;
    std::vector<int32_t> all(walls_.size());
    std::iota(all.begin(), all.end(), 0);
    settle(0, 0, 0, 0, square_, all.data(), all.data() + all.size(), joins);
  }

  // Splits every cell in doubt and settles its four quarters against its walls: free, blocked, or
  // in doubt at half the size. Stops early when this tree and `others` (bytes held elsewhere)
  // would pass `limit` (the cells not split stay in doubt, for stop()); returns whether it finished.
  bool grow(int& joins, size_t others, size_t limit) {
    const std::vector<Doubt> parents = std::move(doubts_);
    std::vector<int32_t> walls = std::move(near_);
    doubts_.clear(), near_.clear();
    const size_t held = others + parents.capacity() * sizeof(Doubt) + walls.capacity() * sizeof(int32_t);
    cell_ /= 2;
    nodes_.reserve(nodes_.size() + 4 * parents.size());
    for (size_t i = 0; i < parents.size(); ++i) {
      const Doubt& d = parents[i];
      if (held + bytes() > limit) {
        for (size_t r = i; r < parents.size(); ++r) {  // the rest stay in doubt, with their walls, for stop()
          Doubt rest = parents[r];
          rest.from = uint32_t(near_.size());
          near_.insert(near_.end(), walls.begin() + std::ptrdiff_t(parents[r].from),
                       walls.begin() + std::ptrdiff_t(parents[r].to));
          rest.to = uint32_t(near_.size());
          doubts_.push_back(rest);
        }
        return false;
      }
      const int32_t first = static_cast<int32_t>(nodes_.size());
      nodes_[size_t(d.node)].child = first;
      nodes_.resize(nodes_.size() + 4);
      for (uint32_t k = 0; k < 4; ++k) {
        const uint32_t ix = 2 * d.ix + (k & 1), iy = 2 * d.iy + (k >> 1);
        const Box box{square_.x0 + ix * cell_, square_.y0 + iy * cell_, square_.x0 + (ix + 1) * cell_,
                      square_.y0 + (iy + 1) * cell_};
        if (meetsFace(box))
          settle(first + int32_t(k), d.depth + 1, ix, iy, box, walls.data() + d.from, walls.data() + d.to, joins);
      }
    }
    return true;
  }

  // The search stops here: the cells in doubt become undecided leaves (blocked to the search's
  // answer, open to its upper bound), keeping their walls.
  void stop(int& joins) {
    for (size_t i = 0; i < doubts_.size(); ++i) markUndecided(i, joins);
  }

  // Grows the undecided cells within `radius` of (x, y) down to the finest cells, while the tree
  // stays under `limit` bytes: round the start and the goal, where a few units of room decide.
  void refineNear(double x, double y, double radius, size_t limit, int& joins) {
    std::vector<size_t> todo;
    for (size_t i = 0; i < doubts_.size(); ++i) todo.push_back(i);
    while (!todo.empty() && bytes() <= limit) {
      const Doubt d = doubts_[todo.back()];
      todo.pop_back();
      const Box box = boxOf(d);
      if (nodes_[size_t(d.node)].child >= 0 || box.distanceTo(x, y) > radius) continue;
      const int32_t first = static_cast<int32_t>(nodes_.size());
      nodes_[size_t(d.node)].child = first;
      nodes_.resize(nodes_.size() + 4);
      const auto q = quarters(box);
      std::vector<int32_t> walls(near_.begin() + d.from, near_.begin() + d.to);  // settle() adds to near_
      for (uint32_t k = 0; k < 4; ++k) {
        if (!meetsFace(q[k])) continue;
        const size_t before = doubts_.size();
        settle(first + int32_t(k), d.depth + 1, 2 * d.ix + (k & 1), 2 * d.iy + (k >> 1), q[k], walls.data(),
               walls.data() + walls.size(), joins);
        if (doubts_.size() == before) continue;
        markUndecided(before, joins);
        todo.push_back(before);
      }
    }
  }

  // Whether some point of the segment (x0, y0) - (x1, y1), a stretch of the side of a leaf, is
  // clear of every wall by the player's radius: always for a free leaf (doubt < 0); for the
  // undecided leaf doubts_[doubt], by its walls (all those within reach of its square).
  bool openAlong(int doubt, double x0, double y0, double x1, double y1) const {
    if (doubt < 0) return true;
    const Doubt& d = doubts_[size_t(doubt)];
    std::vector<std::pair<double, double>> covered;  // stretches of the segment (0 to 1) within reach of a wall
    for (uint32_t i = d.from; i < d.to; ++i) {
      const FlatWall& w = walls_[size_t(near_[i])];
      if (const auto [lo, hi] = withinReach(x0, y0, x1, y1, w); lo < hi) covered.push_back({lo, hi});
    }
    std::sort(covered.begin(), covered.end());
    double reached = 0;  // [0, reached] is covered (strictly inside, except at 0 itself)
    bool started = false;
    for (const auto& [lo, hi] : covered) {
      if (started ? lo >= reached : lo >= 0) return true;  // a point between the stretches is clear
      started = true;
      reached = std::max(reached, hi);
      if (reached > 1) return false;
    }
    return true;
  }

  // Joins open leaves that share a stretch of a side: across the inner sides of every split node.
  void linkInside(Open open, Joins& joins) const { linkInside(0, square_, open, joins); }

  // The open leaves whose squares come within `reach` of the convex polygon `shape` (in this
  // face's frame; one point for a disk), with their squares.
  void leavesNear(const std::vector<std::pair<double, double>>& shape, double reach, Open open,
                  std::vector<Leaf>& out) const {
    near(0, square_, shape, reach, open, out);
  }

  // The open leaves along the segment a -> b, with the stretch of it (0 to 1) each covers.
  void leavesAlong(physics::Vec2 a, physics::Vec2 b, Open open, std::vector<Stretch>& out) const {
    along(0, square_, a, b, open, out);
  }

 private:
  struct Doubt {
    int32_t node;
    uint32_t depth, ix, iy;  // its size (the face's square halved `depth` times) and place in the grid of that size
    uint32_t from, to;       // its walls in near_
    bool ring = false;       // once undecided: open round its rim (ringOpen)
  };

  double cellOf(uint32_t depth) const { return std::ldexp(square_.x1 - square_.x0, -int(depth)); }

  Box boxOf(const Doubt& d) const {
    const double side = cellOf(d.depth);
    return {square_.x0 + d.ix * side, square_.y0 + d.iy * side, square_.x0 + (d.ix + 1) * side,
            square_.y0 + (d.iy + 1) * side};
  }

  void markUndecided(size_t doubt, int& joins) {
    Doubt& d = doubts_[doubt];
    nodes_[size_t(d.node)].join = -2 - int32_t(doubt);
    undecidedJoin_.resize(doubts_.size(), -1);
    undecidedJoin_[doubt] = joins++;
    d.ring = ringOpen(d);
  }

  // An undecided cell whose walls' disk-swept shapes all lie strictly inside it, the cell strictly
  // inside the face: its rim is clear, one piece, so the disk passes round it from any side to any
  // other (what lies inside, a pocket perhaps, is not known; a cell of short walls far apart,
  // where the search stopped coarse, is mostly this).
  bool ringOpen(const Doubt& d) const {
    const Box box = boxOf(d);
    for (const auto& c :
         {std::pair{box.x0, box.y0}, std::pair{box.x1, box.y0}, std::pair{box.x1, box.y1}, std::pair{box.x0, box.y1}})
      for (size_t i = 0; i < corners_.size(); ++i)
        if (side(corners_[i], corners_[(i + 1) % corners_.size()], c.first, c.second) <= 0) return false;
    for (uint32_t i = d.from; i < d.to; ++i) {
      const FlatWall& w = walls_[size_t(near_[i])];
      if (std::min(w.ax, w.bx) - kPlayerRadius <= box.x0 || std::max(w.ax, w.bx) + kPlayerRadius >= box.x1 ||
          std::min(w.ay, w.by) - kPlayerRadius <= box.y0 || std::max(w.ay, w.by) + kPlayerRadius >= box.y1)
        return false;
    }
    return true;
  }
  static constexpr size_t kNodeBytes = sizeof(Node) + 2 * sizeof(int);

  bool meetsFace(const Box& b) const {
    if (hull_.distanceTo(b) > 0) return false;
    const double xs[4] = {b.x0, b.x1, b.x1, b.x0}, ys[4] = {b.y0, b.y0, b.y1, b.y1};
    for (size_t i = 0; i < corners_.size(); ++i) {
      const physics::Vec2 a = corners_[i], c = corners_[(i + 1) % corners_.size()];
      bool allOutside = true;
      for (int k = 0; k < 4 && allOutside; ++k) allOutside = side(a, c, xs[k], ys[k]) < 0;
      if (allOutside) return false;
    }
    return true;
  }

  // A cell against the walls near its parent: blocked when one wall is within reach of all of it,
  // free when none is within reach of any of it, otherwise in doubt (blocked at the finest size).
  void settle(int32_t node, uint32_t depth, uint32_t ix, uint32_t iy, const Box& box, int32_t* from, int32_t* to,
              int& joins) {
    const size_t mark = near_.size();
    const double xs[4] = {box.x0, box.x1, box.x1, box.x0}, ys[4] = {box.y0, box.y0, box.y1, box.y1};
    for (int32_t* w = from; w != to; ++w) {
      const FlatWall& l = walls_[size_t(*w)];
      if (std::min(l.ax, l.bx) >= box.x1 + kPlayerRadius || std::max(l.ax, l.bx) <= box.x0 - kPlayerRadius ||
          std::min(l.ay, l.by) >= box.y1 + kPlayerRadius || std::max(l.ay, l.by) <= box.y0 - kPlayerRadius)
        continue;  // their bounding boxes are the radius apart
      if (std::min(l.ax, l.bx) - kPlayerRadius > box.x0 && std::max(l.ax, l.bx) + kPlayerRadius < box.x1 &&
          std::min(l.ay, l.by) - kPlayerRadius > box.y0 && std::max(l.ay, l.by) + kPlayerRadius < box.y1) {
        near_.push_back(*w);  // well inside the square: near it, and within reach of none of its corners
        continue;
      }
      int inReach = 0, outOfReach = 0;  // corners; one of each settles it: near, not covering
      for (int k = 0; k < 4 && (inReach == 0 || outOfReach == 0); ++k)
        ++(pointSegmentDistance2(xs[k], ys[k], l.ax, l.ay, l.bx, l.by) < kReach2 ? inReach : outOfReach);
      if (inReach == 4) {  // the disk-swept wall is convex: it covers the square
        near_.resize(mark);
        std::iter_swap(from, w);  // the quarters beside this one will likely find it covering them too
        return;                   // a blocked leaf
      }
      if (inReach == 0 && !reachesBox(l, box)) continue;
      near_.push_back(*w);
    }
    if (near_.size() == mark) {
      nodes_[size_t(node)].join = joins++;
      return;
    }
    if (box.x1 - box.x0 <= kFinestCell) {  // a wall within reach of part of it: blocked, to be safe
      near_.resize(mark);
      return;
    }
    doubts_.push_back({node, depth, ix, iy, uint32_t(mark), uint32_t(near_.size())});
  }

  // Whether the wall comes within the radius of the box, none of whose corners is within it: then
  // the nearest points are an end of the wall and the box (a square and a segment apart are
  // nearest at a corner of one of them), or the wall crosses the box.
  static bool reachesBox(const FlatWall& l, const Box& box) {
    if (box.distance2To(l.ax, l.ay) < kReach2 || box.distance2To(l.bx, l.by) < kReach2) return true;
    const double dx = l.bx - l.ax, dy = l.by - l.ay;  // Liang-Barsky: some of the wall inside the box
    double t0 = 0, t1 = 1;
    const double p[4] = {-dx, dx, -dy, dy}, q[4] = {l.ax - box.x0, box.x1 - l.ax, l.ay - box.y0, box.y1 - l.ay};
    for (int i = 0; i < 4; ++i) {
      if (p[i] == 0) {
        if (q[i] < 0) return false;
        continue;
      }
      const double t = q[i] / p[i];
      if (p[i] < 0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
    }
    return t0 <= t1;
  }

  static std::array<Box, 4> quarters(const Box& b) {
    const double mx = (b.x0 + b.x1) / 2, my = (b.y0 + b.y1) / 2;
    return {Box{b.x0, b.y0, mx, my}, Box{mx, b.y0, b.x1, my}, Box{b.x0, my, mx, b.y1}, Box{mx, my, b.x1, b.y1}};
  }

  // A leaf's join index if it is open, else -1 (to the search's answer, an undecided leaf is
  // open round its rim if ringOpen); and an undecided leaf's index in doubts_, else -1.
  int openJoin(const Node& n, Open open) const {
    if (n.child >= 0 || n.join == -1) return -1;
    if (n.join >= 0) return n.join;
    const size_t d = size_t(-2 - n.join);
    return open == Open::FreeOrUndecided || doubts_[d].ring ? undecidedJoin_[d] : -1;
  }
  bool ring(const Node& n) const { return doubtOf(n) >= 0 && doubts_[size_t(doubtOf(n))].ring; }
  static int doubtOf(const Node& n) { return n.child < 0 && n.join <= -2 ? -2 - n.join : -1; }

  void linkInside(int node, const Box& box, Open open, Joins& joins) const {
    const int c = nodes_[size_t(node)].child;
    if (c < 0) return;
    const auto q = quarters(box);
    for (int k = 0; k < 4; ++k) linkInside(c + k, q[size_t(k)], open, joins);
    linkAcross(c, q[0], c + 1, q[1], true, open, joins), linkAcross(c + 2, q[2], c + 3, q[3], true, open, joins);
    linkAcross(c, q[0], c + 2, q[2], false, open, joins), linkAcross(c + 1, q[1], c + 3, q[3], false, open, joins);
  }
  // `a` left of `b` (sideways) or below it; descends to the leaves along their shared side. Two
  // undecided leaves join only where a point of their shared stretch is clear of the walls.
  void linkAcross(int a, const Box& boxA, int b, const Box& boxB, bool sideways, Open open, Joins& joins) const {
    const Node &na = nodes_[size_t(a)], &nb = nodes_[size_t(b)];
    if (na.child < 0 && nb.child < 0) {
      const int ja = openJoin(na, open), jb = openJoin(nb, open);
      if (ja < 0 || jb < 0) return;
      const double x0 = sideways ? boxA.x1 : std::max(boxA.x0, boxB.x0),
                   y0 = sideways ? std::max(boxA.y0, boxB.y0) : boxA.y1;
      const double x1 = sideways ? boxA.x1 : std::min(boxA.x1, boxB.x1),
                   y1 = sideways ? std::min(boxA.y1, boxB.y1) : boxA.y1;
      if (open == Open::Free || (openAlong(doubtOf(na), x0, y0, x1, y1) && openAlong(doubtOf(nb), x0, y0, x1, y1)))
        joins.join(ja, jb);
      return;
    }
    // The children along the shared side: a's right (or top) pair, b's left (or bottom) pair.
    const auto qa = quarters(boxA), qb = quarters(boxB);
    const int ka1 = sideways ? 1 : 2, kb2 = sideways ? 2 : 1;
    const int a1 = na.child < 0 ? a : na.child + ka1, a2 = na.child < 0 ? a : na.child + 3;
    const int b1 = nb.child < 0 ? b : nb.child, b2 = nb.child < 0 ? b : nb.child + kb2;
    const Box& boxA1 = na.child < 0 ? boxA : qa[size_t(ka1)];
    const Box& boxA2 = na.child < 0 ? boxA : qa[3];
    const Box& boxB1 = nb.child < 0 ? boxB : qb[0];
    const Box& boxB2 = nb.child < 0 ? boxB : qb[size_t(kb2)];
    linkAcross(a1, boxA1, b1, boxB1, sideways, open, joins);
    linkAcross(a2, boxA2, b2, boxB2, sideways, open, joins);
  }

  void near(int node, const Box& box, const std::vector<std::pair<double, double>>& shape, double reach, Open open,
            std::vector<Leaf>& out) const {
    bool inside = shape.size() >= 3;  // the box's corner inside the (counter-clockwise) shape
    for (size_t i = 0; i < shape.size() && inside; ++i) {
      const auto [ax, ay] = shape[i];
      const auto [bx, by] = shape[(i + 1) % shape.size()];
      inside = (bx - ax) * (box.y0 - ay) - (by - ay) * (box.x0 - ax) >= 0;
    }
    double d = inside ? 0 : INFINITY;
    for (size_t i = 0; i < shape.size(); ++i) {
      const auto [ax, ay] = shape[i];
      const auto [bx, by] = shape[(i + 1) % shape.size()];
      d = std::min(d, segmentBoxDistance(ax, ay, bx, by, box));
    }
    if (d > reach) return;
    const Node& n = nodes_[size_t(node)];
    if (n.child >= 0) {
      const auto q = quarters(box);
      for (int k = 0; k < 4; ++k) near(n.child + k, q[size_t(k)], shape, reach, open, out);
    } else if (const int j = openJoin(n, open); j >= 0) {
      out.push_back({j, box, open == Open::Free && ring(n)});
    }
  }

  void along(int node, const Box& box, physics::Vec2 a, physics::Vec2 b, Open open, std::vector<Stretch>& out) const {
    // Liang-Barsky: the part of a -> b inside the box.
    const double dx = double(b.x) - a.x, dy = double(b.y) - a.y;
    double t0 = 0, t1 = 1;
    const double p[4] = {-dx, dx, -dy, dy}, q[4] = {a.x - box.x0, box.x1 - a.x, a.y - box.y0, box.y1 - a.y};
    for (int i = 0; i < 4; ++i) {
      if (p[i] == 0) {
        if (q[i] < 0) return;
        continue;
      }
      const double t = q[i] / p[i];
      if (p[i] < 0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
    }
    if (t0 > t1) return;
    const Node& n = nodes_[size_t(node)];
    if (n.child >= 0) {
      const auto quarter = quarters(box);
      for (int k = 0; k < 4; ++k) along(n.child + k, quarter[size_t(k)], a, b, open, out);
    } else if (const int j = openJoin(n, open); j >= 0) {
      out.push_back({t0, t1, j, doubtOf(n)});
    }
  }

  const std::vector<physics::Vec2>& corners_;
  std::vector<FlatWall> walls_;
  Box hull_, square_;
  std::vector<Node> nodes_;
  double cell_ = 0;                 // the side of the cells in doubts_
  std::vector<Doubt> doubts_;       // the cells of the last level grown that are in doubt (once stopped, undecided)
  std::vector<int> undecidedJoin_;  // the undecided leaves' join indices, as doubts_
  std::vector<int32_t> near_;       // their walls
};

// Grows every face's tree coarse to fine, one cell size at a time over all faces (the largest
// cells first), while the next level fits in kSearchBytes; `joins` counts the join indices handed
// out. Returns the side of the cells it left undecided (kFinestCell when it reached the finest
// everywhere).
double growTrees(std::vector<FaceTree>& trees, int& joins) {
  for (FaceTree& t : trees) t.plant(joins);
  for (;;) {
    double largest = 0;
    size_t used = 0;
    for (const FaceTree& t : trees) largest = std::max(largest, t.cellInDoubt()), used += t.bytes();
    if (largest == 0) return kFinestCell;
    size_t split = 0;
    for (const FaceTree& t : trees)
      if (t.cellInDoubt() > largest / 2) split += t.splitBytes();
    bool fits = used + split <= kSearchBytes;
    for (FaceTree& t : trees)
      if (fits && t.cellInDoubt() > largest / 2) {
        const size_t others = used - t.bytes();
        fits = t.grow(joins, others, kSearchBytes);
        used = others + t.bytes();
      }
    if (!fits) {
      for (FaceTree& t : trees) t.stop(joins);
      return largest;
    }
  }
}

using Shape = std::vector<std::pair<double, double>>;

Shape mapped(const Shape& shape, const FlatMap& map) {
  Shape out = shape;
  for (auto& [x, y] : out) map.apply(x, y);
  return out;
}

// Whether the player's disk slides from (x0, y0) to (x1, y1) in a straight line clear of every
// wall in `walls`.
bool clearPath(double x0, double y0, double x1, double y1, const std::vector<FlatWall>& walls) {
  for (const FlatWall& w : walls) {
    if (segmentsMeet(x0, y0, x1, y1, w.ax, w.ay, w.bx, w.by)) return false;
    const double d2 = std::min(
        {pointSegmentDistance2(x0, y0, w.ax, w.ay, w.bx, w.by), pointSegmentDistance2(x1, y1, w.ax, w.ay, w.bx, w.by),
         pointSegmentDistance2(w.ax, w.ay, x0, y0, x1, y1), pointSegmentDistance2(w.bx, w.by, x0, y0, x1, y1)});
    if (d2 < kReach2) return false;
  }
  return true;
}

// The open leaves whose squares come within `reach` of `p`: on its face, and across the edges
// within `reach` of it (as the face's own frame sees them, laid flat).
struct NearLeaf {
  FaceTree::Leaf leaf;
  size_t face, edge;  // the face whose tree holds it, and the edge of p's face it lies across (or its corner count)
};
std::vector<NearLeaf> leavesRound(const Stage& stage, const std::vector<FaceTree>& trees, const LevelPoint& p,
                                  double reach, Open open) {
  const auto f = static_cast<size_t>(p.face);
  const StageFace& face = stage.faces[f];
  const Shape point{{double(p.position.x), double(p.position.y)}};
  std::vector<NearLeaf> out;
  std::vector<FaceTree::Leaf> leaves;
  trees[f].leavesNear(point, reach, open, leaves);
  for (const auto& l : leaves) out.push_back({l, f, face.corners.size()});
  for (size_t k = 0; k < face.corners.size(); ++k) {
    if (distanceToSegment(p.position.x, p.position.y, face.corners[k], face.corners[(k + 1) % face.corners.size()]) >
        reach)
      continue;
    const auto g = static_cast<size_t>(face.neighbours[k].face);
    leaves.clear();
    trees[g].leavesNear(mapped(point, unfoldAcross(stage, f, k).inverse()), reach, open, leaves);
    for (const auto& l : leaves) out.push_back({l, g, k});
  }
  return out;
}

// Moves a point inside `box` to the nearest point of its rim.
void nearestOnRim(const Box& box, double& x, double& y) {
  const double toSide[4] = {x - box.x0, box.x1 - x, y - box.y0, box.y1 - y};
  const int nearest = int(std::min_element(toSide, toSide + 4) - toSide);
  if (nearest == 0) x = box.x0;
  if (nearest == 1) x = box.x1;
  if (nearest == 2) y = box.y0;
  if (nearest == 3) y = box.y1;
}

// The free leaves the player's disk at `p` reaches by sliding in a straight line, clear of every
// wall, to the nearest point of their square, within `reach`: on p's face, and across the edges
// within `reach` of it (the line carried over the edge). Enough even where p has only a few units
// of room (a corner 100 units from a floor and a wall): the cells next to the walls are in doubt,
// so blocked, and the free ones lie a cell or two beyond. One leaf per joined piece is enough.
std::vector<int> leavesInSight(const Stage& stage, const std::vector<FaceTree>& trees, const LevelPoint& p,
                               double reach, Joins& joins) {
  const auto f = static_cast<size_t>(p.face);
  const double px = p.position.x, py = p.position.y;
  std::vector<FlatWall> local;  // the walls a path of `reach` from p could come near
  const double near = reach + kPlayerRadius;
  for (const FlatWall& w : trees[f].walls())
    if (pointSegmentDistance2(px, py, w.ax, w.ay, w.bx, w.by) < near * near) local.push_back(w);
  std::vector<int> out;
  if (!clearPath(px, py, px, py, local)) return out;
  const StageFace& face = stage.faces[f];
  struct Candidate {
    double distance, x, y;  // its square's nearest point, in p's face's frame
    int join;
    size_t edge;  // the edge the path crosses, or the face's corner count
  };
  std::vector<Candidate> candidates;
  for (const NearLeaf& n : leavesRound(stage, trees, p, reach, Open::Free)) {
    const bool here = n.edge == face.corners.size();
    const FlatMap there = here ? FlatMap{} : unfoldAcross(stage, f, n.edge);  // the neighbour's frame to p's
    double qx = px, qy = py;
    if (!here) there.inverse().apply(qx, qy);
    double x = std::clamp(qx, n.leaf.box.x0, n.leaf.box.x1), y = std::clamp(qy, n.leaf.box.y0, n.leaf.box.y1);
    if (n.leaf.ring) nearestOnRim(n.leaf.box, x, y);                  // only its rim is known to be open
    if (!insidePolygon(stage.faces[n.face].corners, x, y)) continue;  // only the part of a square on its face
    there.apply(x, y);
    candidates.push_back({std::hypot(x - px, y - py), x, y, n.leaf.join, n.edge});
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
  std::vector<int> roots;
  for (const Candidate& c : candidates) {
    const int root = joins.root(c.join);
    if (std::find(roots.begin(), roots.end(), root) != roots.end()) continue;
    // Over an edge, the path must leave p's face by that edge (not by another, near a corner).
    bool byItsEdge = true;
    for (size_t k = 0; k < face.corners.size() && byItsEdge && c.edge < face.corners.size(); ++k) {
      const physics::Vec2 a = face.corners[k], b = face.corners[(k + 1) % face.corners.size()];
      byItsEdge = k == c.edge || !segmentsMeet(px, py, c.x, c.y, a.x, a.y, b.x, b.y);
    }
    if (!byItsEdge || !clearPath(px, py, c.x, c.y, local)) continue;
    roots.push_back(root);
    out.push_back(c.join);
  }
  return out;
}

// The open leaves from which the player's disk meets the goal's square: on its face, and on the
// faces across the edges the square comes within the radius of.
std::vector<int> leavesMeetingGoal(const Level& level, const Stage& stage, const std::vector<FaceTree>& trees,
                                   Open open) {
  const auto f = static_cast<size_t>(level.goal.face);
  const double h = goalHalfSide(level), gx = level.goal.position.x, gy = level.goal.position.y;
  const Shape square{{gx - h, gy - h}, {gx + h, gy - h}, {gx + h, gy + h}, {gx - h, gy + h}};
  std::vector<FaceTree::Leaf> leaves;
  trees[f].leavesNear(square, kPlayerRadius, open, leaves);
  const StageFace& face = stage.faces[f];
  for (size_t k = 0; k < face.corners.size(); ++k) {
    double d = INFINITY;
    for (const auto& [x, y] : square)
      d = std::min(d, distanceToSegment(x, y, face.corners[k], face.corners[(k + 1) % face.corners.size()]));
    if (d > kPlayerRadius) continue;
    trees[size_t(face.neighbours[k].face)].leavesNear(mapped(square, unfoldAcross(stage, f, k).inverse()),
                                                      kPlayerRadius, open, leaves);
  }
  std::vector<int> out;
  for (const auto& l : leaves)
    if (!l.ring) out.push_back(l.join);  // its rim may be far from the square (leavesInSight looks at it from the goal)
  return out;
}

// Whether a point of the stretch t0..t1 of edge k of a face (its frame's corners) is clear for a
// leaf (FaceTree::openAlong).
bool openAlongEdge(const FaceTree& tree, int doubt, const std::vector<physics::Vec2>& corners, size_t k, double t0,
                   double t1) {
  const physics::Vec2 a = corners[k], b = corners[(k + 1) % corners.size()];
  const double dx = double(b.x) - a.x, dy = double(b.y) - a.y;
  return tree.openAlong(doubt, a.x + t0 * dx, a.y + t0 * dy, a.x + t1 * dx, a.y + t1 * dy);
}

// Joins the open leaves on either side of every edge whose stretches of it overlap (undecided
// ones only where a point of the overlap is clear of the walls).
void linkEdges(const Stage& stage, const std::vector<FaceTree>& trees, Open open, Joins& joins) {
  for (size_t f = 0; f < stage.faceCount(); ++f) {
    const StageFace& face = stage.faces[f];
    for (size_t k = 0; k < face.corners.size(); ++k) {
      const auto [g, j] = face.neighbours[k];
      if (size_t(g) < f) continue;  // each edge once
      std::vector<FaceTree::Stretch> here, there;
      trees[f].leavesAlong(face.corners[k], face.corners[(k + 1) % face.corners.size()], open, here);
      const StageFace& other = stage.faces[size_t(g)];
      trees[size_t(g)].leavesAlong(other.corners[size_t(j)], other.corners[(size_t(j) + 1) % other.corners.size()],
                                   open, there);
      for (auto& s : there) s = {1 - s.to, 1 - s.from, s.join, s.doubt};  // the other face runs the edge the other way
      auto byStart = [](const FaceTree::Stretch& a, const FaceTree::Stretch& b) { return a.from < b.from; };
      std::sort(here.begin(), here.end(), byStart);
      std::sort(there.begin(), there.end(), byStart);
      for (size_t a = 0, b = 0; a < here.size() && b < there.size();) {
        const double t0 = std::max(here[a].from, there[b].from), t1 = std::min(here[a].to, there[b].to);
        if (t0 <= t1 && (open == Open::Free ||
                         (openAlongEdge(trees[f], here[a].doubt, face.corners, k, t0, t1) &&
                          openAlongEdge(trees[size_t(g)], there[b].doubt, other.corners, size_t(j), 1 - t1, 1 - t0))))
          joins.join(here[a].join, there[b].join);
        here[a].to < there[b].to ? ++a : ++b;
      }
    }
  }
}

// Where the search stopped coarse: the undecided cells round `p` (on its face and across the edges
// near it) grown to the finest, within kRefineBytes for each tree.
void refineRound(const Stage& stage, std::vector<FaceTree>& trees, const LevelPoint& p, double radius, int& joins) {
  const auto f = static_cast<size_t>(p.face);
  const StageFace& face = stage.faces[f];
  trees[f].refineNear(p.position.x, p.position.y, radius, trees[f].bytes() + kRefineBytes, joins);
  for (size_t k = 0; k < face.corners.size(); ++k) {
    if (distanceToSegment(p.position.x, p.position.y, face.corners[k], face.corners[(k + 1) % face.corners.size()]) >
        radius)
      continue;
    double x = p.position.x, y = p.position.y;
    unfoldAcross(stage, f, k).inverse().apply(x, y);
    FaceTree& there = trees[size_t(face.neighbours[k].face)];
    there.refineNear(x, y, radius, there.bytes() + kRefineBytes, joins);
  }
}

// Whether the open leaves join the start to the goal. Counting free leaves only, the start and
// the goal reach the leaves they can slide to in a straight line within `reach`; counting
// undecided leaves too (the upper bound), every open leaf within the least reach, which holds
// every leaf a search with the finest cells would have started from.
bool joined(const Level& level, const Stage& stage, const std::vector<FaceTree>& trees, int joinCount, double reach,
            Open open) {
  Joins joins(joinCount);
  for (const FaceTree& t : trees) t.linkInside(open, joins);
  linkEdges(stage, trees, open, joins);
  auto seeds = [&](const LevelPoint& p) {
    if (open == Open::Free) return leavesInSight(stage, trees, p, reach, joins);
    std::vector<int> out;
    for (const NearLeaf& n : leavesRound(stage, trees, p, kSeedReachLeast, open)) out.push_back(n.leaf.join);
    return out;
  };
  std::vector<int> roots;
  for (const int l : seeds(level.start)) roots.push_back(joins.root(l));
  std::sort(roots.begin(), roots.end());
  std::vector<int> ends = leavesMeetingGoal(level, stage, trees, open);
  for (const int l : seeds(level.goal)) ends.push_back(l);
  for (const int l : ends)
    if (std::binary_search(roots.begin(), roots.end(), joins.root(l))) return true;
  return false;
}

}  // namespace

ReachAnswer searchReach(const Level& level, const Stage& stage) {
  ReachAnswer answer;
  std::vector<FaceTree> trees;
  trees.reserve(stage.faceCount());
  for (size_t f = 0; f < stage.faceCount(); ++f) {
    trees.emplace_back(stage.faces[f].corners, mergedWalls(wallsNear(level, stage, f, kEdgeMargin, Counting::Reach)));
    answer.walls += trees.back().walls().size();
  }
  // The start's disk meeting the goal's square, or sliding straight to the goal's point.
  const auto& goal = level.goal.position;
  const auto& start = level.start.position;
  if (level.start.face == level.goal.face) {
    const double h = goalHalfSide(level);
    const Box square{double(goal.x) - h, double(goal.y) - h, double(goal.x) + h, double(goal.y) + h};
    if (square.distanceTo(start.x, start.y) <= kPlayerRadius ||
        clearPath(start.x, start.y, goal.x, goal.y, trees[size_t(level.start.face)].walls())) {
      answer.reachable = true;
      return answer;
    }
  }
  int joinCount = 0;
  answer.finestCell = growTrees(trees, joinCount);
  if (answer.finestCell > kFinestCell)
    for (const LevelPoint* p : {&level.start, &level.goal})
      refineRound(stage, trees, *p, 2 * answer.finestCell + 256, joinCount);
  const double reach = seedReach(answer.finestCell);
  answer.reachable = joined(level, stage, trees, joinCount, reach, Open::Free);
  answer.couldBeOpen = answer.reachable || (answer.finestCell > kFinestCell &&
                                            joined(level, stage, trees, joinCount, reach, Open::FreeOrUndecided));
  return answer;
}

}  // namespace platon::stage
