#include "platon/core/file_watch.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <poll.h>
#include <set>
#include <stdexcept>
#include <sys/inotify.h>
#include <unistd.h>

namespace platon::core {
namespace {

// A save in place ends with IN_CLOSE_WRITE; a save by rename with IN_MOVED_TO.
constexpr uint32_t kSaved = IN_CLOSE_WRITE | IN_MOVED_TO;

// "folder/name" of a path as given, made absolute: the key events are matched by.
std::filesystem::path normalPath(const std::string& file) { return std::filesystem::absolute(file).lexically_normal(); }

}  // namespace

FileWatcher::FileWatcher() : fd_(inotify_init1(IN_NONBLOCK | IN_CLOEXEC)) {
  if (fd_ < 0)
    throw std::runtime_error(std::string("file watching (inotify) is not available: ") + std::strerror(errno));
}

FileWatcher::~FileWatcher() { close(fd_); }

std::vector<std::string> FileWatcher::watch(const std::vector<std::string>& files) {
  std::map<std::string, std::string> wantedFiles;  // as files_
  std::set<std::string> wantedFolders;
  for (const std::string& file : files) {
    const std::filesystem::path path = normalPath(file);
    wantedFolders.insert(path.parent_path().string());
    wantedFiles.emplace(path.parent_path().string() + "/" + path.filename().string(), file);
  }
  // Drop only the folders no longer wanted. Removing and adding the others again would give them
  // new watch descriptors, and the events queued under the old ones would be lost (a save that
  // landed during a reload).
  std::set<std::string> watchedFolders;
  for (auto it = folders_.begin(); it != folders_.end();) {
    if (wantedFolders.count(it->second)) {
      watchedFolders.insert(it->second);
      ++it;
    } else {
      inotify_rm_watch(fd_, it->first);
      it = folders_.erase(it);
    }
  }
  std::string unwatchable;
  for (const std::string& folder : wantedFolders) {
    if (watchedFolders.count(folder)) continue;
    const int wd = inotify_add_watch(fd_, folder.c_str(), kSaved);
    if (wd < 0) {
      unwatchable += (unwatchable.empty() ? "" : "; ") + folder + ": cannot watch for changes: " + std::strerror(errno);
      continue;
    }
    folders_[wd] = folder;
  }
  std::vector<std::string> added;
  for (const auto& [key, file] : wantedFiles)
    if (!files_.count(key)) added.push_back(file);
  files_ = std::move(wantedFiles);
  if (!unwatchable.empty()) throw std::runtime_error(unwatchable);
  return added;
}

std::vector<std::string> FileWatcher::changes(int timeoutMilliseconds) {
  std::set<std::string> changed;
  pollfd p{fd_, POLLIN, 0};
  if (poll(&p, 1, timeoutMilliseconds) <= 0) return {};
  alignas(inotify_event) char buffer[16384];
  for (;;) {
    const ssize_t n = read(fd_, buffer, sizeof buffer);
    if (n <= 0) break;  // EAGAIN: read everything there was
    for (ssize_t at = 0; at < n;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
      const auto folder = folders_.find(event->wd);
      if (folder == folders_.end() || event->len == 0) continue;
      const auto file = files_.find(folder->second + "/" + event->name);
      if (file != files_.end()) changed.insert(file->second);
    }
  }
  return {changed.begin(), changed.end()};
}

}  // namespace platon::core
