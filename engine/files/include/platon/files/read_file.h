// Reading a whole file that a person or content names (a level, a script, a manifest, a replay, a
// scenario, a mesh, a JUnit report): it must be a regular file, not a FIFO that blocks the reader
// for ever (a tar archive can carry one), a device that never ends (/dev/zero) or a folder, and no
// larger than the reader allows. Both are checked on the opened file, before a byte is read, so a
// file swapped after a check is caught too.
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>

namespace platon::files {

// Why a file cannot be read: what() is "path: reason"; the parts apart, so a caller can put the
// place that named the file in front.
class FileError : public std::runtime_error {
 public:
  FileError(std::string path, std::string reason)
      : std::runtime_error(path + ": " + reason), path_(std::move(path)), reason_(std::move(reason)) {}
  const std::string& path() const { return path_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string path_, reason_;
};

// The file's bytes. Throws FileError (cannot be opened, is not a regular file, is larger than
// maxBytes, a read failed).
std::string readBoundedFile(const std::string& path, size_t maxBytes);

// Checks what readBoundedFile checks without reading (for a file another library reads by its
// path, as assimp does); returns its size.
size_t checkBoundedFile(const std::string& path, size_t maxBytes);

}  // namespace platon::files
