#include "platon/files/read_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "beneath.h"
#include "fd.h"

namespace platon::files {

namespace {

std::string sizeText(unsigned long long bytes) {
  if (bytes >= (1ULL << 20)) return std::to_string(bytes >> 20) + " MB";
  return std::to_string(bytes) + " bytes";
}

// Checks the opened file: a regular file of at most maxBytes. Returns its size.
size_t checkOpened(const std::string& path, size_t maxBytes, const Fd& file) {
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

size_t openChecked(const std::string& path, size_t maxBytes, Fd& file) {
  file.fd = open(path.c_str(), kReadFlags);
  if (file.fd < 0) throw FileError(path, std::string("cannot open it: ") + std::strerror(errno));
  return checkOpened(path, maxBytes, file);
}

// Fills `bytes` (sized to the file) from the file; shorter if the file shrank while read.
void readAll(const std::string& path, const Fd& file, std::string& bytes) {
  size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = read(file.fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw FileError(path, std::string("cannot read it: ") + std::strerror(errno));
    if (n == 0) break;
    got += static_cast<size_t>(n);
  }
  bytes.resize(got);
}

}  // namespace

std::string readBoundedFile(const std::string& path, size_t maxBytes) {
  Fd file{-1};
  std::string bytes(openChecked(path, maxBytes, file), '\0');
  readAll(path, file, bytes);
  return bytes;
}

size_t checkBoundedFile(const std::string& path, size_t maxBytes) {
  Fd file{-1};
  return openChecked(path, maxBytes, file);
}

std::string readInside(const std::string& folder, const std::string& name, size_t maxBytes,
                       int (*openName)(int, const std::string&)) {
  const std::string shown = folder + "/" + name;
  if (name.empty() || name[0] == '/')
    throw FileError(shown, "not a name inside the folder (empty or absolute): content names its own files");
  Fd dir{open(folder.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC)};
  if (dir.fd < 0) throw FileError(folder, std::string("cannot open the folder: ") + std::strerror(errno));
  Fd file{openName(dir.fd, name)};
  if (file.fd < 0) {
    if (errno == EXDEV || errno == ELOOP)
      throw FileError(shown, "leads out of its folder (through '..' or a link): content reads only its own folder");
    throw FileError(shown, std::string("cannot open it: ") + std::strerror(errno));
  }
  std::string bytes(checkOpened(shown, maxBytes, file), '\0');
  readAll(shown, file, bytes);
  return bytes;
}

std::string readFileInside(const std::string& folder, const std::string& name, size_t maxBytes) {
  return readInside(folder, name, maxBytes, openBeneath);
}

}  // namespace platon::files
