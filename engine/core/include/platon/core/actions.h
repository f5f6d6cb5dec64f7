// The player's actions: one table of what a player does with keys and pad buttons (its name, its
// label, its default keys and buttons, what it does). The window's bindings, the settings file and
// screen, scenarios, replays, the Lua `input` table, `platon defs` and the docs all read it. The
// engine's eight come first (Button's order); a scene's mods may add actions of their own (a dash)
// after them, which the same paths carry by name.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace platon::core {

// The actions held on a frame: bit i is action i of the scene's table.
using Buttons = uint16_t;
inline constexpr int kMaxActions = 16;  // the engine's 8 and at most 8 a scene's mods add

struct Action {
  std::string name;                    // "jump": scenarios, replays, settings (keys_jump), Lua (input.jump)
  std::string label;                   // "Jump": the settings screen
  std::vector<std::string> keys, pad;  // by default, by SDL's names ("Space"; "a")
  std::string does;                    // one line: what it does
  bool bindable = true;                // the settings may change its keys (pause and reload are the tools')
  std::string owner;                   // "" the engine's, else the mod that declared it
};

// The engine's actions, in Button's order.
const std::vector<Action>& engineActions();
// The index of `name` in `actions`, or nullopt.
std::optional<int> actionIndex(const std::vector<Action>& actions, std::string_view name);
// "left, right, up, ..." for messages.
std::string actionList(const std::vector<Action>& actions);
// Whether a name may be an action's: letters, digits and _ starting with a letter, 1..32 long.
bool isActionName(std::string_view name);
// Adds a mod's action to `actions`; throws std::runtime_error naming what is wrong (a name taken,
// not a word, more than kMaxActions in all).
void addAction(std::vector<Action>& actions, Action action);

// The names a file (a replay, a scenario) gives its bits: the engine's first, then each other name
// in the order the file first uses it, with where that was, so a name the scene it plays does not
// have is said at its line and column.
struct ActionNames {
  std::vector<std::string> names;  // bit i's
  std::vector<std::string> where;  // "file:line:column" of each name past the engine's first use
  ActionNames();
  explicit ActionNames(const std::vector<Action>& actions);
  // The bit of `name`, added at `where` when new; nullopt when it is no action name or the file
  // has kMaxActions already.
  std::optional<int> bitOf(std::string_view name, const std::string& where);
};

// A file's bits as a scene numbers them.
class ActionMap {
 public:
  // Throws std::runtime_error "where: no action 'dash' in this scene (its actions: ...)".
  ActionMap(const ActionNames& from, const std::vector<Action>& to);
  Buttons operator()(Buttons held) const;

 private:
  bool same_ = true;
  std::array<Buttons, kMaxActions> bit_{};
};

// The keys and pad buttons that hold each action (keys[i]: action i's), by SDL's names.
struct KeyBindings {
  std::vector<std::vector<std::string>> keys, pad;
};
// What a player chose in the settings, by action name (an action not here keeps its defaults).
struct BindingChoices {
  std::map<std::string, std::vector<std::string>> keys, pad;
};
KeyBindings bindingsFor(const std::vector<Action>& actions, const BindingChoices& choices = {});

}  // namespace platon::core
