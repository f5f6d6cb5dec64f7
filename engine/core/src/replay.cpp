#include "platon/core/replay.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "platon/core/input.h"
#include "platon/core/visible_text.h"
#include "platon/files/read_file.h"
#include "platon/files/write_file.h"

namespace platon::core {
namespace {

constexpr uint64_t kMaxFrames = uint64_t{1} << 25;  // 6 days at 60 Hz: a bound on what a file can allocate (64 MB)

struct Word {
  std::string text;
  int column;
  bool quoted = false;
};

class LineReader {
 public:
  LineReader(const std::string& text, const std::string& file) : in_(text), file_(file) {}

  // The next line that is not blank or a comment, split into words; false at the end.
  bool next(std::vector<Word>& words) {
    std::string line;
    while (std::getline(in_, line)) {
      ++line_;
      words.clear();
      for (size_t i = 0; i < line.size();) {
        if (line[i] == ' ' || line[i] == '\t' || line[i] == '\r') {
          ++i;
          continue;
        }
        if (line[i] == '#') break;  // a comment, to the end of the line
        const size_t start = i;
        if (line[i] == '"') {  // \" \\ and \n inside are escapes (a console line's code)
          std::string text;
          size_t j = i + 1;
          for (; j < line.size() && line[j] != '"'; ++j) {
            if (line[j] != '\\') {
              text += line[j];
              continue;
            }
            // Any other backslash is itself (a scene path written before escapes: back\slash).
            if (j + 1 == line.size() || (line[j + 1] != '"' && line[j + 1] != '\\' && line[j + 1] != 'n')) {
              text += '\\';
              continue;
            }
            ++j;
            text += line[j] == 'n' ? '\n' : line[j];
          }
          if (j >= line.size()) fail(static_cast<int>(i) + 1, "unfinished string");
          words.push_back({std::move(text), static_cast<int>(start) + 1, true});
          i = j + 1;
          continue;
        }
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        words.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
      }
      if (!words.empty()) return true;
    }
    return false;
  }

  int line() const { return line_; }
  // "file:line:column" of a column on the current line.
  std::string at(int column) const { return file_ + ":" + std::to_string(line_) + ":" + std::to_string(column); }
  [[noreturn]] void failAt(int line, int column, const std::string& reason) const {
    throw std::runtime_error(file_ + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                             visibleText(reason));
  }
  [[noreturn]] void fail(int column, const std::string& reason) const { failAt(line_, column, reason); }
  // An empty file has no line to name: its line 1 is where the missing text belongs.
  [[noreturn]] void failAtEnd(const std::string& reason) const {
    failAt(std::max(line_, 1), 1, reason + " (at the end of the file)");
  }

  uint64_t number(const Word& w, uint64_t max, const char* what) const {
    if (w.text.empty() || w.text.find_first_not_of("0123456789") != std::string::npos)
      fail(w.column, std::string(what) + ": expected a whole number, got '" + w.text + "'");
    uint64_t v = 0;
    const auto [end, error] = std::from_chars(w.text.data(), w.text.data() + w.text.size(), v);
    if (error == std::errc::result_out_of_range || v > max)  // out of range: more than 2^64 - 1, so more than max
      fail(w.column, std::string(what) + " " + w.text + " is more than " + std::to_string(max));
    return v;
  }

  // A signed whole number within -max..max (a point's coordinate).
  int64_t signedNumber(const Word& w, uint64_t max, const char* what) const {
    const bool negative = !w.text.empty() && w.text[0] == '-';
    const Word magnitude{negative ? w.text.substr(1) : w.text, w.column, w.quoted};
    const auto v = static_cast<int64_t>(number(magnitude, max, what));
    return negative ? -v : v;
  }

  void expect(const std::vector<Word>& words, const char* keyword, size_t count, const char* usage) const {
    if (words[0].text != keyword)
      fail(words[0].column, "expected '" + std::string(usage) + "', got '" + words[0].text + "'");
    if (words.size() != count)
      fail(words[std::min(words.size(), count) - 1].column, std::string("expected '") + usage + "'");
  }

