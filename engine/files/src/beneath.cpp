#include "beneath.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <deque>
#include <fcntl.h>
#include <linux/openat2.h>
#include <sys/syscall.h>
#include <unistd.h>
#include <vector>

#include "fd.h"

namespace platon::files {

namespace {

constexpr int kMaxLinks = 40;  // as the kernel's own walk

std::deque<std::string> partsOf(const std::string& path) {
  std::deque<std::string> parts;
  for (size_t begin = 0; begin <= path.size();) {
    const size_t end = std::min(path.find('/', begin), path.size());
    parts.push_back(path.substr(begin, end - begin));
    begin = end + 1;
  }
  return parts;
}

// The folders walked into, the first the one the walk began in: each closed at the end.
struct Walk {
  std::vector<int> folders;
  ~Walk() {
    for (const int fd : folders) close(fd);
  }
  int fail(int error) {
    errno = error;
    return -1;
  }
};

}  // namespace

int openWalking(int folder, const std::string& name) {
  Walk walk;
  walk.folders.push_back(dup(folder));
  if (walk.folders.back() < 0) return -1;
  std::deque<std::string> parts = partsOf(name);
  int links = 0;
  while (!parts.empty()) {
    const std::string part = parts.front();
    parts.pop_front();
    const int at = walk.folders.back();
    if (part.empty() || part == ".") {
      if (parts.empty()) return openat(at, ".", kReadFlags);  // "a/": the folder itself
      continue;
    }
    if (part == "..") {
      if (walk.folders.size() == 1) return walk.fail(EXDEV);  // above the folder
      close(at);
      walk.folders.pop_back();
      if (parts.empty()) return openat(walk.folders.back(), ".", kReadFlags);
      continue;
    }
    char target[PATH_MAX];
    const ssize_t n = readlinkat(at, part.c_str(), target, sizeof target - 1);
    if (n >= 0) {  // a link: its target is walked in its place
      if (++links > kMaxLinks) return walk.fail(ELOOP);
      if (n == 0 || target[0] == '/') return walk.fail(EXDEV);
      std::deque<std::string> inner = partsOf(std::string(target, static_cast<size_t>(n)));
      parts.insert(parts.begin(), inner.begin(), inner.end());
      continue;
    }
    if (errno != EINVAL) return -1;  // missing, or not readable
    if (parts.empty()) return openat(at, part.c_str(), kReadFlags | O_NOFOLLOW);
    const int next = openat(at, part.c_str(), O_PATH | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (next < 0) return -1;
    walk.folders.push_back(next);
  }
  return walk.fail(ENOENT);
}

int openBeneath(int folder, const std::string& name) {
  open_how how{};
  how.flags = kReadFlags;
  how.resolve = RESOLVE_BENEATH | RESOLVE_NO_MAGICLINKS;
  const long fd = syscall(SYS_openat2, folder, name.c_str(), &how, sizeof how);
  if (fd < 0 && (errno == ENOSYS || errno == EPERM)) return openWalking(folder, name);  // EPERM: a seccomp filter
  return static_cast<int>(fd);
}

}  // namespace platon::files
