#include "platon/editor/level_document.h"

#include <stdexcept>

#include "platon/files/write_file.h"

namespace platon::editor {

LevelDocument::LevelDocument(std::string path, std::string text, std::shared_ptr<const stage::TagTable> tags)
    : path_(std::move(path)), text_(std::move(text)), saved_(text_), tags_(std::move(tags)) {
  level_ = stage::parseLevel(text_, path_, tags_);
}

void LevelDocument::setText(std::string text) {
  level_ = stage::parseLevel(text, path_, tags_);
  text_ = std::move(text);
}

std::string levelDifference(const stage::Level& a, const stage::Level& b) {
  if (a.solid != b.solid || a.mesh != b.mesh) return "the solid";
  if (!(a.start == b.start) || a.startMillidegrees != b.startMillidegrees) return "the start";
  if (!(a.goal == b.goal)) return "the goal";
  if (a.size != b.size) return "the size";
  if (a.faces.size() != b.faces.size()) return "the number of faces";
  for (size_t f = 0; f < a.faces.size(); ++f) {
    if (a.faces[f].gravityQ16 != b.faces[f].gravityQ16) return "face " + std::to_string(f) + "'s gravity";
    if (a.faces[f].lines.size() != b.faces[f].lines.size())
      return "face " + std::to_string(f) + "'s number of segments";
    for (size_t i = 0; i < a.faces[f].lines.size(); ++i)
      if (!(a.faces[f].lines[i] == b.faces[f].lines[i]))
        return "segment " + std::to_string(i) + " of face " + std::to_string(f);
  }
  return "";
}

bool LevelDocument::edit(const std::string& name, const std::function<void(stage::Level&)>& change) {
  stage::Level next = level_;
  change(next);
  if (next == level_) return false;
  std::string text = stage::writeLevel(next, text_);
  stage::Level read = stage::parseLevel(text, path_, tags_);  // throws for a value out of range
  // The written text must read back as the edit, in the same order: what the editor shows is what
  // the file says (a mismatch is the writer's bug; refused rather than saved).
  if (const std::string diff = levelDifference(read, next); !diff.empty())
    throw stage::StageError({path_, 0, 0}, "the edit does not read back as made (" + diff + "): not made");
  undoBytes_ += text_.size();
  undo_.push_back({name, std::move(text_)});
  while (undoBytes_ > kMaxUndoBytes && undo_.size() > 1) {  // the oldest steps go first
    undoBytes_ -= undo_.front().text.size();
    undo_.pop_front();
  }
  redo_.clear();
  text_ = std::move(text);
  level_ = std::move(read);
  return true;
}

bool LevelDocument::undo() {
  if (undo_.empty()) return false;
  Step step = std::move(undo_.back());
  undo_.pop_back();
  undoBytes_ -= step.text.size();
  redo_.push_back({step.name, text_});
  setText(std::move(step.text));
  return true;
}

bool LevelDocument::redo() {
  if (redo_.empty()) return false;
  Step step = std::move(redo_.back());
  redo_.pop_back();
  undoBytes_ += text_.size();
  undo_.push_back({step.name, text_});
  setText(std::move(step.text));
  return true;
}

void LevelDocument::save() {
  if (const std::string why = files::saveWhole(path_, text_, "the level"); !why.empty()) throw std::runtime_error(why);
  saved_ = text_;
}

}  // namespace platon::editor
