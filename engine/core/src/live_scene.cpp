#include "platon/core/live_scene.h"

#include <chrono>

#include "platon/core/error.h"

namespace platon::core {

LiveScene::LiveScene(std::string manifestPath, const SystemRegistry& registry, bool watch)
    : path_(std::move(manifestPath)), registry_(registry), scene_(loadScene(path_, registry_)) {
  if (watch) {
    watcher_.emplace();
    watcher_->watch(watchedFiles());
  }
}

std::vector<std::string> LiveScene::watchedFiles() const {
  std::vector<std::string> files{path_};
  if (!scene_->manifest().levelFile.empty()) files.push_back(scene_->manifest().levelFile);
  for (size_t i = 0; i < scene_->systemCount(); ++i) scene_->system(i).sourceFiles(files);
  return files;
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
  std::vector<std::string> changed = watcher_->changes(timeoutMilliseconds);
  if (changed.empty()) return std::nullopt;
  return reload(std::move(changed));
}

ReloadReport LiveScene::reload(std::vector<std::string> because) {
  const auto start = std::chrono::steady_clock::now();
  ReloadReport report;
  report.files = std::move(because);
  try {
    std::unique_ptr<Scene> next = loadScene(path_, registry_);
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
  // Watch what the live version reads, even after a refused reload (a broken edit may have added
  // a file, and saving the fix must be seen).
  if (watcher_) {
    try {
      watcher_->watch(watchedFiles());
    } catch (const std::exception& e) {
      if (report.error.empty()) report.error = e.what();
    }
  }
  report.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace platon::core
