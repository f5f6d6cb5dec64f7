// The tag table and the game's kinds.
#include "platon/stage/tags.h"

#include <algorithm>

namespace platon::stage {
namespace {

bool isWord(std::string_view w) {
  if (w.empty() || w.size() > 32 || !std::isalpha(static_cast<unsigned char>(w[0]))) return false;
  return std::all_of(w.begin(), w.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

uint64_t last(const TagKind& k) { return uint64_t{k.number} + k.count; }

}  // namespace

void TagTable::add(TagKind kind) {
  if (!isWord(kind.word))
    throw TagError("'" + kind.word.substr(0, 40) +
                   "' is no tag word: letters, digits and _, starting with a letter, at most 32");
  if (kind.word == "oneway" || kind.word == "tag")
    throw TagError("'" + kind.word + "' is the level format's own word, not a tag's");
  if (const TagKind* k = find(kind.word)) throw TagError("the tag '" + kind.word + "' is already " + k->owner + "'s");
  if (last(kind) > UINT32_MAX) throw TagError("the tag '" + kind.word + "' runs past the largest tag number");
  // The kinds are disjoint ranges sorted by their first numbers: only the neighbours can overlap.
  const auto next = std::lower_bound(byNumber_.begin(), byNumber_.end(), std::pair<uint32_t, size_t>{kind.number, 0});
  for (auto at : {next, next == byNumber_.begin() ? next : std::prev(next)}) {
    if (at == byNumber_.end()) continue;
    const TagKind& k = kinds_[at->second];
    if (kind.number <= last(k) && k.number <= last(kind))
      throw TagError("the tag '" + kind.word + "' (" + std::to_string(kind.number) + ") overlaps '" + k.word + "' (" +
                     k.owner + "'s)");
  }
  byNumber_.insert(next, {kind.number, kinds_.size()});
  byWord_.emplace(kind.word, kinds_.size());
  kinds_.push_back(std::move(kind));
}

const TagKind* TagTable::find(std::string_view word) const {
  const auto at = byWord_.find(std::string(word));
  return at == byWord_.end() ? nullptr : &kinds_[at->second];
}

const TagKind* TagTable::kindOf(uint32_t tag, uint32_t* n) const {
  // The kind with the greatest first number at most `tag`: the only one that can hold it.
  auto at = std::upper_bound(byNumber_.begin(), byNumber_.end(), std::pair<uint32_t, size_t>{tag, SIZE_MAX});
  if (at == byNumber_.begin()) return nullptr;
  const TagKind& k = kinds_[std::prev(at)->second];
  if (!k.holds(tag)) return nullptr;
  if (n) *n = tag - k.number;
  return &k;
}

uint32_t TagTable::number(std::string_view word) const {
  const TagKind* k = find(word);
  if (!k) throw TagError("no tag '" + std::string(word) + "' in the table");
  return k->number;
}

Passage TagTable::passage(uint32_t tag) const {
  const TagKind* k = kindOf(tag);
  return k ? k->passage : Passage::Wall;
}

TagStyle TagTable::style(uint32_t tag) const {
  const TagKind* k = kindOf(tag);
  return k ? k->style : TagStyle{};
}

std::string TagTable::words() const {
  std::string out;
  for (const TagKind& k : kinds_) out += (out.empty() ? "" : ", ") + k.word + (k.count ? " N" : "");
  return out;
}

std::string TagTable::written(uint32_t tag) const {
  if (tag == 0) return "";
  uint32_t n = 0;
  if (const TagKind* k = kindOf(tag, &n)) return " " + k->word + (k->count ? " " + std::to_string(n) : "");
  return " tag " + std::to_string(tag);
}

const std::shared_ptr<const TagTable>& gameTags() {
  // Colours from Okabe and Ito's palette, for colour-blind players: told apart by lightness as
  // well as hue, and a hazard by its shape too.
  static const std::shared_ptr<const TagTable> table = [] {
    auto t = std::make_shared<TagTable>();
    const std::string game = "the game";
    t->add({"solid", 0, 0, Passage::Wall, {232, 226, 214}, game});
    t->add({"hazard", 1, 0, Passage::Wall, {213, 94, 0, true, true}, game});  // vermillion
    t->add({"goal", 2, 0, Passage::Through, {240, 228, 66, true}, game});     // yellow
    t->add({"checkpoint", 3, 0, Passage::Through, {0, 158, 115}, game});      // bluish green
    t->add({"door", 1000, 999, Passage::Door, {0, 114, 178}, game});          // blue
    t->add({"switch", 2000, 999, Passage::Through, {230, 159, 0}, game});     // orange
    return t;
  }();
  return table;
}

}  // namespace platon::stage