 private:
  std::istringstream in_;
  std::string file_;
  int line_ = 0;
};

bool isHash(const std::string& text) {
  return text.size() == 16 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

// The input section: runs of `count buttons...` up to `end`, `frames` in all.
void readInput(LineReader& in, std::vector<Word>& w, uint64_t frames, Replay& r) {
  r.held.reserve(frames);
  for (;;) {
    if (!in.next(w)) in.failAtEnd("missing 'end'");
    if (w[0].text == "end" && w.size() == 1) break;
    const uint64_t count = in.number(w[0], kMaxFrames, "frame count");
    if (count == 0) in.fail(w[0].column, "a run of 0 frames");
    if (w.size() < 2) in.fail(w[0].column, "expected 'count buttons...' ('-' for none)");
    Buttons held = 0;
    for (size_t i = 1; i < w.size(); ++i) {
      if (w[i].text == "-" && w.size() == 2) continue;
      const std::optional<int> b = r.actions.bitOf(w[i].text, in.at(w[i].column));
      if (!b)
        in.fail(w[i].column, "'" + w[i].text + "' is no action (" + actionList(engineActions()) +
                                 ", an action a mod adds, or - for none)");
      if (held >> *b & 1) in.fail(w[i].column, "'" + w[i].text + "' is given twice");
      held |= static_cast<Buttons>(1u << *b);
    }
    if (r.held.size() + count > frames)
      in.fail(w[0].column, "the input runs past frame " + std::to_string(frames) + " given by 'frames'");
    r.held.insert(r.held.end(), count, held);
  }
  if (r.held.size() != frames)
    in.fail(w[0].column,
            "the input covers " + std::to_string(r.held.size()) + " frames, 'frames' says " + std::to_string(frames));
}

// The frame after `frame` that carries a hash: the next multiple of hashEvery, or the last frame.
uint64_t nextHashFrame(uint64_t frame, uint64_t hashEvery, uint64_t frames) {
  if (hashEvery == 0) return frames;
  return std::min(frames, (frame / hashEvery + 1) * hashEvery);
}

// The hashes: all that hash_every implies, in order, or none.
void readHashes(LineReader& in, std::vector<Word>& w, Replay& r) {
  const uint64_t frames = r.frames();
  auto implies = [&](uint64_t frame) {
    return "hash_every " + std::to_string(r.hashEvery) + " implies a hash at frame " + std::to_string(frame) +
           " (each multiple of hash_every and the last frame): the hashes are all there or none"
           " (hash_every 0: the last frame's only)";
  };
  uint64_t expected = nextHashFrame(0, r.hashEvery, frames);
  while (in.next(w)) {
    if (w[0].text == "console") {  // a line typed in the game's console, run before its frame
      in.expect(w, "console", 3, "console FRAME \"code\"");
      const uint64_t frame = in.number(w[1], frames, "console frame");
      if (frame == 0) in.fail(w[1].column, "console frame 0: a line runs before a frame, counted from 1");
      if (!r.console.empty() && frame < r.console.back().frame) in.fail(w[1].column, "console frames may not decrease");
      if (!w[2].quoted) in.fail(w[2].column, "the console's code is written in double quotes");
      r.console.push_back({frame, w[2].text});
      continue;
    }
    in.expect(w, "hash", 3, "hash FRAME HEX16");
    const uint64_t frame = in.number(w[1], frames, "hash frame");
    if (frame == 0) in.fail(w[1].column, "hash frame 0: frames count from 1 (a hash is the state after its frame)");
    if (!r.hashes.empty() && frame <= r.hashes.back().frame) in.fail(w[1].column, "hash frames must increase");
    if (!isHash(w[2].text)) in.fail(w[2].column, "a hash is 16 lower-case hex digits");
    if (frame != expected)
      in.fail(w[1].column, frame > expected ? implies(expected)
                                            : "hash_every " + std::to_string(r.hashEvery) +
                                                  " implies no hash at frame " + std::to_string(frame));
    r.hashes.push_back({frame, std::stoull(w[2].text, nullptr, 16)});
    expected = frame == frames ? 0 : nextHashFrame(frame, r.hashEvery, frames);
  }
  if (!r.hashes.empty() && expected != 0) in.failAtEnd(implies(expected));
}

}  // namespace

// Whether a path has a ".." step: a replay names its scene's own path, and replays are shared.
bool hasParentStep(const std::string& path) {
  for (size_t start = 0; start <= path.size();) {
    const size_t end = std::min(path.find('/', start), path.size());
    if (path.compare(start, end - start, "..") == 0) return true;
    start = end + 1;
  }
  return false;
}

Replay parseReplay(const std::string& text, const std::string& fileName) {
  LineReader in(text, fileName);
  std::vector<Word> w;
  auto line = [&](const char* what) {
    if (!in.next(w))
      in.failAtEnd(in.line() == 0 ? "an empty file, not a replay: missing 'platon replay 1'"
                                  : "missing '" + std::string(what) + "'");
  };
  Replay r;
  line("platon replay 1");
  if (w.size() != 3 || w[0].text != "platon" || w[1].text != "replay")
    in.fail(w[0].column, text.rfind("\xEF\xBB\xBF", 0) == 0 && in.line() == 1
                             ? "not a replay: the file starts with a byte-order mark (a replay is plain ASCII text)"
                             : "not a replay: the first line is 'platon replay 1'");
  if (w[2].text != "1") in.fail(w[2].column, "replay version " + w[2].text + " is not supported (this engine reads 1)");
  line("scene \"path\"");
  in.expect(w, "scene", 2, "scene \"path\"");
  r.scene = w[1].text;
  r.sceneAt = fileName + ":" + std::to_string(in.line()) + ":" + std::to_string(w[1].column);
  if (!w[1].quoted) in.fail(w[1].column, "the scene path is written in double quotes");
  if (r.scene.empty()) in.fail(w[1].column, "empty scene path");
  if (r.scene[0] == '/')
    in.fail(w[1].column,
            "'" + r.scene +
                "': a replay's scene path is relative, from the replay's folder, the current folder or the game's "
                "data folder "
                "(replays are shared: an absolute path could name any file)");
  if (hasParentStep(r.scene))
    in.fail(w[1].column,
            "'" + r.scene +
                "': a replay's scene path may not contain '..' (replays are shared: it names the scene's own path)");
  line("frames N");
  if (w[0].text == "scene_files") {  // optional
    in.expect(w, "scene_files", 2, "scene_files HEX16");
    if (!isHash(w[1].text)) in.fail(w[1].column, "the scene files' hash is 16 lower-case hex digits");
    r.sceneFiles = std::stoull(w[1].text, nullptr, 16);
    line("frames N");
  }
  if (w[0].text == "speed") {  // optional: the assist mode's game speed
    in.expect(w, "speed", 2, "speed PERCENT");
    const uint64_t speed = in.number(w[1], 100, "speed");
    if (speed < 50) in.fail(w[1].column, "speed: the game runs at 50 to 100 percent, not " + w[1].text);
    r.speed = static_cast<int>(speed);
    line("frames N");
  }
  if (w[0].text == "start") {  // optional: the run starts here, not at the level's start
    in.expect(w, "start", 4, "start FACE X Y");
    r.start = ReplayStart{static_cast<int>(in.number(w[1], 1'000'000, "start face")),
                          static_cast<int32_t>(in.signedNumber(w[2], kMaxStartCoordinate, "start x")),
                          static_cast<int32_t>(in.signedNumber(w[3], kMaxStartCoordinate, "start y"))};
    line("frames N");
  }
  in.expect(w, "frames", 2, "frames N");
  const uint64_t frames = in.number(w[1], kMaxFrames, "frames");
  line("hash_every N");
  in.expect(w, "hash_every", 2, "hash_every N");
  r.hashEvery = in.number(w[1], kMaxFrames, "hash_every");
  line("input");
  in.expect(w, "input", 1, "input");
  readInput(in, w, frames, r);
  readHashes(in, w, r);
  return r;
}

Replay readReplay(const std::string& path) {
  std::string text;
  try {
    text = files::readBoundedFile(path, kMaxReplayBytes);
  } catch (const files::FileError& e) {
    throw std::runtime_error(path + ": the replay: " + e.reason());
  }
  return parseReplay(text, path);
}

namespace {
// A quoted word's text as the reader reads it back: \" \\ and \n escaped.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char ch : text) out += ch == '"' ? "\\\"" : ch == '\\' ? "\\\\" : ch == '\n' ? "\\n" : std::string(1, ch);
  return out;
}

std::string hex16(uint64_t value) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(value));
  return hex;
}
}  // namespace

