// A scene that reloads itself when its files change: the manifest, the level and the scripts.
//
// A reload loads the whole scene again from its manifest, into a new world with new systems, and
// only then lets each new system take over from its old self (System::carryOver): the player
// keeps its place and state where the new level allows it. Any error while loading or taking
// over leaves the old scene running and is reported; so is an error while running a frame, and
// the game goes on. The files to watch are the manifest and what each system read
// (System::sourceFiles), and after a refused reload also the files the refused manifest names (a
// broken edit may have added one, and saving its fix must reload). A save that lands while a
// reload runs is not lost: the next poll() reloads again for it.
//
// Entity handles do not cross a reload: the new world numbers its entities afresh, so a handle a
// script carried over (through save/onReload) may name another entity of the new world. Scripts
// carry places and their own ids instead, and look entities up again.
#pragma once
#include <filesystem>
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

// The files a loaded scene was read from: its manifest, its level file and what each system read
// (System::sourceFiles), each once, in that order. Hot reload watches them; a replay records a
// hash of their contents.
std::vector<std::string> sceneSourceFiles(Scene& scene);

class LiveScene {
 public:
  // Loads the scene; throws as loadScene does when the first version is broken (there is no
  // last good version yet). `watch`: follow the files with inotify.
  // `override`: the level's text or start replaced, in this version and every reload (the
  // editor's play-test of a level as edited).
  LiveScene(std::string manifestPath, const SystemRegistry& registry, bool watch,
            std::optional<LevelOverride> override = std::nullopt);

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
  // The files the live version read: the manifest, the level file, each system's sources.
  std::vector<std::string> watchedFiles() const;
  // The files the manifest on disk names now, read without Lua (empty when it does not parse:
  // the manifest itself is always watched).
  std::vector<std::string> manifestFiles() const;
  // Watches the live version's files and the manifest's; a file watched only from now on that
  // was saved since `since` goes to pending_.
  void watchAgain(std::filesystem::file_time_type since, ReloadReport& report);

  std::string path_;
  const SystemRegistry& registry_;
  std::optional<LevelOverride> override_;
  std::unique_ptr<Scene> scene_;
  std::optional<FileWatcher> watcher_;
  std::string lastError_;
  uint64_t reloads_ = 0;
  std::vector<std::string> pending_;  // saved while a reload ran: the next poll() reloads for them
};

}  // namespace platon::core
