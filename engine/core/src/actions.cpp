#include "platon/core/actions.h"

#include <stdexcept>

#include "platon/core/input.h"

namespace platon::core {

const std::vector<Action>& engineActions() {
  // Button's order: a recorded bit keeps its meaning from one version to the next.
  static const std::vector<Action> actions{
      {"left",
       "Left",
       {"Left", "A"},
       {"dpleft"},
       "walks left along the face (its own left, as gravity turns)",
       true,
       ""},
      {"right", "Right", {"Right", "D"}, {"dpright"}, "walks right along the face", true, ""},
      {"up", "Up", {"Up", "W"}, {"dpup"}, "up, for scripts that use it (the game's player does not)", true, ""},
      {"down",
       "Down",
       {"Down", "S"},
       {"dpdown"},
       "down, for scripts that use it (the game's player does not)",
       true,
       ""},
      {"jump",
       "Jump",
       {"Space"},
       {"a", "b"},
       "jumps; held longer, higher (the jump is cut when it is let go)",
       true,
       ""},
      {"restart", "Restart", {"R"}, {"back"}, "back to the level's start (a death)", true, ""},
      {"pause", "Pause", {}, {}, "held by scripts and scenarios only: the game's Esc pauses the window", false, ""},
      {"reload", "Reload", {"F5"}, {}, "F5: the level's files read again (the tool's key, not bindable)", false, ""},
  };
  static_assert(kButtonCount == 8);
  return actions;
}

std::optional<int> actionIndex(const std::vector<Action>& actions, std::string_view name) {
  for (size_t i = 0; i < actions.size(); ++i)
    if (actions[i].name == name) return static_cast<int>(i);
  return std::nullopt;
}

std::string actionList(const std::vector<Action>& actions) {
  std::string out;
  for (const Action& a : actions) out += (out.empty() ? "" : ", ") + a.name;
  return out;
}

bool isActionName(std::string_view name) {
  if (name.empty() || name.size() > 32) return false;
  const auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
  if (!letter(name[0])) return false;
  for (const char c : name)
    if (!letter(c) && !(c >= '0' && c <= '9') && c != '_') return false;
  return true;
}

void addAction(std::vector<Action>& actions, Action action) {
  if (!isActionName(action.name))
    throw std::runtime_error("'" + action.name + "' is no action name (letters, digits and _, from a letter)");
  if (action.name == "pressed")  // Lua's input.pressed is the table of the frame's presses
    throw std::runtime_error("'pressed' is input.pressed, the frame's presses: no action's name");
  if (const std::optional<int> i = actionIndex(actions, action.name)) {
    const Action& taken = actions[static_cast<size_t>(*i)];
    throw std::runtime_error("the action '" + action.name + "' is " +
                             (taken.owner.empty() ? std::string("the engine's") : taken.owner + "'s"));
  }
  if (actions.size() >= kMaxActions)
    throw std::runtime_error("more than " + std::to_string(kMaxActions - kButtonCount) +
                             " actions added to the engine's (" + actionList(actions) + ")");
  if (action.label.empty()) action.label = action.name;
  actions.push_back(std::move(action));
}

ActionNames::ActionNames() : ActionNames(engineActions()) {}

ActionNames::ActionNames(const std::vector<Action>& actions) {
  for (const Action& a : actions) names.push_back(a.name);
  where.resize(names.size());
}

std::optional<int> ActionNames::bitOf(std::string_view name, const std::string& at) {
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  if (!isActionName(name) || names.size() >= kMaxActions) return std::nullopt;
  names.emplace_back(name);
  where.push_back(at);
  return static_cast<int>(names.size() - 1);
}

ActionMap::ActionMap(const ActionNames& from, const std::vector<Action>& to) {
  for (size_t i = 0; i < from.names.size() && i < kMaxActions; ++i) {
    const std::optional<int> j = actionIndex(to, from.names[i]);
    if (!j) {
      const std::string& at = i < from.where.size() ? from.where[i] : "";
      throw std::runtime_error((at.empty() ? "" : at + ": ") + "no action '" + from.names[i] +
                               "' in this scene (its actions: " + actionList(to) + ")");
    }
    bit_[i] = static_cast<Buttons>(1u << *j);
    same_ = same_ && *j == static_cast<int>(i);
  }
}

Buttons ActionMap::operator()(Buttons held) const {
  if (same_) return held;
  Buttons out = 0;
  for (int i = 0; held >> i; ++i)
    if (held >> i & 1) out |= bit_[static_cast<size_t>(i)];
  return out;
}

KeyBindings bindingsFor(const std::vector<Action>& actions, const BindingChoices& choices) {
  KeyBindings out;
  for (const Action& a : actions) {
    const auto keys = choices.keys.find(a.name);
    const auto pad = choices.pad.find(a.name);
    const bool chosen = a.bindable;  // the tools' keys are not the player's to move
    out.keys.push_back(chosen && keys != choices.keys.end() ? keys->second : a.keys);
    out.pad.push_back(chosen && pad != choices.pad.end() ? pad->second : a.pad);
  }
  return out;
}

}  // namespace platon::core