std::string formatReplay(const Replay& r) {
  std::string out = "platon replay 1\nscene \"" + escaped(r.scene) + "\"\n";
  if (r.sceneFiles) out += "scene_files " + hex16(*r.sceneFiles) + "\n";
  if (r.speed != 100) out += "speed " + std::to_string(r.speed) + "\n";
  if (r.start)
    out += "start " + std::to_string(r.start->face) + " " + std::to_string(r.start->x) + " " +
           std::to_string(r.start->y) + "\n";
  out += "frames " + std::to_string(r.frames()) + "\nhash_every " + std::to_string(r.hashEvery) + "\ninput\n";
  for (size_t i = 0; i < r.held.size();) {
    size_t j = i;
    while (j < r.held.size() && r.held[j] == r.held[i]) ++j;
    out += std::to_string(j - i);
    if (r.held[i] == 0) out += " -";
    for (size_t b = 0; b < r.actions.names.size(); ++b)
      if (r.held[i] >> b & 1) (out += ' ') += r.actions.names[b];
    out += '\n';
    i = j;
  }
  out += "end\n";
  for (const ReplayConsole& c : r.console)
    out += "console " + std::to_string(c.frame) + " \"" + escaped(c.code) + "\"\n";
  for (const ReplayHash& h : r.hashes) out += "hash " + std::to_string(h.frame) + " " + hex16(h.hash) + "\n";
  return out;
}

