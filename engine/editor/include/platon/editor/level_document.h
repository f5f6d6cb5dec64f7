// A level being edited: its text, the level that text reads as, and the edits between, each one an
// undo step. Every edit is made on the level's data, written over the current text keeping every
// line it did not change (stage::writeLevel with the original), and read back; so the text is
// always what saving writes, the level is always what the game will read from it, and a segment's
// sourceLine always points at its line (the check's findings find their segment by it).
#pragma once
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "platon/stage/level.h"
#include "platon/stage/stage.h"
#include "platon/stage/tags.h"

namespace platon::editor {

class LevelDocument {
 public:
  // The level's text as read from `path` (stage::readLevelFile), read with the scene's tags. Throws
  // stage::StageError for a text that does not read as a level.
  LevelDocument(std::string path, std::string text, std::shared_ptr<const stage::TagTable> tags);

  const std::string& path() const { return path_; }
  const std::string& text() const { return text_; }
  const stage::Level& level() const { return level_; }
  const std::shared_ptr<const stage::TagTable>& tags() const { return tags_; }
  // Whether the text differs from what was last read or saved.
  bool modified() const { return text_ != saved_; }
  // What the file holds when the text given was completed on reading (a mesh level's missing face
  // lines): the document counts as modified until saved.
  void assumeSaved(std::string onDisk) { saved_ = std::move(onDisk); }

  // Makes one edit, named for the undo list ("draw a segment"): `change` edits a copy of the level;
  // the copy is written and read back. Returns false, changing nothing, when the change did nothing.
  // A change that does not read back as itself (a value out of the format's ranges) is refused:
  // throws stage::StageError, and the document is as it was.
  bool edit(const std::string& name, const std::function<void(stage::Level&)>& change);
  // Undo and redo. The steps kept are the latest, up to kMaxUndoBytes of text in all (each step
  // keeps the whole text before it: a level of 10^4 segments is about 300 KB a step).
  static constexpr size_t kMaxUndoBytes = size_t{64} << 20;
  bool undo();
  bool redo();
  size_t undoSteps() const { return undo_.size(); }
  // The name of the edit undo() or redo() would take back or make again ("" for none).
  std::string undoName() const { return undo_.empty() ? "" : undo_.back().name; }
  std::string redoName() const { return redo_.empty() ? "" : redo_.back().name; }

  // Writes the text to the file (a temporary file renamed over it, so a crash leaves the old one).
  // Throws std::runtime_error naming the file when it cannot.
  void save();

 private:
  struct Step {
    std::string name, text;
  };
  void setText(std::string text);

  std::string path_, text_, saved_;
  std::shared_ptr<const stage::TagTable> tags_;
  stage::Level level_;
  std::deque<Step> undo_;
  std::vector<Step> redo_;
  size_t undoBytes_ = 0;
};

// How far a level's data differ from another's: the first difference in words ("" when equal).
std::string levelDifference(const stage::Level& a, const stage::Level& b);

}  // namespace platon::editor
