#include "platon/stage/net.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

namespace platon::stage {
namespace {

std::vector<Eigen::Vector2d> outline(const StageFace& face, const NetFace& at) {
  std::vector<Eigen::Vector2d> out;
  for (const physics::Vec2 c : face.corners) out.push_back(at.place(c.x, c.y));
  return out;
}

// Whether two convex polygons' interiors overlap (separating axis test, with a margin for the
// shared edges of neighbours).
bool overlap(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b, double margin) {
  for (const auto* poly : {&a, &b})
    for (size_t i = 0; i < poly->size(); ++i) {
      const Eigen::Vector2d e = (*poly)[(i + 1) % poly->size()] - (*poly)[i];
      const Eigen::Vector2d n(-e.y(), e.x());
      double aLo = INFINITY, aHi = -INFINITY, bLo = INFINITY, bHi = -INFINITY;
      for (const auto& p : a) aLo = std::min(aLo, n.dot(p)), aHi = std::max(aHi, n.dot(p));
      for (const auto& p : b) bLo = std::min(bLo, n.dot(p)), bHi = std::max(bHi, n.dot(p));
      if (aHi <= bLo + margin * n.norm() || bHi <= aLo + margin * n.norm()) return false;
    }
  return true;
}

}  // namespace

std::vector<NetFace> unfold(const Stage& stage) {
  const size_t count = stage.faceCount();
  std::vector<NetFace> net(count);
  std::vector<bool> placed(count, false);
  net[0] = {Eigen::Vector2d::Zero(), Eigen::Vector2d::UnitX(), -1};
  placed[0] = true;
  double size = 0;
  for (const auto& f : stage.faces)
    for (const auto& c : f.corners) size = std::max(size, std::hypot(double(c.x), double(c.y)));
  for (size_t done = 1; done < count; ++done) {
    bool progress = false;
    // The lowest-numbered face not yet flat that can join a flat face without overlapping.
    for (size_t g = 0; g < count && !progress; ++g) {
      if (placed[g]) continue;
      const StageFace& face = stage.faces[g];
      for (size_t j = 0; j < face.neighbours.size() && !progress; ++j) {
        const auto [f, i] = face.neighbours[j];
        if (!placed[static_cast<size_t>(f)]) continue;
        const StageFace& other = stage.faces[static_cast<size_t>(f)];
        const NetFace& at = net[static_cast<size_t>(f)];
        // g's edge j (corner j -> j + 1) lies on f's edge i, the other way round.
        const physics::Vec2 fa = other.corners[static_cast<size_t>(i)];
        const physics::Vec2 fb = other.corners[(static_cast<size_t>(i) + 1) % other.corners.size()];
        const Eigen::Vector2d to0 = at.place(fb.x, fb.y), to1 = at.place(fa.x, fa.y);
        const physics::Vec2 ga = face.corners[j], gb = face.corners[(j + 1) % face.corners.size()];
        const Eigen::Vector2d local(double(gb.x) - ga.x, double(gb.y) - ga.y);
        const double turn = std::atan2((to1 - to0).y(), (to1 - to0).x()) - std::atan2(local.y(), local.x());
        NetFace candidate;
        candidate.xAxis = Eigen::Vector2d(std::cos(turn), std::sin(turn));
        candidate.origin = Eigen::Vector2d::Zero();
        candidate.origin = to0 - candidate.place(ga.x, ga.y);
        candidate.attachedTo = f;
        const auto shape = outline(face, candidate);
        bool free = true;
        for (size_t k = 0; k < count && free; ++k)
          if (placed[k] && overlap(shape, outline(stage.faces[k], net[k]), 1e-6 * size)) free = false;
        if (!free) continue;
        net[g] = candidate;
        placed[g] = true;
        progress = true;
      }
    }
    if (!progress) break;  // no room anywhere: leave the rest where they are (never for a convex solid's net so far)
  }
  return net;
}

std::string neighbourTable(const Stage& stage) {
  size_t edges = 0;
  for (const auto& f : stage.faces) edges = std::max(edges, f.neighbours.size());
  std::ostringstream out;
  out << "| face |";
  for (size_t k = 0; k < edges; ++k) out << " edge " << k << " |";
  out << "\n|---|";
  for (size_t k = 0; k < edges; ++k) out << "---|";
  out << "\n";
  for (size_t f = 0; f < stage.faceCount(); ++f) {
    out << "| " << f << " |";
    for (const Neighbour& n : stage.faces[f].neighbours) out << " " << n.face << " (its edge " << n.edge << ") |";
    out << "\n";
  }
  return out.str();
}

namespace {

// A line's colour on white paper: its tag's, darkened where it is too light to read there.
std::string tagColour(const LevelLine& l, const TagTable& tags) {
  if (l.tag == 0) return l.oneWay ? "#56b4e9" : "#333";
  const TagStyle s = tags.style(l.tag);
  const double light = (0.2126 * s.r + 0.7152 * s.g + 0.0722 * s.b) / 255, k = light > 0.7 ? 0.75 : 1.0;
  char out[8];
  std::snprintf(out, sizeof out, "#%02x%02x%02x", int(s.r * k), int(s.g * k), int(s.b * k));
  return out;
}

// Where the net lies on the page: its bounds, its scale and the margin around it.
struct NetPage {
  Eigen::Vector2d lo, hi;
  double scale = 1, pad = 30;
};

// A point's "x,y" on the page. SVG's y runs down: flipped so that the net reads as the faces' own
// frames do (y up).
std::string netPoint(const NetPage& page, const Eigen::Vector2d& p) {
  std::ostringstream s;
  s.precision(1);
  s << std::fixed << (p.x() - page.lo.x()) * page.scale + page.pad << ","
    << (page.hi.y() - p.y()) * page.scale + page.pad + 24;
  return s.str();
}

void netLine(std::ostringstream& svg, const NetPage& page, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
             const char* colour) {
  const std::string pa = netPoint(page, a), pb = netPoint(page, b);
  svg << "<line x1=\"" << pa.substr(0, pa.find(',')) << "\" y1=\"" << pa.substr(pa.find(',') + 1) << "\" x2=\""
      << pb.substr(0, pb.find(',')) << "\" y2=\"" << pb.substr(pb.find(',') + 1) << "\" stroke=\"" << colour
      << "\" stroke-width=\"2.5\"/>\n";
}

// An arrow from `from` to `to`: its shaft and its head, the head's size a part of the edge.
void netArrow(std::ostringstream& svg, const NetPage& page, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
              const char* colour, double edge) {
  netLine(svg, page, from, to, colour);
  const Eigen::Vector2d d = (to - from).normalized() * edge * 0.07, n(-d.y(), d.x());
  svg << "<polygon fill=\"" << colour << "\" points=\"" << netPoint(page, to) << " " << netPoint(page, to - d + n * 0.5)
      << " " << netPoint(page, to - d - n * 0.5) << "\"/>\n";
}

void netLabel(std::ostringstream& svg, const NetPage& page, const Eigen::Vector2d& p, const std::string& text,
              int sizePx, const char* colour) {
  const std::string s = netPoint(page, p);
  svg << "<text x=\"" << s.substr(0, s.find(',')) << "\" y=\"" << s.substr(s.find(',') + 1) << "\" font-size=\""
      << sizePx << "\" fill=\"" << colour << "\" text-anchor=\"middle\" dominant-baseline=\"middle\">" << text
      << "</text>\n";
}

// "down" on a face: an arrow from its centre along -y, or along the level's own gravity for this
// face (then labelled with it). `o`: the face's origin on the page.
void netDown(std::ostringstream& svg, const NetPage& page, const NetFace& at, const Eigen::Vector2d& centre,
             const Eigen::Vector2d& o, double edge, const LevelFace* levelFace) {
  Eigen::Vector2d down(0, -1);
  if (levelFace && levelFace->gravityQ16) {
    down = Eigen::Vector2d(double(levelFace->gravityQ16->x), double(levelFace->gravityQ16->y));
    down = down.norm() > 0 ? down.normalized() : Eigen::Vector2d(0, 0);
  }
  const Eigen::Vector2d downEnd = centre + (at.place(down.x() * edge * 0.14, down.y() * edge * 0.14) - o);
  const Eigen::Vector2d downStart = centre + (at.place(down.x() * edge * 0.02, down.y() * edge * 0.02) - o);
  if (down.norm() > 0) netArrow(svg, page, downStart, downEnd, "#36c", edge);
  if (levelFace && levelFace->gravityQ16) {
    std::ostringstream g;
    g.precision(3);
    g << "g " << double(levelFace->gravityQ16->x) / 65536 << " " << double(levelFace->gravityQ16->y) / 65536;
    netLabel(svg, page, downEnd + (at.place(down.x() * edge * 0.08, down.y() * edge * 0.08) - o), g.str(), 11, "#36c");
  }
}

// The level on face f: its lines in their tags' colours (one-way dashed), and the start's and the
// goal's dots when they are on it.
void netLevelFace(std::ostringstream& svg, const NetPage& page, const NetFace& at, const Eigen::Vector2d& o,
                  double edge, const Level& level, size_t f) {
  for (const LevelLine& l : level.faces[f].lines) {
    const std::string pa = netPoint(page, at.place(l.a.x, l.a.y)), pb = netPoint(page, at.place(l.b.x, l.b.y));
    svg << "<line x1=\"" << pa.substr(0, pa.find(',')) << "\" y1=\"" << pa.substr(pa.find(',') + 1) << "\" x2=\""
        << pb.substr(0, pb.find(',')) << "\" y2=\"" << pb.substr(pb.find(',') + 1) << "\" stroke=\""
        << tagColour(l, *level.tags) << "\" stroke-width=\"2\"" << (l.oneWay ? " stroke-dasharray=\"5,3\"" : "")
        << "/>\n";
  }
  for (const auto& [point, name, colour] :
       {std::tuple{&level.start, "start", "#1a1"}, std::tuple{&level.goal, "goal", "#b8a200"}}) {
    if (point->face != static_cast<int>(f)) continue;
    const std::string p = netPoint(page, at.place(point->position.x, point->position.y));
    svg << "<circle cx=\"" << p.substr(0, p.find(',')) << "\" cy=\"" << p.substr(p.find(',') + 1)
        << "\" r=\"5\" fill=\"" << colour << "\"/>\n";
    netLabel(svg, page, at.place(point->position.x, point->position.y) + (at.place(0, edge * 0.06) - o), name, 11,
             colour);
  }
}

// Face f of the net: its outline (face 0 tinted), its axes from its origin (corner 0: x red along
// the floor, y green), its number, its "down", and the level's lines and points on it.
void netFace(std::ostringstream& svg, const NetPage& page, const StageFace& face, const NetFace& at, size_t f,
             double edge, const Level* level) {
  svg << "<polygon fill=\"" << (f == 0 ? "#fff3c4" : "#eef2f7") << "\" stroke=\"#333\" stroke-width=\"1.2\" points=\"";
  for (const auto& p : outline(face, at)) svg << netPoint(page, p) << " ";
  svg << "\"/>\n";
  const double arrow = edge * 0.22;
  const Eigen::Vector2d o = at.place(0, 0);
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& p : outline(face, at)) centre += p;
  centre /= static_cast<double>(face.corners.size());
  const Eigen::Vector2d inset = o + (centre - o) * 0.22;
  const Eigen::Vector2d xEnd = inset + (at.place(arrow, 0) - o), yEnd = inset + (at.place(0, arrow) - o);
  netArrow(svg, page, inset, xEnd, "#d22", edge);
  netArrow(svg, page, inset, yEnd, "#1a1", edge);
  netLabel(svg, page, xEnd + (xEnd - inset).normalized() * edge * 0.07, "x", 11, "#d22");
  netLabel(svg, page, yEnd + (yEnd - inset).normalized() * edge * 0.07, "y", 11, "#1a1");
  netLabel(svg, page, centre + (at.place(0, edge * 0.1) - o), std::to_string(f), 22, "#000");
  const LevelFace* levelFace = level && f < level->faces.size() ? &level->faces[f] : nullptr;
  netDown(svg, page, at, centre, o, edge, levelFace);
  if (levelFace) netLevelFace(svg, page, at, o, edge, *level, f);
}

}  // namespace

