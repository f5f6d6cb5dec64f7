// The scripting system: one LuaJIT state per scene, created only for scenes whose manifest lists
// "scripting". It loads the scene's scripts (scripts/scene.lua drives them): the rules, the
// player, the progression, the level script and mods, and runs them each frame.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "platon/core/scene.h"
#include "platon/script/script_error.h"

namespace platon::script {

// The game's state as the scripts keep it: what scenarios check and the HUD shows.
struct GameStatus {
  bool won = false;
  uint64_t wonFrame = 0;  // the frame the goal was reached (0: not yet)
  int deaths = 0;
  uint64_t time = 0;            // frames played on the level (kept across hot reloads)
  physics::MapPartId face = 0;  // the player's face (its anchor's part)
  int32_t x = 0, y = 0;         // the player's position on it
  double vx = 0, vy = 0;        // its velocity, units per frame
  bool grounded = false;        // the player script's own word (its `grounded` field)
  bool hasCheckpoint = false;   // the last checkpoint touched, where the player comes back
  physics::MapPartId checkpointFace = 0;
  int32_t checkpointX = 0, checkpointY = 0;
  std::string message;             // the latest level message
  std::vector<uint32_t> openTags;  // line tags the game lets the player through now (open doors)
};

class ScriptSystem final : public core::System, public core::Console {
 public:
  // root: the folder that holds scripts/ (engine scripts are found there).
  ScriptSystem(core::Scene& scene, std::string root);
  ~ScriptSystem() override;

  void declareTags(core::Scene& scene, stage::TagTable& tags) override;
  void build(core::Scene& scene) override;
  void start(core::Scene& scene) override;
  void beforeStep(core::Scene& scene, const core::InputFrame& input) override;
  void afterStep(core::Scene& scene) override;
  void draw(const core::Scene& scene, core::DrawList& out) const override;
  void sourceFiles(std::vector<std::string>& out) const override;
  // Hands the old version's save() (plain data: counters, the player, what level scripts and mods
  // save) to the new version's restore(); docs/scripting.md, "Hot reload".
  void carryOver(core::Scene& scene, core::System& previous) override;
  void carryBeforeBuild(core::System& previous) override;

  // The game's state. Never throws: a script error here (or in draw()) is kept, reported with
  // the next frame's errors (or by takeError()), and the last status that worked is returned.
  GameStatus status() const;
  // The errors kept from status() and draw() and from sandboxed calls since the last frame, as
  // one report; nothing when there are none. For a run that ends before another frame would.
  std::optional<std::string> takeError();
  // Runs `code` as trusted Lua in the scene's state with `game` and `platon` visible; for
  // scenarios' checks. Returns its first result converted to a string ("" for nil).
  std::string evaluate(const std::string& code, const std::string& chunkName);
  size_t luaMemoryBytes() const;
  // Runs a line typed in the game's console (docs/scripting.md, "Console"), between frames: as
  // sandboxed code in the level script's globals (when it is sandboxed) but a sandbox of its own,
  // with the level's `game` (what level scripts get) as `game`, under the sandboxes' budget and
  // memory limit. An expression's value is returned as the
  // sandboxes' tostring shows it. Never throws: an error is the answer.
  using ConsoleAnswer = core::ConsoleAnswer;
  ConsoleAnswer console(const std::string& code);
  core::Console* console() override { return this; }
  ConsoleAnswer run(const std::string& code) override { return console(code); }
  // The Lua language server's definitions (---@meta) of the API trusted scripts see, or sandboxed
  // ones (with the `game` level scripts get), from the live binding tables; `problems` gets each
  // binding with no definition and each definition with no binding (`platon defs`).
  std::string definitions(bool sandboxed, std::vector<std::string>& problems);

  struct State;  // the Lua state and what the bindings reach (script_system.cpp)

 private:
  GameStatus readStatus() const;
  void prepare(core::Scene& scene);
  void declareActions(core::Scene& scene, int list);
  void setTagsApi(const stage::TagTable& tags);
  bool tagsSet_ = false;
  bool consoleOpenedFrame_ = false;  // console lines began the coming frame's budget (console, beforeStep)
  std::unique_ptr<State> state_;
  double carriedFrames_ = 0;  // the level's frames played, from the version this one replaces
};

// The registry's factory for "scripting": finds the engine's scripts in core::dataRoot() (the
// program's data folder, or $PLATON_ROOT).
std::unique_ptr<core::System> makeScriptSystem(core::Scene& scene);

}  // namespace platon::script
