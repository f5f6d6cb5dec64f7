#include "platon/core/replay.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "platon/core/input.h"

namespace platon::core {
namespace {

constexpr uint64_t kMaxFrames = uint64_t{1} << 26;  // 12 days at 60 Hz: a bound on what a file can allocate

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
        if (line[i] == '#' && words.empty()) break;
        const size_t start = i;
        if (line[i] == '"') {
          const size_t end = line.find('"', i + 1);
          if (end == std::string::npos) fail(static_cast<int>(i) + 1, "unfinished string");
          words.push_back({line.substr(i + 1, end - i - 1), static_cast<int>(start) + 1, true});
          i = end + 1;
          continue;
        }
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
        words.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
      }
      if (!words.empty()) return true;
    }
    return false;
  }

  [[noreturn]] void fail(int column, const std::string& reason) const {
    throw std::runtime_error(file_ + ":" + std::to_string(line_) + ":" + std::to_string(column) + ": " + reason);
  }
  [[noreturn]] void failAtEnd(const std::string& reason) const { fail(1, reason + " (at the end of the file)"); }

  uint64_t number(const Word& w, uint64_t max, const char* what) const {
    if (w.text.empty() || w.text.size() > 20 || w.text.find_first_not_of("0123456789") != std::string::npos)
      fail(w.column, std::string(what) + ": expected a whole number, got '" + w.text + "'");
    const uint64_t v = std::stoull(w.text);
    if (v > max) fail(w.column, std::string(what) + " " + w.text + " is more than " + std::to_string(max));
    return v;
  }

  void expect(const std::vector<Word>& words, const char* keyword, size_t count, const char* usage) const {
    if (words[0].text != keyword) fail(words[0].column, "expected '" + std::string(usage) + "', got '" + words[0].text + "'");
    if (words.size() != count) fail(words[std::min(words.size(), count) - 1].column, std::string("expected '") + usage + "'");
  }

 private:
  std::istringstream in_;
  std::string file_;
  int line_ = 0;
};

}  // namespace

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
    if (!in.next(w)) in.failAtEnd("missing '" + std::string(what) + "'");
  };
  Replay r;
  line("platon replay 1");
  if (w.size() != 3 || w[0].text != "platon" || w[1].text != "replay")
    in.fail(w[0].column, "not a replay: the first line is 'platon replay 1'");
  if (w[2].text != "1") in.fail(w[2].column, "replay version " + w[2].text + " is not supported (this engine reads 1)");
  line("scene \"path\"");
  in.expect(w, "scene", 2, "scene \"path\"");
  r.scene = w[1].text;
  if (!w[1].quoted) in.fail(w[1].column, "the scene path is written in double quotes");
  if (r.scene.empty()) in.fail(w[1].column, "empty scene path");
  if (hasParentStep(r.scene))
    in.fail(w[1].column, "'" + r.scene + "': a replay's scene path may not contain '..' (replays are shared: it names the scene's own path)");
  line("frames N");
  in.expect(w, "frames", 2, "frames N");
  const uint64_t frames = in.number(w[1], kMaxFrames, "frames");
  line("hash_every N");
  in.expect(w, "hash_every", 2, "hash_every N");
  r.hashEvery = in.number(w[1], kMaxFrames, "hash_every");
  line("input");
  in.expect(w, "input", 1, "input");
  r.held.reserve(frames);
  for (;;) {
    line("end");
    if (w[0].text == "end" && w.size() == 1) break;
    const uint64_t count = in.number(w[0], kMaxFrames, "frame count");
    if (count == 0) in.fail(w[0].column, "a run of 0 frames");
    if (w.size() < 2) in.fail(w[0].column, "expected 'count buttons...' ('-' for none)");
    uint8_t held = 0;
    for (size_t i = 1; i < w.size(); ++i) {
      if (w[i].text == "-" && w.size() == 2) continue;
      Button b{};
      if (!buttonFromName(w[i].text, b))
        in.fail(w[i].column, "unknown button '" + w[i].text + "' (left, right, up, down, jump, restart, pause, reload, or - for none)");
      held |= InputFrame::bit(b);
    }
    if (r.held.size() + count > frames)
      in.fail(w[0].column, "the input runs past frame " + std::to_string(frames) + " given by 'frames'");
    r.held.insert(r.held.end(), count, held);
  }
  if (r.held.size() != frames)
    in.fail(w[0].column, "the input covers " + std::to_string(r.held.size()) + " frames, 'frames' says " + std::to_string(frames));
  while (in.next(w)) {
    in.expect(w, "hash", 3, "hash FRAME HEX16");
    const uint64_t frame = in.number(w[1], frames, "hash frame");
    if (!r.hashes.empty() && frame <= r.hashes.back().frame) in.fail(w[1].column, "hash frames must increase");
    if (w[2].text.size() != 16 || w[2].text.find_first_not_of("0123456789abcdef") != std::string::npos)
      in.fail(w[2].column, "a hash is 16 lower-case hex digits");
    r.hashes.push_back({frame, std::stoull(w[2].text, nullptr, 16)});
  }
  return r;
}

Replay readReplay(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(path + ": cannot open the replay");
  std::ostringstream text;
  text << file.rdbuf();
  return parseReplay(text.str(), path);
}

std::string formatReplay(const Replay& r) {
  std::string out = "platon replay 1\nscene \"" + r.scene + "\"\nframes " + std::to_string(r.frames()) +
                    "\nhash_every " + std::to_string(r.hashEvery) + "\ninput\n";
  for (size_t i = 0; i < r.held.size();) {
    size_t j = i;
    while (j < r.held.size() && r.held[j] == r.held[i]) ++j;
    out += std::to_string(j - i);
    if (r.held[i] == 0) out += " -";
    for (int b = 0; b < kButtonCount; ++b)
      if (r.held[i] >> b & 1) (out += ' ') += buttonName(static_cast<Button>(b));
    out += '\n';
    i = j;
  }
  out += "end\n";
  for (const ReplayHash& h : r.hashes) {
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h.hash));
    out += "hash " + std::to_string(h.frame) + " " + hex + "\n";
  }
  return out;
}

void writeReplay(const Replay& replay, const std::string& path) {
  if (replay.scene.find('"') != std::string::npos) throw std::runtime_error(path + ": a scene path with '\"' cannot be written");
  const std::string temporary = path + ".partial";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file << formatReplay(replay);
    if (!file.flush()) throw std::runtime_error(temporary + ": cannot write the replay");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) throw std::runtime_error(path + ": cannot write the replay");
}

ReplayRecorder::ReplayRecorder(std::string scene, uint64_t hashEvery) {
  replay_.scene = std::move(scene);
  replay_.hashEvery = hashEvery;
}

void ReplayRecorder::frame(uint8_t held, uint64_t stateHashAfter) {
  replay_.held.push_back(held);
  lastHash_ = stateHashAfter;
  const uint64_t f = replay_.held.size();
  if (replay_.hashEvery > 0 && f % replay_.hashEvery == 0) replay_.hashes.push_back({f, stateHashAfter});
}

Replay ReplayRecorder::replay() const {
  Replay r = replay_;
  if (r.frames() > 0 && (r.hashes.empty() || r.hashes.back().frame != r.frames())) r.hashes.push_back({r.frames(), lastHash_});
  return r;
}

}  // namespace platon::core
