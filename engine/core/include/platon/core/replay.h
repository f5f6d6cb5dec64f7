// A replay: the buttons held on every frame of a run, and the world's state hash every few frames,
// in a small text file. The simulation is deterministic (integer physics, a fixed step, seeded
// randomness), so feeding the same input to the same scene reproduces the run bit for bit, and
// the hashes say on which frame a replay first went another way.
//
//   platon replay 1
//   scene "levels/cube_intro/scene.lua"
//   scene_files 5d41402abc4b2a76   <- optional: a hash of the scene's files when it was recorded
//   speed 75                   <- optional: the assist mode's game speed it was played at (50-100 %)
//   start 2 1200 640           <- optional: where the run starts (face x y), if not at the level's start
//   frames 336
//   hash_every 60
//   input
//   12 -                       <- 12 frames with nothing held
//   300 right                  <- then 300 frames holding right
//   24 right jump
//   end
//   hash 60 0a1b2c3d4e5f6a7b
//   hash 120 ...
//
// Blank lines are ignored, and so is everything from a '#' that starts a word to the end of its
// line (a comment on a line of its own or after the words). The file is plain ASCII: a UTF-8
// byte-order mark is not skipped. The hashes are all or none: a file either has every hash its
// hash_every implies (each multiple of it, and the last frame) or none at all (input only: it
// replays but checks nothing). Errors name file:line:column.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "platon/core/actions.h"

namespace platon::core {

struct ReplayHash {
  uint64_t frame;
  uint64_t hash;
};

// A line typed in the game's console (docs/scripting.md, "Console"): run before frame `frame`.
struct ReplayConsole {
  uint64_t frame;
  std::string code;
};

// Where a run starts when not at its level's start (a play-test from the editor's cursor): a face
// and a point on it, in the level file's units.
struct ReplayStart {
  int face = 0;
  int32_t x = 0, y = 0;
  friend bool operator==(const ReplayStart&, const ReplayStart&) = default;
};
inline constexpr uint64_t kMaxStartCoordinate = (uint64_t{1} << 29);  // the level format's range

struct Replay {
  std::string scene;    // the scene's manifest, as the run named it
  std::string sceneAt;  // "file:line:column" of that path in the replay read, for errors about the scene
  // A hash of the contents of the scene's files when it was recorded (core/live_scene.h's
  // sceneSourceFiles): a replay that goes another way can say whether they changed since. Files
  // from before this line existed have none.
  std::optional<uint64_t> sceneFiles;
  // The game speed (percent) a player ran it at in the assist mode: pacing only, so the frames and
  // their hashes are the same at any speed; kept so a run can be watched as it was played.
  int speed = 100;
  std::optional<ReplayStart> start;    // none: the level's own start
  std::vector<Buttons> held;           // held[f - 1]: the actions held on frame f, bit i actions.names[i]
  ActionNames actions;                 // the scene's when recorded; read: the engine's, then the file's others
  uint64_t hashEvery = 60;             // frames between recorded hashes (0: none)
  std::vector<ReplayHash> hashes;      // increasing frames
  std::vector<ReplayConsole> console;  // frames that do not decrease

  uint64_t frames() const { return held.size(); }
};

// Whether a path has a ".." component: a replay's or a scenario's scene path may not (they are
// shared, and a ".." could name a scene by a path that looks like another: scripts/../../x).
bool hasParentStep(const std::string& path);

// Throws std::runtime_error "file:line:column: reason" for anything malformed (and a scene path
// with "..").
// A replay file is a regular file of at most this (hours of play take a few MB).
inline constexpr size_t kMaxReplayBytes = size_t{64} << 20;
Replay readReplay(const std::string& path);
Replay parseReplay(const std::string& text, const std::string& fileName);
std::string formatReplay(const Replay& replay);
// Writes through a temporary file and a rename, so a crash never leaves half a replay.
void writeReplay(const Replay& replay, const std::string& path);

// The hash a replay records of its scene's files: their contents in the order given (a file that
// cannot be read counts as one that says so).
uint64_t sceneFilesHash(const std::vector<std::string>& files);

// Builds a replay while a run goes on: call frame() after each simulated frame.
class ReplayRecorder {
 public:
  ReplayRecorder(std::string scene, uint64_t hashEvery, std::optional<uint64_t> sceneFiles = std::nullopt);
  void frame(Buttons held, uint64_t stateHashAfter);
  // The names of the bits frame() is given: the scene's actions (the engine's by default).
  void setActions(ActionNames names) { replay_.actions = std::move(names); }
  // A console line, run before the next frame.
  void console(const std::string& code);
  // The game speed the run is played at (Replay::speed).
  void setSpeed(int percent) { replay_.speed = percent; }
  // Where the run started, when not at its level's start (Replay::start).
  void setStart(std::optional<ReplayStart> start) { replay_.start = start; }
  // The replay so far, its last frame's hash included.
  Replay replay() const;

 private:
  Replay replay_;
  uint64_t lastHash_ = 0;
};

}  // namespace platon::core
