// A file descriptor closed when it goes out of scope (the file layer's reads and saves).
#pragma once
#include <unistd.h>

namespace platon::files {

struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) close(fd);
  }
};

}  // namespace platon::files