std::string netSvg(const Stage& stage, const std::vector<NetFace>& net, const std::string& title, const Level* level) {
  NetPage page{Eigen::Vector2d::Constant(INFINITY), -Eigen::Vector2d::Constant(INFINITY), 1, 30};
  for (size_t f = 0; f < stage.faceCount(); ++f)
    for (const auto& p : outline(stage.faces[f], net[f])) page.lo = page.lo.cwiseMin(p), page.hi = page.hi.cwiseMax(p);
  const auto& c0 = stage.faces[0].corners;
  const double edge = std::hypot(double(c0[1].x - c0[0].x), double(c0[1].y - c0[0].y));
  const Eigen::Vector2d lo = page.lo, hi = page.hi;
  page.scale = 600.0 / std::max(hi.x() - lo.x(), hi.y() - lo.y());
  const double pad = page.pad;
  const double width = std::max(720.0, (hi.x() - lo.x()) * page.scale + 2 * pad),
               height = (hi.y() - lo.y()) * page.scale + 2 * pad + 24 + (level ? 14 : 0);
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << int(width) << "\" height=\"" << int(height)
      << "\" font-family=\"DejaVu Sans, sans-serif\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << pad << "\" y=\"20\" font-size=\"15\">" << title << "</text>\n";
  for (size_t f = 0; f < stage.faceCount(); ++f) netFace(svg, page, stage.faces[f], net[f], f, edge, level);
  svg << "<text x=\"" << pad << "\" y=\"" << int(height - 8 - (level ? 14 : 0))
      << "\" font-size=\"11\" fill=\"#555\">face number; x (red) and y (green) from each face's origin, corner 0; "
      << (level ? "blue: down (g gx gy: the face's own gravity)" : "blue: down (-y)") << "</text>\n";
  if (level)
    svg << "<text x=\"" << pad << "\" y=\"" << int(height - 8)
        << "\" font-size=\"11\" fill=\"#555\">the level's lines by tag (dashed: one-way), its start and its "
           "goal</text>\n";
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace platon::stage
