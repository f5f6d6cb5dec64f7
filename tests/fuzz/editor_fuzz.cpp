// libFuzzer target: the editor's writer (a LevelDocument: each edit written over the level's text
// with stage::writeLevel keeping the lines it did not change, read back) and its save. The input
// is a level's text, then (after a 0 byte) a stream of edits: segments drawn, moved, retagged and
// deleted, the start and goal moved, undo, redo, save. Invariants after every step:
//  - an edit either holds or throws StageError, and a refused edit changes nothing;
//  - the text reads back as the document's level, and writing that level over the text gives the
//    text again (what is saved is what the game reads);
//  - undo then redo gives the text back;
//  - a save writes exactly the text, and never through the links planted in the level's folder
//    under the names a save might use (the file beside the folder is unchanged).
// Anything else (another exception, a crash, a sanitizer report) is a bug.
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <unistd.h>

#include "fuzz_bug.h"
#include "fuzz_bytes.h"
#include "platon/editor/level_document.h"

using namespace platon;
namespace fs = std::filesystem;

namespace {

// A coordinate of a face of `faceSize`: mostly inside it, sometimes far out.
int32_t coordinate(Bytes& in, int32_t faceSize) {
  const uint8_t b = in.next();
  if (b == 255) return (in.next() & 1) ? INT32_MAX : INT32_MIN;
  return static_cast<int32_t>((int64_t{b} << 8 | in.next()) * (faceSize + 64) / 65536) - 32;
}

std::string contents(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void checkDocument(const editor::LevelDocument& d, const std::string& input) {
  const stage::Level read = stage::parseLevel(d.text(), d.path(), d.tags());
  if (const std::string diff = editor::levelDifference(read, d.level()); !diff.empty())
    bug("the text does not read as the document's level: " + diff, input);
  if (stage::writeLevel(d.level(), d.text()) != d.text()) bug("writing the level over its text changes it", input);
}

// One edit of the stream on the document (may throw StageError).
void edit(editor::LevelDocument& d, Bytes& in) {
  const uint8_t op = in.next() % 6;
  const size_t faces = d.level().faces.size();
  if (faces == 0) return;
  const size_t face = in.next() % faces;
  const int32_t size = d.level().size;
  d.edit("fuzz", [&](stage::Level& l) {
    auto& lines = l.faces[face].lines;
    switch (op) {
      case 0: {  // draw
        stage::LevelLine s;
        s.a = {coordinate(in, size), coordinate(in, size)};
        s.b = {coordinate(in, size), coordinate(in, size)};
        s.tag = in.next() % 4 == 0 ? 1 : 0;
        lines.push_back(s);
        break;
      }
      case 1:  // move an end
        if (!lines.empty()) lines[in.next() % lines.size()].b = {coordinate(in, size), coordinate(in, size)};
        break;
      case 2:  // delete
        if (!lines.empty()) lines.erase(lines.begin() + in.next() % lines.size());
        break;
      case 3:  // retag
        if (!lines.empty()) lines[in.next() % lines.size()].tag = in.next() % 8 == 0 ? 2001 : in.next() % 4;
        break;
      case 4:  // the start
        l.start.face = static_cast<int>(face), l.start.position = {coordinate(in, size), coordinate(in, size)};
        break;
      default:  // the goal
        l.goal.face = static_cast<int>(face), l.goal.position = {coordinate(in, size), coordinate(in, size)};
        break;
    }
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const size_t zero = input.find('\0');
  const std::string text = input.substr(0, zero);
  static const fs::path root = fs::temp_directory_path() / ("platon_editor_fuzz_" + std::to_string(getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "level");
  std::ofstream(root / "victim.txt") << "the player's own file\n";
  const fs::path file = root / "level" / "x.level";
  for (const char* suffix : {".new", ".partial", ".tmp", "~"})
    fs::create_symlink(root / "victim.txt", root / "level" / (std::string("x.level") + suffix));
  std::optional<editor::LevelDocument> doc;
  try {
    doc.emplace(file.string(), text, stage::gameTags());
  } catch (const stage::StageError&) {
    fs::remove_all(root);
    return 0;
  }
  checkDocument(*doc, input);
  Bytes in{data, size, zero == std::string::npos ? size : zero + 1};
  for (int steps = 0; in.more() && steps < 64; ++steps) {
    const std::string before = doc->text();
    const uint8_t what = in.next() % 8;
    if (what < 5) {
      try {
        edit(*doc, in);
      } catch (const stage::StageError&) {
        if (doc->text() != before) bug("a refused edit changed the text", input);
      }
    } else if (what == 5) {
      if (doc->undo()) {
        const std::string undone = doc->text();
        if (!doc->redo() || doc->text() != before) bug("undo then redo does not give the text back", input);
        doc->undo();
        if (doc->text() != undone) bug("undo is not repeatable", input);
      }
    } else if (what == 6) {
      doc->redo();
    } else {
      doc->save();
      if (contents(file) != doc->text()) bug("the save did not write the text", input);
      if (contents(root / "victim.txt") != "the player's own file\n") bug("a save wrote through a link", input);
      if (fs::is_symlink(file)) bug("the saved file is a link", input);
    }
    checkDocument(*doc, input);
  }
  fs::remove_all(root);
  return 0;
}
