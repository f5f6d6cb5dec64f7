// parseLevel: the level text, line by line. Every rejection names file:line:column.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <span>

#include "platon/stage/level.h"

namespace platon::stage {
namespace {

struct Token {
  std::string_view text;
  int column = 0;
  int end() const { return column + static_cast<int>(text.size()); }  // the column just past it
};

// A token as a message shows it: bytes outside printable ASCII as \x{HH} (a NUL would end the
// message, a byte order mark or a look-alike minus would hide; the braces say where the escape
// ends, so that a NUL before "00" cannot read as one four-digit escape), and at most 40 bytes.
std::string shown(std::string_view token) {
  constexpr size_t kLongest = 40;
  std::string out;
  for (const char c : token.substr(0, kLongest)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      out += c;
      continue;
    }
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x{%02X}", byte);
    out += hex;
  }
  return token.size() > kLongest ? out + "..." : out;
}

// The blank-looking bytes that do not separate values (only spaces and tabs do): a value that
// holds one is named, since it looks like two values.
const char* hiddenSeparatorName(char c) {
  switch (c) {
    case '\v':
      return "a vertical tab (\\x{0B})";
    case '\f':
      return "a form feed (\\x{0C})";
    default:
      return nullptr;
  }
}

// What a value that holds a hidden separator is: "" for most values.
std::string hiddenSeparatorNote(std::string_view token) {
  for (const char c : token)
    if (const char* name = hiddenSeparatorName(c))
      return std::string(" (it holds ") + name + ", which does not separate values: only spaces and tabs do)";
  return "";
}

std::string quoted(std::string_view token) { return "'" + shown(token) + "'" + hiddenSeparatorNote(token); }

struct TextLine {
  int number = 0;
  std::span<const Token> tokens;
};

// The bytes a value is made of: all but the separators (space, tab, CR), '#' and the line end.
constexpr auto kValueByte = [] {
  std::array<bool, 256> table{};
  for (int c = 0; c < 256; ++c)
    table[static_cast<size_t>(c)] = c != ' ' && c != '\t' && c != '\r' && c != '#' && c != '\n';
  return table;
}();

// Reads the text one line at a time (a level of 10^5 segments never holds more than one line's
// tokens): comments (# to the end of the line) and blank lines are skipped.
class LineReader {
 public:
  // A UTF-8 byte order mark in front is skipped (line 1's columns count from after it).
  LineReader(std::string_view text, const std::string& file)
      : text_(text.substr(text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0)), file_(file) {}

  // The next line with values, or nullptr at the end. Valid until the next call. One pass over
  // each line's bytes: values end at a space, tab, CR, '#' (a comment to the end of the line) or
  // the line's end (a level of 10^5 segments is mostly this loop).
  const TextLine* next() {
    const char* const begin = text_.data();
    const char* const end = begin + text_.size();
    while (at_ < text_.size()) {
      const char* const lineStart = begin + at_;
      const char* p = lineStart;
      ++number_;
      tokens_.clear();
      while (p < end && *p != '\n') {
        const char c = *p;
        if (c == ' ' || c == '\t') {
          ++p;
        } else if (kValueByte[static_cast<unsigned char>(c)]) {
          const char* const start = p;
          while (p < end && kValueByte[static_cast<unsigned char>(*p)]) ++p;
          tokens_.push_back(
              {std::string_view(start, static_cast<size_t>(p - start)), static_cast<int>(start - lineStart) + 1});
        } else if (c == '\r') {
          checkAfterCr(std::string_view(p, static_cast<size_t>(end - p)), static_cast<int>(p - lineStart) + 1);
          ++p;
        } else if (c == '#') {
          const void* newline = std::memchr(p, '\n', static_cast<size_t>(end - p));
          const char* stop = newline ? static_cast<const char*>(newline) : end;
          if (const void* cr = std::memchr(p, '\r', static_cast<size_t>(stop - p)))
            checkAfterCr(
                std::string_view(static_cast<const char*>(cr), static_cast<size_t>(end - static_cast<const char*>(cr))),
                static_cast<int>(static_cast<const char*>(cr) - lineStart) + 1);
          p = stop;
        }
      }
      at_ = static_cast<size_t>(p - begin) + 1;
      if (tokens_.empty()) continue;
      current_ = {number_, tokens_};
      return &current_;
    }
    return nullptr;
  }
  // Lines read so far (all of them, once next() returned nullptr).
  int lineCount() const { return number_; }

