#include "platon/core/live_scene.h"

#include <algorithm>
#include <chrono>
#include <system_error>
#include <time.h>

#include "platon/core/error.h"
#include "platon/core/manifest.h"

namespace platon::core {
namespace {

void addOnce(std::vector<std::string>& files, const std::string& file) {
  if (!file.empty() && std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
}

// The folder engine scripts ("scripts/...") are read from, as the live version read them: the
// scripting system always loads its driver, <root>/scripts/scene.lua. "" when the live version
// has no scripting (then the engine scripts a refused manifest names are not watched).
std::string engineRootOf(const std::vector<std::string>& liveFiles) {
  const std::string driver = "/scripts/scene.lua";
  for (const std::string& file : liveFiles)
    if (file.size() > driver.size() && file.compare(file.size() - driver.size(), driver.size(), driver) == 0)
      return file.substr(0, file.size() - driver.size());
  return "";
}

// Now, on the clock file times are stamped with. The kernel stamps a write with its coarse clock
// (a tick of a few milliseconds), which can be a little behind the exact time: compared with the
// exact time, a save just after it could look older than it is.
std::filesystem::file_time_type fileClockNow() {
  timespec now{};
  clock_gettime(CLOCK_REALTIME_COARSE, &now);
  const auto sinceEpoch = std::chrono::seconds(now.tv_sec) + std::chrono::nanoseconds(now.tv_nsec);
  return std::chrono::file_clock::from_sys(std::chrono::system_clock::time_point(
      std::chrono::duration_cast<std::chrono::system_clock::duration>(sinceEpoch)));
}

}  // namespace

std::vector<std::string> sceneSourceFiles(Scene& scene) {
  std::vector<std::string> files;
  addOnce(files, scene.manifest().path);
  addOnce(files, scene.manifest().levelFile);
  std::vector<std::string> sources;
  for (size_t i = 0; i < scene.systemCount(); ++i) scene.system(i).sourceFiles(sources);
  for (const std::string& file : sources) addOnce(files, file);
  return files;
}

LiveScene::LiveScene(std::string manifestPath, const SystemRegistry& registry, bool watch,
                     std::optional<LevelOverride> override)
    : path_(std::move(manifestPath)),
      registry_(registry),
      override_(std::move(override)),
      scene_(loadScene(path_, registry_, nullptr, override_ ? &*override_ : nullptr)) {
  if (watch) {
    watcher_.emplace();
    watcher_->watch(watchedFiles());
  }
}

std::vector<std::string> LiveScene::watchedFiles() const {
  std::vector<std::string> files = sceneSourceFiles(*scene_);
  addOnce(files, path_);
  return files;
}

std::vector<std::string> LiveScene::manifestFiles() const {
  SceneManifest m;
  try {
    m = loadManifest(path_);
  } catch (const std::exception&) {
    return {};  // a broken manifest: the manifest is watched, and its fix reloads
  }
  std::vector<std::string> files{m.levelFile};
  const std::vector<std::string> live = watchedFiles();
  for (const std::string* script : {&m.rules, &m.player, &m.progression, &m.level}) {
    if (script->rfind("scripts/", 0) != 0) {
      files.push_back(*script);  // the level's own: already relative to the manifest's folder
    } else if (const std::string root = engineRootOf(live); !root.empty()) {
      files.push_back(root + "/" + *script);
    }
  }
  files.insert(files.end(), m.mods.begin(), m.mods.end());
  files.erase(std::remove(files.begin(), files.end(), std::string()), files.end());
  return files;
}

void LiveScene::watchAgain(std::filesystem::file_time_type since, ReloadReport& report) {
  std::vector<std::string> files = watchedFiles();
  for (const std::string& file : manifestFiles()) addOnce(files, file);
  std::vector<std::string> added;
  try {
    added = watcher_->watch(files);
  } catch (const std::exception& e) {
    if (report.error.empty()) report.error = e.what();
    return;
  }
  // A file watched only from now on was read by the load before its watch began: a save in
  // between raised no event, so its time tells.
  for (const std::string& file : added) {
    std::error_code error;
    const auto written = std::filesystem::last_write_time(file, error);
    if (!error && written >= since) addOnce(pending_, file);
  }
}

std::optional<std::string> LiveScene::step(const InputFrame& input) {
  try {
    scene_->step(input);
  } catch (const std::exception& e) {
    lastError_ = errorReport(e);
    return lastError_;
  }
  return std::nullopt;
}

std::optional<ReloadReport> LiveScene::poll(int timeoutMilliseconds) {
  if (!watcher_) return std::nullopt;
  std::vector<std::string> changed = watcher_->changes(pending_.empty() ? timeoutMilliseconds : 0);
  for (const std::string& file : pending_) addOnce(changed, file);
  pending_.clear();
  if (changed.empty()) return std::nullopt;
  return reload(std::move(changed));
}

ReloadReport LiveScene::reload(std::vector<std::string> because) {
  const auto start = std::chrono::steady_clock::now();
  const auto startOnFileClock = fileClockNow();
  ReloadReport report;
  report.files = std::move(because);
  try {
    std::unique_ptr<Scene> next = loadScene(path_, registry_, scene_.get(), override_ ? &*override_ : nullptr);
    for (size_t i = 0; i < next->systemCount(); ++i)
      if (System* old = scene_->findSystem(next->systemName(i)); old && !next->systemName(i).empty())
        next->system(i).carryOver(*next, *old);
    scene_ = std::move(next);
    report.ok = true;
    lastError_.clear();
    ++reloads_;
  } catch (const std::exception& e) {
    report.error = errorReport(e);
    lastError_ = report.error;
  }
  // Watch what the live version reads, even after a refused reload, and what the manifest on disk
  // names (a broken edit may have added a file, and saving the fix must be seen).
  if (watcher_) watchAgain(startOnFileClock, report);
  report.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace platon::core
