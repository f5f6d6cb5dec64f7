// One running level: its physics world, the stage its faces came from, and the systems it asked
// for. A frame is: systems read the input, physics solves, systems see the result.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "platon/core/actions.h"
#include "platon/core/look.h"
#include "platon/core/manifest.h"
#include "platon/core/mesh_source.h"
#include "platon/core/sound.h"
#include "platon/core/system.h"
#include "platon/physics/world.h"
#include "platon/stage/level.h"
#include "platon/stage/mesh.h"
#include "platon/stage/stage.h"

namespace platon::core {

class Scene {
 public:
  physics::World& world() { return world_; }
  const physics::World& world() const { return world_; }

  // The solid the level is drawn on, once built into the world.
  void setStage(stage::Stage stage) { stage_ = std::move(stage); }
  const stage::Stage* stage() const { return stage_ ? &*stage_ : nullptr; }
  // The level file the stage came from, when the manifest names one.
  void setLevel(stage::Level level) { level_ = std::move(level); }
  const stage::Level* level() const { return level_ ? &*level_ : nullptr; }
  // The scene's line tags: the game's and what its systems declared (System::declareTags), the
  // words its level file was read with and the looks the renderer gives them.
  void setTags(std::shared_ptr<const stage::TagTable> tags) { tags_ = std::move(tags); }
  const std::shared_ptr<const stage::TagTable>& tags() const { return tags_; }
  // The player's actions in this scene: the engine's, then those its mods added (core/actions.h).
  void setActions(std::vector<Action> actions) { actions_ = std::move(actions); }
  const std::vector<Action>& actions() const { return actions_; }

  // The manifest the scene was loaded from (empty for scenes built in code).
  const SceneManifest& manifest() const { return manifest_; }
  void setManifest(SceneManifest manifest) { manifest_ = std::move(manifest); }

  // Systems run in the order they were added; `name` is the registry's name for it.
  void addSystem(std::unique_ptr<System> system, std::string name = "");
  size_t systemCount() const { return systems_.size(); }
  System& system(size_t index) { return *systems_.at(index); }
  const std::string& systemName(size_t index) const { return names_.at(index); }
  // The named system, or nullptr.
  System* findSystem(std::string_view name);

  // One fixed frame. A system that throws does not stop the frame: the physics step and the other
  // systems run, and the first error is rethrown at the end, so a frame always happens once.
  physics::SolveReport step(const InputFrame& input);
  uint64_t frame() const { return world_.frame(); }
  // Draws the world (its entities by their looks, its platforms), then asks every system what to
  // draw; does nothing when the list is disabled (no renderer).
  void draw(DrawList& out) const;
  // How entities are drawn (platon.draw.look): the picture's, not the simulation's.
  Looks& looks() { return looks_; }
  // What the scene makes heard (platon.sound): its bank, this frame's effects, its tune. Cleared at
  // each step's start and handed to every system's hear() at its end.
  Sounds& sounds() { return sounds_; }
  const Sounds& sounds() const { return sounds_; }

 private:
  SceneManifest manifest_;
  physics::World world_;
  std::shared_ptr<const stage::TagTable> tags_ = stage::gameTags();
  std::vector<Action> actions_ = engineActions();
  std::optional<stage::Stage> stage_;
  std::optional<stage::Level> level_;
  Looks looks_;
  Sounds sounds_;
  std::vector<std::unique_ptr<System>> systems_;
  std::vector<std::string> names_;
};

// Loads a scene from its manifest: builds the stage, creates the systems the manifest names that
// `registry` knows (the others are left out: a headless run registers no renderer), lets them
// build the level, initializes the faces and starts the systems. Throws std::runtime_error with
// file:line:column for a bad manifest and the systems' own errors for the rest. A hot reload names
// the scene it replaces: each new system is given its predecessor before build (carryBeforeBuild).
// What a scene is loaded with instead of what its files say: the level's text as an editor holds
// it (not saved yet), and where the player starts (a play-test from the editor's cursor, a scenario
// or a replay that starts there).
struct LevelOverride {
  std::optional<std::string> text;
  std::optional<stage::LevelPoint> start;
};
std::unique_ptr<Scene> loadScene(const std::string& manifestPath, const SystemRegistry& registry,
                                 Scene* replacing = nullptr, const LevelOverride* override = nullptr);

// The line tags a scene's level file may write: the game's and those its mods declare (the mods
// are run for it, in a scene of their own). For tools that read a level without playing it.
std::shared_ptr<const stage::TagTable> sceneTags(const std::string& manifestPath, const SystemRegistry& registry);

// A mesh level's stage: its MESH file (relative to the level file) read by `source`, made a convex
// solid with the level's size. Throws StageError naming the level file and what is wrong.
stage::Stage meshStageOf(const stage::Level& level, MeshSource& source);
// The stage a level is drawn on: its Platonic solid, or its mesh read by the meshes system (created
// in `scene` when it has none; the scene's manifest must list "meshes"). Throws StageError.
stage::Stage levelStage(const stage::Level& level, const SystemRegistry& registry, Scene& scene);
// What the meshes plugin read, as the stage's mesh builder takes it.
stage::MeshData meshDataOf(const MeshFile& file);

}  // namespace platon::core
