// A file descriptor closed when it goes out of scope (the file layer's reads and saves).
#pragma once
#include <fcntl.h>
#include <unistd.h>

namespace platon::files {

// How content's files are opened for reading. O_NONBLOCK: opening a FIFO with no writer would
// otherwise wait for one for ever.
inline constexpr int kReadFlags = O_RDONLY | O_NONBLOCK | O_CLOEXEC;

struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) close(fd);
  }
};

}  // namespace platon::files