void writeReplay(const Replay& replay, const std::string& path) {
  if (replay.scene.find_first_of("\"\n\r") != std::string::npos)
    throw std::runtime_error(path + ": a scene path with '\"' or a line break cannot be written");
  const std::string text = formatReplay(replay);
  const std::string why = files::saveWhole(path, text, "the replay");
  if (why.empty()) return;
  files::saveWhole(path + ".partial", text, "the replay");  // the run kept beside it, where it can be
  throw std::runtime_error(why);
}

uint64_t sceneFilesHash(const std::vector<std::string>& files) {
  uint64_t h = 14695981039346656037ull;  // FNV-1a, 64 bits
  auto mix = [&](std::string_view bytes) {
    for (const char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  };
  for (const std::string& file : files) {
    std::string contents;
    try {
      contents = files::readBoundedFile(file, size_t{256} << 20);
    } catch (const files::FileError&) {
      contents = std::string("\0unreadable", 11);
    }
    mix(std::to_string(contents.size()) + ":");  // lengths keep "ab"+"c" apart from "a"+"bc"
    mix(contents);
  }
  return h;
}

ReplayRecorder::ReplayRecorder(std::string scene, uint64_t hashEvery, std::optional<uint64_t> sceneFiles) {
  replay_.scene = std::move(scene);
  replay_.hashEvery = hashEvery;
  replay_.sceneFiles = sceneFiles;
}

void ReplayRecorder::console(const std::string& code) { replay_.console.push_back({replay_.frames() + 1, code}); }

void ReplayRecorder::frame(Buttons held, uint64_t stateHashAfter) {
  replay_.held.push_back(held);
  lastHash_ = stateHashAfter;
  const uint64_t f = replay_.held.size();
  if (replay_.hashEvery > 0 && f % replay_.hashEvery == 0) replay_.hashes.push_back({f, stateHashAfter});
}

Replay ReplayRecorder::replay() const {
  Replay r = replay_;
  // A console line typed after the last frame ran before no frame: it changed nothing recorded.
  while (!r.console.empty() && r.console.back().frame > r.frames()) r.console.pop_back();
  if (r.frames() > 0 && (r.hashes.empty() || r.hashes.back().frame != r.frames()))
    r.hashes.push_back({r.frames(), lastHash_});
  return r;
}

}  // namespace platon::core
