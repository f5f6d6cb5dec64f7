#include "settings.h"

#include <algorithm>
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

const char* const kKeyNames[core::KeyBindings::kBound] = {"keys_left", "keys_right", "keys_up",
                                                          "keys_down", "keys_jump",  "keys_restart"};
const char* const kPadNames[core::KeyBindings::kBound] = {"pad_left", "pad_right", "pad_up",
                                                          "pad_down", "pad_jump",  "pad_restart"};

// "Left, A, Keypad 4" -> its names, trimmed; nothing for an empty one.
std::vector<std::string> names(const std::string& list) {
  std::vector<std::string> out;
  std::istringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    const size_t a = name.find_first_not_of(" \t\r"), b = name.find_last_not_of(" \t\r");
    if (a != std::string::npos) out.push_back(name.substr(a, b + 1 - a));
  }
  return out;
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
    const auto key = std::find(std::begin(kKeyNames), std::end(kKeyNames), name);
    const auto pad = std::find(std::begin(kPadNames), std::end(kPadNames), name);
    if (key != std::end(kKeyNames) || pad != std::end(kPadNames)) {
      const size_t start = line.find(name) + name.size();
      const std::vector<std::string> bound = names(line.substr(start, line.find('#') - start));
      if (bound.empty())
        problems.push_back(at + "'" + line + "': " + name +
                           (pad != std::end(kPadNames) ? " names one button or more (a, dpleft)"
                                                       : " names one key or more (Left, A)") +
                           "; its default is used");
      else if (key != std::end(kKeyNames))
        s.keys.keys[key - std::begin(kKeyNames)] = bound;
      else
        s.keys.pad[pad - std::begin(kPadNames)] = bound;
      continue;
    }
    if ((name == "fullscreen" || name == "vsync") && more.empty() && (value == "on" || value == "off")) {
      (name == "fullscreen" ? s.fullscreen : s.vsync) = value == "on";
      continue;
    }
    if (name == "multisampling" && more.empty() &&
        (value == "auto" || value == "0" || value == "2" || value == "4" || value == "8")) {
      s.multisamples = value == "auto" ? -1 : std::stoi(value);
      continue;
    }
    if (name == "game_speed" && more.empty() && wholeIn(value, 50, 100, volume)) {
      s.gameSpeed = volume;
      continue;
    }
    if ((name == "music_volume" || name == "effects_volume") && more.empty() && wholeIn(value, 0, 100, volume)) {
      (name == "music_volume" ? s.musicVolume : s.effectsVolume) = volume;
    } else if (name == "screen_shake" && more.empty() && (value == "on" || value == "off")) {
      s.screenShake = value == "on";
    } else if (name == "music_volume" || name == "effects_volume" || name == "screen_shake" || name == "fullscreen" ||
               name == "vsync" || name == "game_speed" || name == "multisampling") {
      problems.push_back(at + "'" + line + "': " + name +
                         (name == "game_speed"                                 ? " is a whole number 50..100"
                          : name == "music_volume" || name == "effects_volume" ? " is a whole number 0..100"
                                                                               : " is on or off") +
                         "; its default is used");
    } else {
      problems.push_back(at + "unknown setting '" + name +
                         "' (known: music_volume, effects_volume, screen_shake, fullscreen, vsync, game_speed, "
                         "keys_left ... keys_restart, pad_left ... pad_restart); the line is ignored");
    }
  }
  return s;
}

std::string Settings::text() const {
  std::string text = "# Platon settings (the game writes this file; a line it cannot read keeps its default)\n";
  text += "music_volume " + std::to_string(musicVolume) + "\n";
  text += "effects_volume " + std::to_string(effectsVolume) + "\n";
  text += std::string("screen_shake ") + (screenShake ? "on" : "off") + "\n";
  text += std::string("fullscreen ") + (fullscreen ? "on" : "off") + "\n";
  text += std::string("vsync ") + (vsync ? "on" : "off") + "\n";
  text += "game_speed " + std::to_string(gameSpeed) + "\n";
  text += "multisampling " + (multisamples < 0 ? std::string("auto") : std::to_string(multisamples)) + "\n";
  for (int b = 0; b < core::KeyBindings::kBound; ++b) {
    text += kKeyNames[b];
    for (size_t i = 0; i < keys.keys[b].size(); ++i) text += (i ? ", " : " ") + keys.keys[b][i];
    text += "\n";
  }
  for (int b = 0; b < core::KeyBindings::kBound; ++b) {
    text += kPadNames[b];
    for (size_t i = 0; i < keys.pad[b].size(); ++i) text += (i ? ", " : " ") + keys.pad[b][i];
    text += "\n";
  }
  return text;
}

std::string Settings::save(const std::string& path) const { return saveWhole(path, text(), "the settings file"); }

}  // namespace platon::app
