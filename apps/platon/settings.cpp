#include "settings.h"

#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "platon/files/read_file.h"
#include "platon/session/session.h"
#include "save_file.h"

namespace platon::app {
namespace {

// The kinds of value a setting holds: how the file writes it and what it may be.
enum class Kind { Percent, Speed, Samples, Flag };

// One table of the settings the file holds, for reading, writing and the "known" list alike.
struct Field {
  const char* name;
  Kind kind;
  int Settings::*number = nullptr;  // Percent, Speed, Samples
  bool Settings::*flag = nullptr;   // Flag
};
const Field kFields[] = {
    {"music_volume", Kind::Percent, &Settings::musicVolume},
    {"effects_volume", Kind::Percent, &Settings::effectsVolume},
    {"screen_shake", Kind::Flag, nullptr, &Settings::screenShake},
    {"fullscreen", Kind::Flag, nullptr, &Settings::fullscreen},
    {"vsync", Kind::Flag, nullptr, &Settings::vsync},
    {"game_speed", Kind::Speed, &Settings::gameSpeed},
    {"multisampling", Kind::Samples, &Settings::multisamples},
};
// The binding lines: keys_<action> and pad_<action>, SDL's names, commas between.
constexpr std::string_view kKeysPrefix = "keys_", kPadPrefix = "pad_";

// A whole number within [low, high], or nothing.
bool wholeIn(const std::string& word, int low, int high, int& out) {
  if (word.empty() || word.size() > 4 || word.find_first_not_of("0123456789") != std::string::npos) return false;
  out = std::stoi(word);
  return out >= low && out <= high;
}

// Reads `value` as `field` holds it into `s`; false when it is none of the field's values.
bool readField(const Field& field, const std::string& value, Settings& s) {
  int n = 0;
  switch (field.kind) {
    case Kind::Percent:
      if (!wholeIn(value, 0, 100, n)) return false;
      break;
    case Kind::Speed:
      if (!wholeIn(value, 50, 100, n)) return false;
      break;
    case Kind::Samples:
      if (value != "auto" && value != "0" && value != "2" && value != "4" && value != "8") return false;
      n = value == "auto" ? -1 : std::stoi(value);
      break;
    case Kind::Flag:
      if (value != "on" && value != "off") return false;
      s.*field.flag = value == "on";
      return true;
  }
  s.*field.number = n;
  return true;
}

const char* expected(Kind kind) {
  switch (kind) {
    case Kind::Percent:
      return "a whole number 0..100";
    case Kind::Speed:
      return "a whole number 50..100";
    case Kind::Samples:
      return "auto, 0, 2, 4 or 8";
    case Kind::Flag:
      return "on or off";
  }
  return "";
}

std::string written(const Field& field, const Settings& s) {
  if (field.kind == Kind::Flag) return s.*field.flag ? "on" : "off";
  const int n = s.*field.number;
  return field.kind == Kind::Samples && n < 0 ? "auto" : std::to_string(n);
}

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

// The binding a line's name is (keys_jump: the keys of jump; keys_dash: a mod's action's), or
// nullptr; `why` says why a binding line is not one (an action of the engine's no player binds).
std::vector<std::string>* bindingOf(const std::string& name, Settings& s, std::string& why) {
  const bool keys = name.rfind(kKeysPrefix, 0) == 0, pad = name.rfind(kPadPrefix, 0) == 0;
  if (!keys && !pad) return nullptr;
  const std::string action = name.substr((keys ? kKeysPrefix : kPadPrefix).size());
  if (!core::isActionName(action)) return nullptr;
  if (const std::optional<int> i = core::actionIndex(core::engineActions(), action);
      i && !core::engineActions()[static_cast<size_t>(*i)].bindable) {
    why = action + " is not the player's to bind (" + core::engineActions()[static_cast<size_t>(*i)].does + ")";
    return nullptr;
  }
  return keys ? &s.keys.keys[action] : &s.keys.pad[action];
}

// The settings file's list of the bindable actions: keys_left ... keys_restart, pad_left ... pad_restart.
std::string bindingNames() {
  std::string first, last;
  for (const core::Action& a : core::engineActions())
    if (a.bindable) (first.empty() ? first : last) = a.name;
  return "keys_" + first + " ... keys_" + last + ", pad_" + first + " ... pad_" + last + ", or a mod's keys_dash";
}

}  // namespace

std::string Settings::defaultPath() { return userFolder("config") + "/settings.txt"; }

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
    const std::string content = line.substr(0, line.find('#'));
    std::istringstream words(content);
    std::string name, value, more;
    words >> name >> value >> more;
    if (name.empty()) continue;
    const std::string at = path + ":" + std::to_string(number) + ": ";
    std::string why;
    if (std::vector<std::string>* binding = bindingOf(name, s, why)) {
      std::vector<std::string> bound = names(content.substr(content.find(name) + name.size()));
      for (const std::string& key : bound)
        if (name.rfind(kKeysPrefix, 0) == 0 && session::Session::isToolKey(key))
          problems.push_back(at + name + ": " + key + " is a tool's key (F2, F3, F4, F5, F11, F12, `), no action's");
      std::erase_if(bound, [&](const std::string& key) {
        return name.rfind(kKeysPrefix, 0) == 0 && session::Session::isToolKey(key);
      });
      if (bound.empty()) {
        problems.push_back(at + "'" + line + "': " + name +
                           (name.rfind(kPadPrefix, 0) == 0 ? " names one button or more (a, dpleft)"
                                                           : " names one key or more (Left, A)") +
                           "; its default is used");
        (name.rfind(kPadPrefix, 0) == 0 ? s.keys.pad : s.keys.keys).erase(name.substr(name.find('_') + 1));
      } else {
        *binding = bound;
      }
      continue;
    }
    if (!why.empty()) {
      problems.push_back(at + name + ": " + why + "; the line is ignored");
      continue;
    }
    const Field* field = nullptr;
    for (const Field& f : kFields)
      if (name == f.name) field = &f;
    if (!field) {
      std::string known;
      for (const Field& f : kFields) known += std::string(f.name) + ", ";
      problems.push_back(at + "unknown setting '" + name + "' (known: " + known + bindingNames() +
                         "); the line is ignored");
    } else if (!more.empty() || !readField(*field, value, s)) {
      problems.push_back(at + "'" + line + "': " + name + " is " + expected(field->kind) + "; its default is used");
    }
  }
  return s;
}