  // The usual segment line, four whole numbers within +-2^29 and nothing else, read straight from
  // the bytes (a level of 10^5 segments is mostly these): true with the numbers and the line
  // consumed; false leaves the line, whatever it holds, to next().
  bool plainSegment(std::array<int32_t, 4>& values, int& lineNumber, int& column, int& endColumn) {
    const char* const lineStart = text_.data() + at_;
    const char* const end = text_.data() + text_.size();
    const char* p = skipBlanks(lineStart, end);
    const char* const first = p;
    const char* third = p;  // where b's x is written
    for (size_t i = 0; i < values.size(); ++i) {
      if (i > 0) {
        if (p == end || (*p != ' ' && *p != '\t')) return false;
        p = skipBlanks(p, end);
      }
      if (i == 2) third = p;
      if (!plainValue(p, end, values[i])) return false;
    }
    p = skipBlanks(p, end);
    if (p < end && *p == '\r' && p + 1 < end && p[1] == '\n') ++p;
    if (p < end && *p != '\n') return false;
    at_ = static_cast<size_t>(p - text_.data()) + 1;
    lineNumber = ++number_;
    column = static_cast<int>(first - lineStart) + 1;
    endColumn = static_cast<int>(third - lineStart) + 1;
    return true;
  }

  static const char* skipBlanks(const char* p, const char* end) {
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    return p;
  }

  // A whole number within +-2^29 at p, ended by a byte that is no part of a value: true with p past it.
  static bool plainValue(const char*& p, const char* end, int32_t& v) {
    const bool negative = p < end && *p == '-';
    if (p < end && (*p == '-' || *p == '+')) ++p;
    const char* const digits = p;
    int64_t value = 0;
    for (unsigned d; p < end && p - digits < 10 && (d = static_cast<unsigned>(*p - '0')) < 10; ++p)
      value = value * 10 + d;
    if (p == digits || (p < end && kValueByte[static_cast<unsigned char>(*p)]) || value > (1 << 29)) return false;
    v = static_cast<int32_t>(negative ? -value : value);
    return true;
  }

  // At most how many lines with values the text holds before its next line that starts with '%'
  // (a face's segments, to reserve room for them at once; blank and comment lines count too).
  size_t linesBeforeNextFace() const {
    size_t count = 0;
    const char* p = text_.data() + std::min(at_, text_.size());
    const char* const end = text_.data() + text_.size();
    while (p < end) {
      const char* first = p;
      while (first < end && (*first == ' ' || *first == '\t')) ++first;
      if (first < end && *first == '%') break;
      ++count;
      const void* newline = std::memchr(p, '\n', static_cast<size_t>(end - p));
      if (!newline) break;
      p = static_cast<const char*>(newline) + 1;
    }
    return count;
  }

 private:
  // A CR counts as a space, unless more of the line follows it: then it is a line end without
  // its LF (old Mac files, or a mix), and the file is refused rather than read as one long line.
  // `rest` starts at the CR and runs to the end of the text.
  void checkAfterCr(std::string_view rest, int column) const {
    const size_t lineEnd = std::min(rest.find('\n'), rest.size());
    if (rest.substr(0, lineEnd).find_first_not_of(" \t\r") == std::string_view::npos) return;
    throw StageError({file_, number_, column},
                     "a CR (\\r) ends a line here without an LF: lines must end with LF or CR LF (CR-only line ends, "
                     "as old Mac files have, are not read)");
  }

