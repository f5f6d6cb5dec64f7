// One run of a scene, frame by frame: the buttons of each frame and their press edges, the console
// lines typed between frames, and the recording of all of it. Every way of playing drives a Run
// (the game, `play`, the editor's play-test, `shot`, `run` and `replay`), so one input plays the
// same frames, and ends in the same state, whichever of them plays it.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "platon/core/input.h"
#include "platon/core/replay.h"
#include "platon/core/system.h"

namespace platon::core {

class LiveScene;
class Scene;

// What a recording names: the scene (as a path a replay may carry), and how the run began.
struct RunRecording {
  std::string scene;
  uint64_t hashEvery = 60;
  std::optional<uint64_t> sceneFiles;  // sceneFilesHash of the files played
  std::optional<ReplayStart> start;    // none: the level's own start
  int speed = 100;                     // the assist mode's game speed (pacing only)
};

class Run {
 public:
  // A live scene: a frame's error is kept and returned, and the game goes on.
  explicit Run(LiveScene& live);
  // A scene of its own: a frame's error throws (a scenario fails at its first).
  explicit Run(Scene& scene);

  Scene& scene();
  // Frames played since the run began.
  uint64_t frame() const { return frame_; }

  // A line typed in the console: run now, before the next frame, and recorded there. nullopt when
  // no system of the scene has a console (no scripts).
  std::optional<ConsoleAnswer> console(const std::string& code);
  // Plays the next frame with `held` actions down (InputFrame bits, the scene's actions); their
  // presses are the ones not down on the frame before. The frame's error (a live scene's), or nullopt.
  std::optional<std::string> step(Buttons held);
  // After a pause, a menu or the editor: a button still held is pressed anew on the next frame.
  void releaseButtons() { previous_ = 0; }

  // Records from the next frame on (a recording already under way is dropped).
  void record(const RunRecording& how);
  bool recording() const { return recorder_.has_value(); }
  // What was recorded since record(), and recording stops; nullopt when none was under way. A
  // reload ends a recording: the new version starts from a state no replay reproduces.
  std::optional<Replay> stopRecording();
  // What was recorded so far (recording goes on); nullopt when none is under way.
  std::optional<Replay> recorded() const;

 private:
  LiveScene* live_ = nullptr;
  Scene* scene_ = nullptr;
  uint64_t frame_ = 0;
  Buttons previous_ = 0;
  std::optional<ReplayRecorder> recorder_;
};

// A replay as a run's input: before each frame the console lines typed there, then its buttons.
class ReplayInput {
 public:
  // The replay's actions are matched to `scene`'s by name (a mod's action may have another bit in
  // another version of the scene); throws std::runtime_error "file:line:column: no action ..."
  // for one the scene does not have.
  ReplayInput(const Replay& replay, const Scene& scene);
  // Whether the replay has no frame left after `frame` frames.
  bool over(uint64_t frame) const { return frame >= replay_.frames(); }
  // Runs in `run` the console lines due before its next frame (each told to `typed`, with its
  // answer) and returns that frame's buttons: none past the replay's end.
  Buttons next(Run& run, const std::function<void(const std::string&, const ConsoleAnswer&)>& typed = {});

 private:
  const Replay& replay_;
  ActionMap map_;
  size_t nextLine_ = 0;
};

}  // namespace platon::core
