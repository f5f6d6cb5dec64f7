// Line tags: the one table of the words a level file may write after a segment. Each kind has a
// word, a number (the tag the physics carries and the rules read), whether the player passes it,
// and its look. The table drives the level reader and writer, the "known words" message, the level
// checks, the net picture, the renderer's colours and the Lua side (platon.tags). The game's kinds
// are gameTags(); a scene's mods add their own to a copy (docs/scripting.md, "Tags").
#pragma once
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace platon::stage {

// Whether the player passes a line of the kind: a wall; a trigger it passes through (a goal, a
// switch); or a door the rules open and shut while playing (the level checks count it as open
// where they ask "can the goal be reached", as shut where they ask "is there room").
enum class Passage : uint8_t { Wall, Through, Door };

struct TagStyle {
  uint8_t r = 232, g = 226, b = 214;  // pale stone
  bool glow = false;                  // drawn unlit, bright: what the player must notice
  bool spikes = false;                // a row of spikes along its top: what kills
};

struct TagKind {
  std::string word;
  uint32_t number = 0;  // the tag; for a numbered kind the base, and "word n" is number + n
  uint32_t count = 0;   // 0: the word stands alone; n > 0: it takes a number 1..n
  Passage passage = Passage::Wall;
  TagStyle style = {};
  std::string owner = {};  // who declared it: "the game", or a mod's file (for messages)

  bool holds(uint32_t tag) const { return count == 0 ? tag == number : tag > number && tag - number <= count; }
};

// Thrown by TagTable::add for a kind that cannot be added (its reason says why).
class TagError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class TagTable {
 public:
  // Adds a kind. Throws TagError for a word that is no word (letters, digits and _, a letter
  // first, at most 32), one already taken, "oneway" or "tag" (the level format's own words), or
  // numbers that overlap another kind's.
  void add(TagKind kind);

  const TagKind* find(std::string_view word) const;
  // The kind `tag` belongs to, and its n (0 for a word alone); nullptr for a tag of no kind (a
  // level may still write it as "tag N").
  const TagKind* kindOf(uint32_t tag, uint32_t* n = nullptr) const;
  // The number of a word standing alone ("goal"); throws TagError when the table has no such kind.
  uint32_t number(std::string_view word) const;

  Passage passage(uint32_t tag) const;  // a tag of no kind is a wall
  TagStyle style(uint32_t tag) const;   // a tag of no kind looks like stone
  bool playerPasses(uint32_t tag) const { return passage(tag) == Passage::Through; }

  // The words as the level format's "known" list: "solid, hazard, ..., door N, switch N".
  std::string words() const;
  // How a level file writes `tag` after a segment: "" for 0, " hazard", " door 3", " tag 7".
  std::string written(uint32_t tag) const;

  const std::vector<TagKind>& kinds() const { return kinds_; }

 private:
  std::vector<TagKind> kinds_;
  // Lookups in constant or logarithmic time whatever the number of kinds (mods may declare
  // thousands; the physics asks on every contact): by word, and by first number (kinds never overlap).
  std::unordered_map<std::string, size_t> byWord_;
  std::vector<std::pair<uint32_t, size_t>> byNumber_;  // sorted by number
};

// The game's kinds (scripts/rules/game.lua gives them their rules): solid 0, hazard 1, goal 2,
// checkpoint 3, door n 1000 + n, switch n 2000 + n (n in 1..999).
const std::shared_ptr<const TagTable>& gameTags();

// A mod's kinds are numbered from here, kModTagStep apart, in the order they are declared (so a
// numbered kind of theirs has room for 999 numbers).
inline constexpr uint32_t kFirstModTag = 1'000'000, kModTagStep = 1000;

}  // namespace platon::stage