std::string Settings::text() const {
  std::string text = "# Platon settings (the game writes this file; a line it cannot read keeps its default)\n";
  for (const Field& f : kFields) text += std::string(f.name) + " " + written(f, *this) + "\n";
  // Every action a player binds, with its keys as chosen or by default, then a mod's chosen ones.
  const core::KeyBindings bound = core::bindingsFor(core::engineActions(), keys);
  auto line = [&](std::string_view prefix, const std::string& action, const std::vector<std::string>& names) {
    text += std::string(prefix) + action;
    for (size_t i = 0; i < names.size(); ++i) text += (i ? ", " : " ") + names[i];
    text += "\n";
  };
  for (const bool pad : {false, true}) {
    for (size_t i = 0; i < core::engineActions().size(); ++i)
      if (core::engineActions()[i].bindable)
        line(pad ? kPadPrefix : kKeysPrefix, core::engineActions()[i].name, pad ? bound.pad[i] : bound.keys[i]);
    for (const auto& [action, names] : pad ? keys.pad : keys.keys)
      if (!core::actionIndex(core::engineActions(), action)) line(pad ? kPadPrefix : kKeysPrefix, action, names);
  }
  return text;
}

std::string Settings::save(const std::string& path) const { return saveWhole(path, text(), "the settings file"); }

}  // namespace platon::app