  std::string_view text_;
  std::string file_;
  size_t at_ = 0;
  int number_ = 0;
  std::vector<Token> tokens_;
  TextLine current_;
};

// Face numbers are checked against the level's own face count once its '%' lines are read (a
// mesh level's count is known only then); here only that they are whole numbers.
constexpr int kMostFaces = 2147483647;

class Parser {
 public:
  Parser(std::string_view text, const std::string& file, std::shared_ptr<const TagTable> tags)
      : file_(file), reader_(text, file), tags_(std::move(tags)) {}

  Level parse() {
    Level level;
    level.file = file_;
    level.tags = tags_;
    solidLine(level);
    startLine(level);
    goalLine(level);
    sizeLine(level);
    faces(level);
    level.endLine = reader_.lineCount() + 1;
    const int faceTotal = static_cast<int>(level.faces.size());
    if (level.solid && faceTotal != faceCount(*level.solid))
      fail(level.endLine, 1,
           std::string(solidName(*level.solid)) + " has " + std::to_string(faceCount(*level.solid)) +
               " faces; the file describes " + std::to_string(faceTotal));
    checkFaceIndex(level, level.start, "start", startFaceText_);
    checkFaceIndex(level, level.goal, "goal", goalFaceText_);
    return level;
  }

 private:
  [[noreturn]] void fail(int line, int column, const std::string& reason) const {
    throw StageError({file_, line, column}, reason);
  }
  [[noreturn]] void fail(const TextLine& line, const Token& token, const std::string& reason) const {
    fail(line.number, token.column, reason);
  }

  const TextLine& next(const char* what) {
    const TextLine* line = reader_.next();
    if (!line) fail(reader_.lineCount() + 1, 1, std::string("the file ends before the ") + what);
    return *line;
  }

  // Too few values on the line: at the column past its last value, or, when a value holds a byte
  // that looks like a separator but is not (a vertical tab), at that byte, naming it.
  [[noreturn]] void tooFewValues(const TextLine& line, const std::string& what) const {
    for (const Token& t : line.tokens)
      for (size_t i = 0; i < t.text.size(); ++i)
        if (const char* name = hiddenSeparatorName(t.text[i]))
          fail(line.number, t.column + static_cast<int>(i),
               what + ": too few values: " + "'" + shown(t.text) + "' is one value; it holds " + name +
                   ", which does not separate values (only spaces and tabs do)");
    fail(line.number, line.tokens.back().end(), what + ": too few values");
  }

  void expectCount(const TextLine& line, size_t lo, size_t hi, const char* what) const {
    if (line.tokens.size() < lo) tooFewValues(line, what);
    if (line.tokens.size() > hi)
      fail(line, line.tokens[hi], std::string(what) + ": unexpected " + quoted(line.tokens[hi].text));
  }

  // A plain integer of at most 10 characters (most numbers in a level), read directly; none for
  // anything else.
  static std::optional<double> plainInteger(std::string_view text) {
    if (text.empty() || text.size() > 10) return std::nullopt;
    size_t k = text[0] == '-' || text[0] == '+' ? 1 : 0;
    if (k == text.size()) return std::nullopt;
    int64_t value = 0;
    for (; k < text.size(); ++k) {
      if (text[k] < '0' || text[k] > '9') return std::nullopt;
      value = value * 10 + (text[k] - '0');
    }
    return static_cast<double>(text[0] == '-' ? -value : value);
  }

  // Digits with an optional sign, point and exponent, and nothing else.
  static bool decimalForm(const std::string& s) {
    auto digitsAt = [&](size_t& i) {
      const size_t first = i;
      while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
      return i - first;
    };
    size_t i = 0;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    size_t digits = digitsAt(i);
    if (i < s.size() && s[i] == '.') digits += digitsAt(++i);
    if (digits == 0) return false;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
      ++i;
      if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
      if (digitsAt(i) == 0) return false;
    }
    return i == s.size();
  }

