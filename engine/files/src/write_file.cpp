#include "platon/files/write_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <random>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>

#include "fd.h"

namespace platon::files {
namespace {

std::string reasonOf(int error) { return std::strerror(error); }

// Why the file of that name may not be replaced ("" when it may: a regular file, or none).
std::string replaceProblem(int folder, const std::string& name) {
  struct stat st {};
  if (fstatat(folder, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0)
    return errno == ENOENT ? "" : "cannot look at it: " + reasonOf(errno);
  if (S_ISLNK(st.st_mode)) return "it is a link (a save never follows one: remove the link first)";
  if (!S_ISREG(st.st_mode)) return "it is not a regular file (a folder, a FIFO or a device)";
  return "";
}

// Makes a new file beside `name` that nobody else named: O_EXCL refuses a name already taken (by a
// planted link too), so another is tried. Sets `made` to its name.
int makeTemporary(int folder, const std::string& name, std::string& made) {
  std::random_device seed;
  std::mt19937_64 pick(seed() ^ static_cast<uint64_t>(getpid()));
  for (int attempt = 0; attempt < 64; ++attempt) {
    char suffix[24];
    std::snprintf(suffix, sizeof suffix, ".new-%08llx", static_cast<unsigned long long>(pick() & 0xffffffffu));
    made = name + suffix;
    const int fd = openat(folder, made.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

bool writeAll(int fd, const std::string& text) {
  for (size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return ::fsync(fd) == 0;
}

}  // namespace

void makeFolders(const std::string& path) {
  for (size_t i = 1; i <= path.size(); ++i)
    if (i == path.size() || path[i] == '/') mkdir(path.substr(0, i).c_str(), 0755);
}

std::string saveWhole(const std::string& path, const std::string& text, const std::string& what) {
  const size_t slash = path.find_last_of('/');
  const std::string folderPath = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::string failed = path + ": cannot write " + what + ": ";
  if (name.empty() || name == "." || name == "..") return failed + "not a file's name";
  if (slash != std::string::npos) makeFolders(folderPath);
  // Every step below is relative to the folder opened once: a folder swapped mid-save cannot move it.
  Fd folder{::open(folderPath.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
  if (folder.fd < 0) return failed + "its folder: " + reasonOf(errno);
  if (const std::string why = replaceProblem(folder.fd, name); !why.empty()) return failed + why;
  std::string temporary;
  Fd file{makeTemporary(folder.fd, name, temporary)};
  if (file.fd < 0) return failed + "cannot make a new file beside it: " + reasonOf(errno);
  const bool written = writeAll(file.fd, text);
  const int writeError = errno;
  close(file.fd);
  file.fd = -1;
  if (!written) {
    unlinkat(folder.fd, temporary.c_str(), 0);
    return failed + reasonOf(writeError);
  }
  // Checked again just before the rename: a link planted while the file was written is not replaced.
  std::string why = replaceProblem(folder.fd, name);
  if (why.empty() && renameat(folder.fd, temporary.c_str(), folder.fd, name.c_str()) != 0)
    why = "cannot replace it: " + reasonOf(errno);
  if (!why.empty()) {
    unlinkat(folder.fd, temporary.c_str(), 0);
    return failed + why;
  }
  ::fsync(folder.fd);  // the rename itself reaches the disk
  return "";
}

void saveWholeOrThrow(const std::string& path, const std::string& text, const std::string& what) {
  if (const std::string why = saveWhole(path, text, what); !why.empty()) throw std::runtime_error(why);
}

}  // namespace platon::files
