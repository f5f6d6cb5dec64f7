// The campaign (the levels in the order a player meets them, levels/campaign.txt) and the player's
// progress through it, saved in the user's data folder so the level select shows what is done.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace platon::app {

struct CampaignLevel {
  std::string folder;      // as written in the campaign file: "cube_intro"
  std::string scene;       // its manifest: <levels>/<folder>/scene.lua
  uint64_t parFrames = 0;  // the par time, in frames (0: none)
  bool yours = false;      // a level of the player's own (installed), after the campaign: always open
};

// One level a line: its folder, relative to the file's own folder, then optionally its par time
// (M:SS, minutes and seconds); '#' starts a comment. Throws std::runtime_error naming
// file:line:column for a folder with no scene.lua, a par time that is none or anything more on
// the line, and for an empty campaign.
std::vector<CampaignLevel> readCampaign(const std::string& path);

// The player's own levels: each folder of `folder` with a scene.lua (`platon install` puts them
// there), by name, as "yours/<name>" (its progress kept apart from a campaign level of that name).
// None when the folder does not exist.
std::vector<CampaignLevel> userLevels(const std::string& folder);

struct LevelRecord {
  uint64_t bestFrames = 0;  // the fastest finish, in frames
  int fewestDeaths = 0;     // the fewest deaths in a finish
  // Only finished at an assist speed (the game slowed): the level is done, but its time is no
  // par run's. A finish at full speed replaces it.
  bool assisted = false;
};

// Finished levels by folder. The file is plain text, one "folder frames deaths" per line (and
// "assist" after a record of assisted runs only); lines
// it cannot read are skipped (a damaged file costs records, never the game), and it is written
// whole to a new file and renamed over the old, so a crash mid-save never leaves half a file.
class Progress {
 public:
  // Whether `levels[i]` may be played: the first level, a level done, and the level after one done
  // (levels unlock in order).
  bool open(const std::vector<CampaignLevel>& levels, size_t i) const {
    return i == 0 || levels[i].yours || done(levels[i].folder) || done(levels[i - 1].folder);
  }
  // $XDG_DATA_HOME/platon/progress.txt, or ~/.local/share/platon/progress.txt.
  static std::string defaultPath();

  explicit Progress(std::string path);
  bool done(const std::string& folder) const { return records_.count(folder) != 0; }
  const LevelRecord* record(const std::string& folder) const;
  // Keeps the better time and the fewer deaths; saves at once. False (and the reason in
  // lastError()) when the file cannot be written: the game goes on. An `assisted` finish (at a
  // game speed under 100%) opens the next level but counts only where no full-speed one exists.
  bool finish(const std::string& folder, uint64_t frames, int deaths, bool assisted = false);
  const std::string& lastError() const { return lastError_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::map<std::string, LevelRecord> records_;
  std::string lastError_;
};

}  // namespace platon::app
