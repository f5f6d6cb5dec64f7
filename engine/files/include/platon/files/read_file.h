// Reading a whole file that a person or content names (a level, a script, a manifest, a replay, a
// scenario, a mesh, a JUnit report): it must be a regular file, not a FIFO that blocks the reader
// for ever (a tar archive can carry one), a device that never ends (/dev/zero) or a folder, and no
// larger than the reader allows. Both are checked on the opened file, before a byte is read, so a
// file swapped after a check is caught too.
//
// A file that content names by itself (a mesh's material library, a glTF buffer) is read with
// readFileInside: the name is resolved beneath the content's folder by the kernel (openat2 with
// RESOLVE_BENEATH), so "..", an absolute name or a link that leads out of the folder is refused at
// the open itself, with nothing outside ever opened.
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
// path); returns its size.
size_t checkBoundedFile(const std::string& path, size_t maxBytes);

// The bytes of `name`, a path relative to `folder` as content wrote it, read only if it resolves
// inside `folder` (links followed, but never out of it; no "..", no absolute name) and is a regular
// file of at most maxBytes. Throws FileError naming folder/name.
std::string readFileInside(const std::string& folder, const std::string& name, size_t maxBytes);

}  // namespace platon::files
