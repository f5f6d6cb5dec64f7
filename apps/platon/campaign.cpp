#include "campaign.h"

#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace platon::app {
namespace {

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") + 1 - a);
}

bool isFile(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

// mkdir -p, for the data folder.
void makeFolders(const std::string& path) {
  for (size_t i = 1; i <= path.size(); ++i)
    if (i == path.size() || path[i] == '/') mkdir(path.substr(0, i).c_str(), 0755);
}

}  // namespace

std::vector<CampaignLevel> readCampaign(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the campaign");
  const size_t slash = path.find_last_of('/');
  const std::string base = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  std::vector<CampaignLevel> levels;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string folder = trim(line.substr(0, line.find('#')));
    if (folder.empty()) continue;
    const std::string scene = base + folder + "/scene.lua";
    if (!isFile(scene))
      throw std::runtime_error(path + ":" + std::to_string(number) + ":1: level '" + folder + "' has no " + scene);
    levels.push_back({folder, scene});
  }
  if (levels.empty()) throw std::runtime_error(path + ": the campaign names no level");
  return levels;
}

std::string Progress::defaultPath() {
  const char* data = std::getenv("XDG_DATA_HOME");
  if (data && data[0] == '/') return std::string(data) + "/platon/progress.txt";
  const char* home = std::getenv("HOME");
  return std::string(home && home[0] ? home : ".") + "/.local/share/platon/progress.txt";
}

Progress::Progress(std::string path) : path_(std::move(path)) {
  std::ifstream in(path_);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string folder;
    LevelRecord r;
    if (fields >> folder >> r.bestFrames >> r.fewestDeaths && r.fewestDeaths >= 0 && folder[0] != '#') records_[folder] = r;
  }
}

const LevelRecord* Progress::record(const std::string& folder) const {
  const auto it = records_.find(folder);
  return it == records_.end() ? nullptr : &it->second;
}

bool Progress::finish(const std::string& folder, uint64_t frames, int deaths) {
  auto [it, added] = records_.try_emplace(folder, LevelRecord{frames, deaths});
  if (!added) {
    it->second.bestFrames = std::min(it->second.bestFrames, frames);
    it->second.fewestDeaths = std::min(it->second.fewestDeaths, deaths);
  }
  const size_t slash = path_.find_last_of('/');
  if (slash != std::string::npos) makeFolders(path_.substr(0, slash));
  const std::string temporary = path_ + ".new";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << "# Platon progress: level, best time in frames (60 a second), fewest deaths\n";
    for (const auto& [name, r] : records_) out << name << " " << r.bestFrames << " " << r.fewestDeaths << "\n";
    out.flush();
    if (!out) {
      lastError_ = temporary + ": cannot write the progress file";
      std::remove(temporary.c_str());
      return false;
    }
  }
  if (std::rename(temporary.c_str(), path_.c_str()) != 0) {
    lastError_ = path_ + ": cannot replace the progress file";
    return false;
  }
  lastError_.clear();
  return true;
}

}  // namespace platon::app