  // A decimal number: digits with an optional sign, point and exponent; nothing else.
  double number(const TextLine& line, const Token& t, double lo, double hi, const char* what) const {
    if (const std::optional<double> v = plainInteger(t.text); v && *v >= lo && *v <= hi) return *v;
    const std::string s(t.text);
    if (!decimalForm(s))
      fail(line, t, std::string(what) + ": '" + shown(s) + "' is not a number" + hiddenSeparatorNote(s));
    const double v = std::strtod(s.c_str(), nullptr);
    if (!(v >= lo && v <= hi))
      fail(line, t,
           std::string(what) + ": " + shown(s) + " is out of range (" + format(lo) + " to " + format(hi) + ")");
    return v;
  }

  static std::string format(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", v);
    return text;
  }

  // Coordinates are whole units; a decimal is rounded to the nearest (halves away from zero).
  int32_t unit(const TextLine& line, const Token& t, const char* what) const {
    // Most coordinates are plain integers: read those without a double.
    const std::string_view text = t.text;
    if (text.size() <= 10) {
      const size_t first = !text.empty() && (text[0] == '-' || text[0] == '+') ? 1 : 0;
      int64_t value = 0;
      size_t k = first;
      for (unsigned digit; k < text.size() && (digit = static_cast<unsigned>(text[k] - '0')) < 10; ++k)
        value = value * 10 + digit;
      if (k == text.size() && k > first && value <= (1 << 29))
        return static_cast<int32_t>(text[0] == '-' ? -value : value);
    }
    return static_cast<int32_t>(std::lround(number(line, t, -(1 << 29), 1 << 29, what)));
  }

  int integer(const TextLine& line, const Token& t, int lo, int hi, const char* what) const {
    const double v = number(line, t, lo, hi, what);
    if (v != std::floor(v)) fail(line, t, std::string(what) + ": " + shown(t.text) + " is not a whole number");
    return static_cast<int>(v);
  }

  // A face number: any whole number here (kept as -1 below 0 and kMostFaces above it, with its
  // text for the message), checked against the level's faces by checkFaceIndex at the end.
  int faceNumber(const TextLine& line, const Token& t, const char* what, std::string& text) const {
    const double v = number(line, t, -INFINITY, INFINITY, what);
    if (v != std::floor(v)) fail(line, t, std::string(what) + ": " + shown(t.text) + " is not a whole number");
    text = shown(t.text);
    return v < 0 ? -1 : v > kMostFaces ? kMostFaces : static_cast<int>(v);
  }

  void solidLine(Level& level) {
    const TextLine& line = next("solid (the first line)");
    const Token& first = line.tokens[0];
    if (first.text == "MESH") {
      if (line.tokens.size() < 2) fail(line.number, first.end(), "MESH needs a file name");
      const Token& name = line.tokens[1];
      expectCount(line, 2, 2, "MESH");
      const std::string path(name.text);
      if (path.front() == '/' || path.find("..") != std::string::npos || path.find('\\') != std::string::npos)
        fail(line, name, "the mesh file must be a path inside the level's folder (no '/' at the start, no '..')");
      for (const char c : path)
        if (static_cast<unsigned char>(c) < 0x20) fail(line, name, "the mesh file name has a control character");
      level.mesh = path;
      level.meshLine = line.number, level.meshColumn = name.column;
      return;
    }
    expectCount(line, 1, 1, "solid");
    level.solid = solidFromName(first.text);
    if (!level.solid)
      fail(line, first,
           "unknown solid " + quoted(first.text) +
               " (known: TETRAHEDRON, HEXAHEDRON, OCTAHEDRON, DODECAHEDRON, ICOSAHEDRON, or MESH file)");
  }

