#include "settings.h"

#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "platon/files/read_file.h"
#include "save_file.h"

namespace platon::app {
namespace {

// A whole number within [low, high], or nothing.
bool wholeIn(const std::string& word, int low, int high, int& out) {
  if (word.empty() || word.size() > 4 || word.find_first_not_of("0123456789") != std::string::npos) return false;
  out = std::stoi(word);
  return out >= low && out <= high;
}

}  // namespace

std::string Settings::defaultPath() {
  const char* config = std::getenv("XDG_CONFIG_HOME");
  if (config && config[0] == '/') return std::string(config) + "/platon/settings.txt";
  const char* home = std::getenv("HOME");
  return std::string(home && home[0] ? home : ".") + "/.config/platon/settings.txt";
}

Settings Settings::load(const std::string& path, std::vector<std::string>& problems) {
  Settings s;
  std::error_code error;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, error))) return s;  // none saved yet
  std::string text;
  try {
    text = files::readBoundedFile(path, size_t{1} << 16);
  } catch (const files::FileError& e) {
    problems.push_back(path + ": " + e.reason() + "; the default settings are used");
    return s;
  }
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string name, value, more;
    words >> name >> value >> more;
    if (name.empty()) continue;
    const std::string at = path + ":" + std::to_string(number) + ": ";
    int volume = 0;
    if ((name == "music_volume" || name == "effects_volume") && more.empty() && wholeIn(value, 0, 100, volume)) {
      (name == "music_volume" ? s.musicVolume : s.effectsVolume) = volume;
    } else if (name == "screen_shake" && more.empty() && (value == "on" || value == "off")) {
      s.screenShake = value == "on";
    } else if (name == "music_volume" || name == "effects_volume" || name == "screen_shake") {
      problems.push_back(at + "'" + line + "': " + name +
                         (name == "screen_shake" ? " is on or off" : " is a whole number 0..100") +
                         "; its default is used");
    } else {
      problems.push_back(at + "unknown setting '" + name +
                         "' (known: music_volume, effects_volume, screen_shake); the line is ignored");
    }
  }
  return s;
}

std::string Settings::text() const {
  return "# Platon settings (the game writes this file; a line it cannot read keeps its default)\n"
         "music_volume " +
         std::to_string(musicVolume) + "\n" + "effects_volume " + std::to_string(effectsVolume) + "\n" +
         "screen_shake " + (screenShake ? "on" : "off") + "\n";
}

std::string Settings::save(const std::string& path) const { return saveWhole(path, text(), "the settings file"); }

}  // namespace platon::app
