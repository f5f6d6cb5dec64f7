// A scene that reloads itself when its files change: the manifest, the level and the scripts.
//
// A reload loads the whole scene again from its manifest, into a new world with new systems, and
// only then lets each new system take over from its old self (System::carryOver): the player
// keeps its place and state where the new level allows it. Any error while loading or taking
// over leaves the old scene running and is reported; so is an error while running a frame, and
// the game goes on. The files to watch are the manifest and what each system read
// (System::sourceFiles).
#pragma once
#include <memory>
#include <optional>
#include <string>

#include "platon/core/file_watch.h"
#include "platon/core/scene.h"

namespace platon::core {

struct ReloadReport {
  bool ok = false;
  std::string error;               // why the new version was refused (file:line and details)
  std::vector<std::string> files;  // the saved files that caused it
  double milliseconds = 0;         // loading the new version and taking over
};

class LiveScene {
 public:
  // Loads the scene; throws as loadScene does when the first version is broken (there is no
  // last good version yet). `watch`: follow the files with inotify.
  LiveScene(std::string manifestPath, const SystemRegistry& registry, bool watch);

  Scene& scene() { return *scene_; }
  const std::string& manifestPath() const { return path_; }

  // One frame. A system's error is kept in lastError() (the frame still happens) and returned.
  std::optional<std::string> step(const InputFrame& input);
  // Looks for saved files (waiting up to timeoutMilliseconds) and reloads when there are some.
  std::optional<ReloadReport> poll(int timeoutMilliseconds = 0);
  // Loads the scene again now.
  ReloadReport reload(std::vector<std::string> because = {});

  // The latest error (a frame's or a reload's), "" once a reload succeeded or a frame ran clean.
  const std::string& lastError() const { return lastError_; }
  uint64_t reloads() const { return reloads_; }

 private:
  std::vector<std::string> watchedFiles() const;

  std::string path_;
  const SystemRegistry& registry_;
  std::unique_ptr<Scene> scene_;
  std::optional<FileWatcher> watcher_;
  std::string lastError_;
  uint64_t reloads_ = 0;
};

}  // namespace platon::core