  void startLine(Level& level) {
    const TextLine& line = next("start line (face x y [degrees])");
    expectCount(line, 3, 4, "start (face x y [degrees])");
    level.start = {faceNumber(line, line.tokens[0], "start face", startFaceText_),
                   {unit(line, line.tokens[1], "start x"), unit(line, line.tokens[2], "start y")},
                   line.number,
                   line.tokens[0].column};
    if (line.tokens.size() == 4)
      level.startMillidegrees =
          std::llround(number(line, line.tokens[3], -360, 360, "start rotation (degrees)") * 1000);
  }

  void goalLine(Level& level) {
    const TextLine& line = next("goal line ([face] x y)");
    expectCount(line, 2, 3, "goal ([face] x y)");
    const size_t base = line.tokens.size() - 2;
    goalFaceText_ = startFaceText_;
    const int face = base ? faceNumber(line, line.tokens[0], "goal face", goalFaceText_) : level.start.face;
    level.goal = {face,
                  {unit(line, line.tokens[base], "goal x"), unit(line, line.tokens[base + 1], "goal y")},
                  line.number,
                  line.tokens[0].column};
  }

  void sizeLine(Level& level) {
    const TextLine& line = next("face size line");
    expectCount(line, 1, 1, "face size");
    level.size = integer(line, line.tokens[0], 64, 1 << 24, "face size (units)");
  }

  // Refuses the segment at line:column when its face or the level holds as many as they may.
  void countSegment(const Level& level, size_t& total, int line, int column) const {
    if (level.faces.back().lines.size() >= kMaxFaceSegments)
      fail(line, column,
           "face " + std::to_string(level.faces.size() - 1) + " has " + std::to_string(kMaxFaceSegments) +
               " segments already, the most a face may have");
    if (++total > kMaxLevelSegments)
      fail(line, column,
           "the level has " + std::to_string(kMaxLevelSegments) + " segments already, the most a level may have");
  }

  void faces(Level& level) {
    size_t total = 0;
    for (;;) {
      std::array<int32_t, 4> v;
      LevelLine plain;
      if (!level.faces.empty() && reader_.plainSegment(v, plain.sourceLine, plain.sourceColumn, plain.endColumn)) {
        plain.a = {v[0], v[1]};
        plain.b = {v[2], v[3]};
        if (plain.a == plain.b)
          fail(plain.sourceLine, plain.sourceColumn, "the segment has no length (both ends at one point)");
        countSegment(level, total, plain.sourceLine, plain.sourceColumn);
        level.faces.back().lines.push_back(plain);
        continue;
      }
      const TextLine* next = reader_.next();
      if (!next) break;
      const TextLine& line = *next;
      if (line.tokens[0].text == "%") {
        if (level.faces.size() >= kMaxLevelFaces)
          fail(line, line.tokens[0],
               "this '%' starts face " + std::to_string(level.faces.size()) + "; a level has at most " +
                   std::to_string(kMaxLevelFaces) + " faces (a mesh's most)");
        if (level.solid && static_cast<int>(level.faces.size()) == faceCount(*level.solid))
          fail(line, line.tokens[0],
               std::string(solidName(*level.solid)) + " has " + std::to_string(faceCount(*level.solid)) +
                   " faces; this '%' starts one more");
        level.faces.push_back(faceOptions(line));
        level.faces.back().lines.reserve(std::min(reader_.linesBeforeNextFace(), kMaxFaceSegments));
        continue;
      }
      if (level.faces.empty())
        fail(line, line.tokens[0], "expected '%', which starts face 0 (after the four header lines)");
      countSegment(level, total, line.number, line.tokens[0].column);
      level.faces.back().lines.push_back(segment(line));
    }
  }

