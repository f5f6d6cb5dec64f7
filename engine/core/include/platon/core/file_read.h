// Reading a whole file that a person or content names (a JUnit report, a level, a manifest...):
// it must be a regular file, not a FIFO that blocks the reader for ever, a device that never ends
// (/dev/zero) or a folder, and no larger than the reader allows. Both are checked on the opened
// file (so a file swapped after a check is still caught) before a byte is read.
#pragma once
#include <cstddef>
#include <string>

namespace platon::core {

// The file's bytes. Throws std::runtime_error "path: why" (cannot be opened, is not a regular file,
// is larger than maxBytes, a read failed).
std::string readBoundedFile(const std::string& path, size_t maxBytes);

}  // namespace platon::core
