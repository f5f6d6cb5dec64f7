#include "platon/files/read_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace platon::files {

namespace {

struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) close(fd);
  }
};

std::string sizeText(unsigned long long bytes) {
  if (bytes >= (1ULL << 20)) return std::to_string(bytes >> 20) + " MB";
  return std::to_string(bytes) + " bytes";
}

// Opens `path` for reading, checked: a regular file of at most maxBytes. Returns its size.
size_t openChecked(const std::string& path, size_t maxBytes, Fd& file) {
  // O_NONBLOCK: opening a FIFO with no writer would otherwise wait for one for ever.
  file.fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (file.fd < 0) throw FileError(path, std::string("cannot open it: ") + std::strerror(errno));
  struct stat st {};
  if (fstat(file.fd, &st) != 0) throw FileError(path, std::string("cannot read it: ") + std::strerror(errno));
  if (!S_ISREG(st.st_mode))
    throw FileError(path, std::string("not a regular file (") +
                              (S_ISDIR(st.st_mode)                          ? "a folder"
                               : S_ISFIFO(st.st_mode)                       ? "a FIFO"
                               : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                                                                            : "a socket or other special file") +
                              ")");
  const auto size = static_cast<unsigned long long>(st.st_size);
  if (size > maxBytes)
    throw FileError(path, sizeText(size) + ", more than the " + sizeText(maxBytes) + " such a file may have");
  return static_cast<size_t>(size);
}

}  // namespace

std::string readBoundedFile(const std::string& path, size_t maxBytes) {
  Fd file{-1};
  std::string bytes(openChecked(path, maxBytes, file), '\0');
  size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = read(file.fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw FileError(path, std::string("cannot read it: ") + std::strerror(errno));
    if (n == 0) break;  // shorter than it said: it shrank while read
    got += static_cast<size_t>(n);
  }
  bytes.resize(got);
  return bytes;
}

size_t checkBoundedFile(const std::string& path, size_t maxBytes) {
  Fd file{-1};
  return openChecked(path, maxBytes, file);
}

}  // namespace platon::files