  LevelFace faceOptions(const TextLine& line) const {
    LevelFace face;
    face.sourceLine = line.number;
    for (size_t i = 1; i < line.tokens.size();) {
      const Token& t = line.tokens[i];
      const bool numeric = !t.text.empty() && std::strchr("0123456789+-.", t.text[0]) != nullptr;
      if (numeric && i > 1)
        fail(line, t, "one value too many: gravity takes two numbers, gx gy (units per frame per frame)");
      if (t.text != "gravity") fail(line, t, "unknown face option " + quoted(t.text) + " (known: gravity gx gy)");
      if (face.gravityQ16) fail(line, t, "gravity given twice");
      if (i + 2 >= line.tokens.size()) fail(line, t, "gravity needs two numbers: gx gy (units per frame per frame)");
      const double gx = number(line, line.tokens[i + 1], -16384, 16384, "gravity x");
      const double gy = number(line, line.tokens[i + 2], -16384, 16384, "gravity y");
      face.gravityQ16 = physics::Vec2w{std::llround(gx * 65536), std::llround(gy * 65536)};
      if ((gx != 0 || gy != 0) && face.gravityQ16->x == 0 && face.gravityQ16->y == 0)
        fail(line, t,
             "gravity " + shown(line.tokens[i + 1].text) + " " + shown(line.tokens[i + 2].text) +
                 " rounds to none: gravity is kept in steps of 1/65536 unit per frame per frame (write 0 0 for "
                 "none)");
      i += 3;
    }
    return face;
  }

  LevelLine segment(const TextLine& line) const {
    if (line.tokens.size() < 4) tooFewValues(line, "a segment is x0 y0 x1 y1 [oneway] [tag]");
    LevelLine out;
    out.sourceLine = line.number;
    out.sourceColumn = line.tokens[0].column;
    out.endColumn = line.tokens[2].column;
    out.a = {unit(line, line.tokens[0], "x0"), unit(line, line.tokens[1], "y0")};
    out.b = {unit(line, line.tokens[2], "x1"), unit(line, line.tokens[3], "y1")};
    if (out.a == out.b) fail(line, line.tokens[0], "the segment has no length (both ends at one point)");
    bool tagged = false;
    for (size_t i = 4; i < line.tokens.size(); ++i) {
      const Token& t = line.tokens[i];
      auto setTag = [&](uint32_t tag) {
        if (tagged) fail(line, t, "a segment has one tag at most");
        tagged = true;
        out.tag = tag;
      };
      auto numbered = [&](const char* what, int lo, int hi) {
        if (i + 1 >= line.tokens.size()) fail(line, t, std::string(what) + " needs a number");
        return static_cast<uint32_t>(integer(line, line.tokens[++i], lo, hi, what));
      };
      if (t.text == "oneway") {
        if (out.oneWay) fail(line, t, "oneway given twice");
        out.oneWay = true;
      } else if (t.text == "tag") {
        setTag(numbered("tag", 0, 2147483647));
      } else if (const TagKind* kind = tags_->find(t.text)) {
        if (kind->count == 0) {
          setTag(kind->number);
        } else {
          const std::string what(t.text);
          setTag(kind->number + numbered(what.c_str(), 1, static_cast<int>(kind->count)));
        }
      } else {
        fail(line, t, "unknown segment word " + quoted(t.text) + " (known: oneway, " + tags_->words() + ", tag N)");
      }
    }
    return out;
  }

  void checkFaceIndex(const Level& level, const LevelPoint& p, const char* what, const std::string& text) const {
    const bool known = !level.faces.empty();
    if (p.face >= 0 && (!known || p.face < static_cast<int>(level.faces.size()))) return;
    fail(p.sourceLine, p.sourceColumn,
         std::string(what) + " face " + text + " does not exist (" +
             (known ? "faces 0 to " + std::to_string(level.faces.size() - 1)
                    : std::string("faces are numbered from 0")) +
             ")");
  }

  std::string file_;
  LineReader reader_;
  std::shared_ptr<const TagTable> tags_;
  std::string startFaceText_, goalFaceText_;  // the face numbers as written, for checkFaceIndex
};

}  // namespace

Level parseLevel(std::string_view text, const std::string& file, std::shared_ptr<const TagTable> tags) {
  if (!tags) tags = gameTags();
  return Parser(text, file, std::move(tags)).parse();
}

}  // namespace platon::stage
