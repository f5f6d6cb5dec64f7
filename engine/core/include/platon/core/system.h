// Engine systems and the registry that creates them. A scene names the systems it needs
// (scripting, rendering, meshes, ...); only those are created, so a scene that does not need a
// system neither loads nor pays for it. Physics is not a system: every scene has a world, and an
// empty world costs nothing to step.
#pragma once
#include <cstdio>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "platon/core/draw_list.h"
#include "platon/core/input.h"
#include "platon/stage/tags.h"

namespace platon::core {

class MeshSource;

class Scene;
class Display;
class AudioControls;
struct SoundFrame;

// A line of Lua typed in the game's console, and what it answered: its value as the sandboxes'
// tostring shows it, or its error (the scripting system's, docs/scripting.md "Console").
struct ConsoleAnswer {
  bool ok = false;
  std::string text;
};
class Console {
 public:
  virtual ~Console() = default;
  // Runs `code` between frames, before the next; never throws: an error is the answer.
  virtual ConsoleAnswer run(const std::string& code) = 0;
};

class System {
 public:
  virtual ~System() = default;
  // Once, before the level file is read: add the line tags this system's content declares (a
  // mod's own words, stage/tags.h), so that the level may write them. Throwing refuses the scene.
  virtual void declareTags(Scene& scene, stage::TagTable& tags) { (void)scene, (void)tags; }
  // Once, after the stage's faces exist and before they are initialized: add the level's lines.
  virtual void build(Scene& scene) { (void)scene; }
  // Once, after the faces are initialized: place the player and the level's entities.
  virtual void start(Scene& scene) { (void)scene; }
  // Before the physics step: turn input into velocities, run level logic.
  virtual void beforeStep(Scene& scene, const InputFrame& input) { (void)scene, (void)input; }
  // After the physics step: react to where things ended up.
  virtual void afterStep(Scene& scene) { (void)scene; }
  // At the end of every step, once every system's afterStep has run: what the frame made heard
  // (core/sound.h), for the audio system to play.
  virtual void hear(const SoundFrame& frame) { (void)frame; }
  // Say what to draw; called only when the scene has a renderer.
  virtual void draw(const Scene& scene, DrawList& out) const { (void)scene, (void)out; }

  // Hot reload (core/live_scene.h). The files this system read to build the scene: a save to any
  // of them reloads the scene.
  virtual void sourceFiles(std::vector<std::string>& out) const { (void)out; }
  // Called on the new version of a system, once it has started, with the same-named system of the
  // scene it replaces: take over what the new version still allows (the player's place and
  // state, counters). Throwing refuses the new version; the old one stays live.
  virtual void carryOver(Scene& scene, System& previous) { (void)scene, (void)previous; }
  // Called on the new version before build, with the system it replaces: what build must already
  // see (the frames the level has played, so that a platform's cycle goes on where it was).
  virtual void carryBeforeBuild(System& previous) { (void)previous; }

  // The window this system shows the scene in, for the rendering system (core/display.h).
  virtual Display* display() { return nullptr; }
  // The audio system's controls (core/audio.h), for the audio system.
  virtual AudioControls* audio() { return nullptr; }
  // The mesh reader this system offers, for the meshes system (core/mesh_source.h).
  virtual MeshSource* meshSource() { return nullptr; }
  // The console this system runs typed lines in, for the scripting system.
  virtual Console* console() { return nullptr; }
};

using SystemFactory = std::function<std::unique_ptr<System>(Scene&)>;

// The C function a plugin exports: creates its system for `scene` (ownership passes to the caller),
// or returns nullptr with a reason in `error` (at most errorSize bytes, NUL-terminated). No C++
// exception crosses it.
extern "C" using PluginEntry = System * (Scene & scene, char* error, size_t errorSize);
inline constexpr const char* kPluginEntryName = "platon_create_system";

// A plugin's entry body: creates T, and turns any exception into `error` (none may cross the C entry).
template <class T>
System* createPluginSystem(char* error, size_t errorSize) noexcept {
  try {
    return new T();
  } catch (const std::exception& e) {
    std::snprintf(error, errorSize, "%s", e.what());
  } catch (...) {
    std::snprintf(error, errorSize, "unknown error");
  }
  return nullptr;
}

class SystemRegistry {
 public:
  // Registers a factory under `name`; a repeated name throws.
  void add(std::string name, SystemFactory factory);
  // Registers a system that lives in a shared module, lib<module>.so, loaded (dlopen) the first time
  // a scene needs it and kept loaded for the rest of the process (a system's code must outlive it).
  // Searched in $PLATON_PLUGIN_PATH (colon-separated folders), then `folders`. Creating it when no
  // folder has the module, or the module fails to load, throws naming every place tried.
  void addPlugin(const std::string& name, const std::string& module, std::vector<std::string> folders);
  bool has(std::string_view name) const;
  // Creates the named system for `scene`. An unknown name throws, listing the known ones.
  std::unique_ptr<System> create(std::string_view name, Scene& scene) const;
  std::vector<std::string> names() const;

 private:
  struct Entry {
    std::string name;
    SystemFactory factory;
  };
  std::vector<Entry> entries_;
};

}  // namespace platon::core
