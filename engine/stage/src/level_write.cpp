// Writing levels: afresh, or over the text they were read from, keeping what did not change (the
// editor saves this way, so a designer's comments and order survive an edit).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "platon/stage/level.h"

namespace platon::stage {
namespace {

std::string decimal(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string solidText(const Level& level) {
  return level.solid ? std::string(solidName(*level.solid)) : "MESH " + level.mesh;
}

std::string startText(const Level& level) {
  std::string text = std::to_string(level.start.face) + " " + std::to_string(level.start.position.x) + " " +
                     std::to_string(level.start.position.y);
  if (level.startMillidegrees != 0) text += " " + decimal(static_cast<double>(level.startMillidegrees) / 1000);
  return text;
}

std::string goalText(const Level& level) {
  return std::to_string(level.goal.face) + " " + std::to_string(level.goal.position.x) + " " +
         std::to_string(level.goal.position.y);
}

// The shortest decimal the reader turns back into this many 1/65,536 (it rounds to the nearest):
// 22938 is "0.35", not "0.350006103515625".
std::string q16Text(int64_t q16) {
  const double exact = static_cast<double>(q16) / 65536;
  for (int digits = 1; digits < 17; ++digits) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, exact);
    const double back = std::strtod(text, nullptr) * 65536;
    if (static_cast<int64_t>(std::llround(back)) == q16 && std::abs(back - static_cast<double>(q16)) < 0.5) return text;
  }
  return decimal(exact);
}

std::string faceText(const LevelFace& face) {
  if (!face.gravityQ16) return "%";
  return "% gravity " + q16Text(face.gravityQ16->x) + " " + q16Text(face.gravityQ16->y);
}

std::string segmentText(const Level& level, const LevelLine& l) {
  return std::to_string(l.a.x) + " " + std::to_string(l.a.y) + " " + std::to_string(l.b.x) + " " +
         std::to_string(l.b.y) + (l.oneWay ? " oneway" : "") + level.tags->written(l.tag);
}

std::string freshText(const Level& level) {
  std::ostringstream out;
  out << solidText(level) << "\n" << startText(level) << "\n" << goalText(level) << "\n" << level.size << "\n";
  for (size_t f = 0; f < level.faces.size(); ++f) {
    out << faceText(level.faces[f]) << "  # face " << f << "\n";
    for (const LevelLine& l : level.faces[f].lines) out << segmentText(level, l) << "\n";
  }
  return out.str();
}

struct TextLine {
  std::string_view body, end;  // the line without its line end, and the line end ("", "\n", "\r\n")
};

std::vector<TextLine> splitLines(std::string_view text) {
  std::vector<TextLine> lines;
  while (!text.empty()) {
    const size_t newline = text.find('\n');
    const size_t stop = newline == std::string_view::npos ? text.size() : newline;
    const size_t cr = stop > 0 && text[stop - 1] == '\r' && newline != std::string_view::npos ? 1 : 0;
    lines.push_back(
        {text.substr(0, stop - cr), text.substr(stop - cr, newline == std::string_view::npos ? 0 : cr + 1)});
    text.remove_prefix(std::min(text.size(), stop + 1));
  }
  return lines;
}

// Where a line's values end: its comment, and the spaces before it, are what follows.
size_t valuesEnd(std::string_view body) {
  size_t end = std::min(body.find('#'), body.size());
  while (end > 0 && (body[end - 1] == ' ' || body[end - 1] == '\t' || body[end - 1] == '\r')) --end;
  return end;
}

size_t wordCount(std::string_view values) {
  size_t words = 0;
  for (size_t i = 0; i < values.size(); ++i)
    if (values[i] != ' ' && values[i] != '\t' && (i == 0 || values[i - 1] == ' ' || values[i - 1] == '\t')) ++words;
  return words;
}

enum class Role : uint8_t { Other, Solid, Start, Goal, Size, Face, Segment };

// What each line of the original is (index: line number - 1), and for a face or a segment line its
// face and its index among the face's lines.
struct LineRoles {
  std::vector<Role> role;
  std::vector<int> face, index;
};

LineRoles rolesOf(const Level& before, const std::vector<TextLine>& lines) {
  LineRoles r{std::vector<Role>(lines.size(), Role::Other), std::vector<int>(lines.size(), -1),
              std::vector<int>(lines.size(), -1)};
  auto mark = [&](int line, Role role, int face = -1, int index = -1) {
    if (line < 1 || line > static_cast<int>(lines.size())) return;
    r.role[line - 1] = role, r.face[line - 1] = face, r.index[line - 1] = index;
  };
  int content = 0;  // the header is the first four lines with values: solid, start, goal, size
  for (size_t i = 0; i < lines.size() && content < 4; ++i)
    if (valuesEnd(lines[i].body) > 0) {
      ++content;
      if (content == 1) mark(static_cast<int>(i) + 1, Role::Solid);
      if (content == 4) mark(static_cast<int>(i) + 1, Role::Size);
    }
  mark(before.start.sourceLine, Role::Start);
  mark(before.goal.sourceLine, Role::Goal);
  for (size_t f = 0; f < before.faces.size(); ++f) {
    mark(before.faces[f].sourceLine, Role::Face, static_cast<int>(f));
    for (size_t i = 0; i < before.faces[f].lines.size(); ++i)
      mark(before.faces[f].lines[i].sourceLine, Role::Segment, static_cast<int>(f), static_cast<int>(i));
  }
  return r;
}

// Where the level's segments go in the rewritten text: `kept[i]`, the segment written over line
// i + 1 (null: none); `added[f]`, face f's segments written as new lines.
struct SegmentPlaces {
  std::vector<const LevelLine*> kept;
  std::vector<std::vector<const LevelLine*>> added;
};

// Each edited segment that still stands on its original line, and the rest, new, by face. The
// text must read back in the level's order: a segment keeps its line only while the face's
// segments so far did too, in the file's order; from the first that cannot, all are written new.
SegmentPlaces segmentPlaces(const Level& level, const std::vector<TextLine>& lines, const LineRoles& roles) {
  SegmentPlaces places{std::vector<const LevelLine*>(lines.size(), nullptr),
                       std::vector<std::vector<const LevelLine*>>(level.faces.size())};
  for (size_t f = 0; f < level.faces.size(); ++f) {
    int last = 0;
    for (const LevelLine& l : level.faces[f].lines) {
      const int at = l.sourceLine - 1;
      const bool own = places.added[f].empty() && l.sourceLine > last && at < static_cast<int>(lines.size()) &&
                       roles.role[at] == Role::Segment && roles.face[at] == static_cast<int>(f);
      if (own)
        places.kept[at] = &l, last = l.sourceLine;
      else
        places.added[f].push_back(&l);
    }
  }
  return places;
}

// The line each face's new segments follow: its last segment line in the original (or its '%'
// line). `faces`: the level's face count (the original's, checked by the caller).
std::vector<int> segmentInsertLines(const Level& before, size_t faces) {
  std::vector<int> insertAfter(faces);
  for (size_t f = 0; f < before.faces.size(); ++f) {
    insertAfter[f] = before.faces[f].sourceLine;
    for (const LevelLine& l : before.faces[f].lines) insertAfter[f] = std::max(insertAfter[f], l.sourceLine);
  }
  return insertAfter;
}

}  // namespace

