#include "campaign.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

#include "platon/files/read_file.h"
#include "save_file.h"

namespace platon::app {
namespace {

bool isFile(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

}  // namespace

std::vector<CampaignLevel> userLevels(const std::string& folder) {
  std::vector<CampaignLevel> out;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.' || !std::filesystem::is_regular_file(entry.path() / "scene.lua", error))
      continue;
    out.push_back({"yours/" + name, (entry.path() / "scene.lua").string(), 0, true});
  }
  std::sort(out.begin(), out.end(), [](const CampaignLevel& a, const CampaignLevel& b) { return a.folder < b.folder; });
  return out;
}

std::vector<CampaignLevel> readCampaign(const std::string& path) {
  std::istringstream in(files::readBoundedFile(path, size_t{1} << 20));
  const size_t slash = path.find_last_of('/');
  const std::string base = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  std::vector<CampaignLevel> levels;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string text = line.substr(0, line.find('#'));
    std::istringstream words(text);
    std::string folder, par, more;
    words >> folder >> par >> more;
    if (folder.empty()) continue;
    // Each word's column, found after the word before it ("ab 0:20 b": b's is 9, not 2).
    const size_t folderAt = text.find(folder), parAt = text.find(par, folderAt + folder.size()),
                 moreAt = text.find(more, parAt + par.size());
    const auto at = [&](const std::string& word) {
      const size_t column = &word == &folder ? folderAt : &word == &par ? parAt : moreAt;
      return path + ":" + std::to_string(number) + ":" + std::to_string(column + 1) + ": ";
    };
    if (!more.empty())
      throw std::runtime_error(at(more) + "'" + more + "': a line is a level's folder and its par time (M:SS)");
    CampaignLevel level{folder, base + folder + "/scene.lua", 0};
    if (!par.empty()) {
      const size_t colon = par.find(':');
      const std::string minutes = par.substr(0, colon),
                        seconds = colon == std::string::npos ? "" : par.substr(colon + 1);
      const auto digits = [](const std::string& w, size_t most) {
        return !w.empty() && w.size() <= most && w.find_first_not_of("0123456789") == std::string::npos;
      };
      if (!digits(minutes, 3) || seconds.size() != 2 || !digits(seconds, 2) || std::stoi(seconds) > 59 ||
          std::stoi(minutes) * 60 + std::stoi(seconds) == 0)
        throw std::runtime_error(at(par) + "'" + par + "': a par time is minutes and seconds, M:SS (0:20), above 0");
      level.parFrames = static_cast<uint64_t>(std::stoi(minutes) * 60 + std::stoi(seconds)) * 60;
    }
    if (!isFile(level.scene)) throw std::runtime_error(at(folder) + "level '" + folder + "' has no " + level.scene);
    levels.push_back(level);
  }
  if (levels.empty()) throw std::runtime_error(path + ": the campaign names no level");
  return levels;
}

std::string Progress::defaultPath() { return userFolder("data") + "/progress.txt"; }

Progress::Progress(std::string path) : path_(std::move(path)) {
  std::istringstream in;
  try {
    in.str(files::readBoundedFile(path_, size_t{16} << 20));
  } catch (const files::FileError&) {
    // No progress yet (or a file that is none: a folder, a FIFO): nothing is done. Saving
    // replaces it, or says why it cannot.
  }
  std::string line;
  auto count = [](const std::string& word, uint64_t limit, uint64_t& out) {  // digits only: no sign, no wrap
    if (word.empty() || word.size() > 18 || word.find_first_not_of("0123456789") != std::string::npos) return false;
    out = std::stoull(word);
    return out <= limit;
  };
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string folder, frames, deaths, assist, extra;
    uint64_t f = 0, d = 0;
    if (!(fields >> folder >> frames >> deaths) || folder[0] == '#') continue;
    if ((fields >> assist) && (assist != "assist" || (fields >> extra))) continue;
    if (!count(frames, uint64_t{1} << 53, f) || !count(deaths, 1u << 30, d)) continue;
    records_[folder] = {f, static_cast<int>(d), assist == "assist"};
  }
}

const LevelRecord* Progress::record(const std::string& folder) const {
  const auto it = records_.find(folder);
  return it == records_.end() ? nullptr : &it->second;
}

bool Progress::finish(const std::string& folder, uint64_t frames, int deaths, bool assisted) {
  auto [it, added] = records_.try_emplace(folder, LevelRecord{frames, deaths, assisted});
  LevelRecord& r = it->second;
  if (!added && r.assisted && !assisted) {
    r = {frames, deaths, false};  // the first full-speed finish: the assisted ones no longer count
  } else if (!added && r.assisted == assisted) {
    r.bestFrames = std::min(r.bestFrames, frames);
    r.fewestDeaths = std::min(r.fewestDeaths, deaths);
  }  // an assisted finish after a full-speed one changes nothing
  std::string text =
      "# Platon progress: level, best time in frames (60 a second), fewest deaths (assist: at an assist speed only)\n";
  for (const auto& [name, rec] : records_)
    text += name + " " + std::to_string(rec.bestFrames) + " " + std::to_string(rec.fewestDeaths) +
            (rec.assisted ? " assist" : "") + "\n";
  lastError_ = saveWhole(path_, text, "the progress file");
  return lastError_.empty();
}

}  // namespace platon::app
