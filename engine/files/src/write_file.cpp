#include "platon/files/write_file.h"

#include <cstdio>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace platon::files {
void makeFolders(const std::string& path) {
  for (size_t i = 1; i <= path.size(); ++i)
    if (i == path.size() || path[i] == '/') mkdir(path.substr(0, i).c_str(), 0755);
}

std::string saveWhole(const std::string& path, const std::string& text, const std::string& what) {
  const size_t slash = path.find_last_of('/');
  if (slash != std::string::npos) makeFolders(path.substr(0, slash));
  const std::string temporary = path + ".new";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  bool written = fd >= 0;
  for (size_t done = 0; written && done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n <= 0)
      written = false;
    else
      done += static_cast<size_t>(n);
  }
  written = written && ::fsync(fd) == 0;
  if (fd >= 0) ::close(fd);
  if (!written) {
    if (fd >= 0) std::remove(temporary.c_str());
    return temporary + ": cannot write " + what;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) return path + ": cannot replace " + what;
  return "";
}

}  // namespace platon::files