std::string writeLevel(const Level& level, std::string_view original) {
  if (original.empty()) return freshText(level);
  Level before;
  try {
    before = parseLevel(original, level.file, level.tags);
  } catch (const StageError&) {
    return freshText(level);
  }
  if (before.faces.size() != level.faces.size()) return freshText(level);
  const std::vector<TextLine> lines = splitLines(original);
  const LineRoles roles = rolesOf(before, lines);
  const std::string newLine = original.find("\r\n") != std::string_view::npos ? "\r\n" : "\n";

  const SegmentPlaces places = segmentPlaces(level, lines, roles);
  const std::vector<const LevelLine*>& kept = places.kept;
  const std::vector<std::vector<const LevelLine*>>& added = places.added;
  const std::vector<int> insertAfter = segmentInsertLines(before, level.faces.size());

  std::string out;
  out.reserve(original.size() + 64);
  auto write = [&](const TextLine& line, const std::string& values, bool same) {
    if (same)
      out.append(line.body);
    else
      out.append(values).append(line.body.substr(valuesEnd(line.body)));
    out.append(line.end);
  };
  for (size_t i = 0; i < lines.size(); ++i) {
    const TextLine& line = lines[i];
    const int f = roles.face[i];
    switch (roles.role[i]) {
      case Role::Other:
        out.append(line.body).append(line.end);
        break;
      case Role::Solid:
        write(line, solidText(level), level.solid == before.solid && level.mesh == before.mesh);
        break;
      case Role::Start:
        write(line, startText(level),
              level.start == before.start && level.startMillidegrees == before.startMillidegrees);
        break;
      case Role::Goal: {
        // "x y" (two values) names the start's face: kept only while the start's face is the same
        const std::string_view values = line.body.substr(0, valuesEnd(line.body));
        const bool namesFace = wordCount(values) == 3;
        write(line, goalText(level), level.goal == before.goal && (namesFace || level.start.face == before.start.face));
        break;
      }
      case Role::Size:
        write(line, std::to_string(level.size), level.size == before.size);
        break;
      case Role::Face:
        write(line, faceText(level.faces[f]), level.faces[f].gravityQ16 == before.faces[f].gravityQ16);
        break;
      case Role::Segment:
        if (kept[i]) write(line, segmentText(level, *kept[i]), *kept[i] == before.faces[f].lines[roles.index[i]]);
        break;
    }
    if (f < 0) continue;
    if (static_cast<int>(i) + 1 != insertAfter[f] || added[f].empty()) continue;
    if (!out.empty() && out.back() != '\n') out.append(newLine);  // the original's last line had no line end
    for (const LevelLine* l : added[f]) out.append(segmentText(level, *l)).append(newLine);
  }
  return out;
}

}  // namespace platon::stage
