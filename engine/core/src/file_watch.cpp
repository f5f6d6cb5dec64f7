#include "platon/core/file_watch.h"

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <set>
#include <stdexcept>

namespace platon::core {
namespace {

// A save in place ends with IN_CLOSE_WRITE; a save by rename with IN_MOVED_TO.
constexpr uint32_t kSaved = IN_CLOSE_WRITE | IN_MOVED_TO;

}  // namespace

FileWatcher::FileWatcher() : fd_(inotify_init1(IN_NONBLOCK | IN_CLOEXEC)) {
  if (fd_ < 0) throw std::runtime_error(std::string("file watching (inotify) is not available: ") + std::strerror(errno));
}

FileWatcher::~FileWatcher() { close(fd_); }

void FileWatcher::watch(const std::vector<std::string>& files) {
  for (const auto& [wd, folder] : folders_) inotify_rm_watch(fd_, wd);
  folders_.clear();
  files_.clear();
  std::map<std::string, int> byFolder;
  for (const std::string& file : files) {
    const std::filesystem::path path = std::filesystem::absolute(file).lexically_normal();
    const std::string folder = path.parent_path().string();
    if (!byFolder.count(folder)) {
      const int wd = inotify_add_watch(fd_, folder.c_str(), kSaved);
      if (wd < 0) throw std::runtime_error(folder + ": cannot watch for changes: " + std::strerror(errno));
      byFolder[folder] = wd;
      folders_[wd] = folder;
    }
    files_[folder + "/" + path.filename().string()] = file;
  }
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
