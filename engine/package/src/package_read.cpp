// Reading a package: every entry checked before a byte of it is written, into a folder made for
// it. What a hostile archive may try, and why it cannot: a path with "..", "/..." or odd parts
// (pathProblem refuses it), a link or a device (only regular files and folders are taken), a name
// the manifest does not list or lists once but the archive holds twice (refused), a file larger
// than its size (read at most that, then refused), a gzip bomb (no file is read past its listed
// size, and the listed sizes are capped), a file whose bytes are not its hash (refused). Files are
// created with O_EXCL and O_NOFOLLOW inside the new folder, so nothing is followed out of it.
#include <archive.h>
#include <archive_entry.h>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <unistd.h>

#include "package_paths.h"
#include "platon/files/read_file.h"
#include "platon/package/package.h"

namespace platon::package {
namespace {

namespace fs = std::filesystem;

struct Reader {
  archive* a = archive_read_new();
  ~Reader() { archive_read_free(a); }
};

// The entry's data, refused past `limit` bytes.
std::string readData(archive* a, uint64_t limit, const std::string& what) {
  std::string bytes;
  char buffer[65536];
  for (;;) {
    const la_ssize_t n = archive_read_data(a, buffer, sizeof buffer);
    if (n < 0) throw PackageError(what + ": " + archive_error_string(a));
    if (n == 0) return bytes;
    if (bytes.size() + static_cast<size_t>(n) > limit)
      throw PackageError(what + ": larger than " + std::to_string(limit) + " bytes");
    bytes.append(buffer, static_cast<size_t>(n));
  }
}

void writeNew(const fs::path& path, const std::string& bytes) {
  // A folder where the archive put a file already (scene.lua, then scene.lua/x) is the package's
  // error, said as such (package_fuzz found the filesystem's own exception escaping).
  std::error_code error;
  fs::create_directories(path.parent_path(), error);
  if (error) throw PackageError(path.string() + ": cannot make its folder (" + error.message() + ")");
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) throw PackageError(path.string() + ": cannot create it");
  const bool ok = ::write(fd, bytes.data(), bytes.size()) == static_cast<ssize_t>(bytes.size());
  ::close(fd);
  if (!ok) throw PackageError(path.string() + ": cannot write it");
}

// The manifest, read from the package's first entry (which must be it).
PackageManifest firstEntryManifest(archive* a, const std::string& name, mode_t type, const std::string& archivePath) {
  const std::string at = archivePath + ": ";
  if (name != "package.lua" || type != AE_IFREG)
    throw PackageError(at + "not a package: its first entry is '" + name.substr(0, 80) + "', not package.lua");
  PackageManifest manifest = parseManifest(readData(a, 1 << 20, at + "package.lua"), archivePath + ":package.lua");
  uint64_t total = 0;
  std::set<std::string> paths;
  for (const PackageFile& f : manifest.files) total += f.bytes, paths.insert(f.path);
  if (total > kMaxTotalBytes) throw PackageError(at + "its files add up to more than a package holds");
  if (!paths.count("scene.lua") || !paths.count("finish.replay"))
    throw PackageError(at + "a package holds its level's scene.lua and finish.replay, a run to its goal");
  return manifest;
}

// The path inside the package's folder of an entry after the manifest, which must be a regular
// file there; "" for a folder there (made as its files need it).
std::string entryPath(archive_entry* entry, const std::string& name, mode_t type, const std::string& folder,
                      const std::string& at) {
  const std::string prefix = folder + "/";
  if (type == AE_IFDIR && (name == prefix || name.rfind(prefix, 0) == 0)) return "";
  if (name.rfind(prefix, 0) != 0)
    throw PackageError(at + "'" + name.substr(0, 80) + "' lies outside the package's folder " + prefix);
  std::string path = name.substr(prefix.size());
  if (const std::string why = pathProblem(path); !why.empty())
    throw PackageError(at + "'" + name.substr(0, 80) + "': " + why);
  if (type != AE_IFREG)
    throw PackageError(at + "'" + name + "' is " +
                       (type == AE_IFLNK   ? "a link"
                        : type == AE_IFDIR ? "a folder"
                                           : "not a regular file") +
                       ": a package holds regular files only");
  if (archive_entry_hardlink(entry)) throw PackageError(at + "'" + name + "' is a hard link: regular files only");
  return path;
}

PackageManifest unpack(const std::string& archivePath, const fs::path& into) {
  Reader r;
  archive_read_support_filter_gzip(r.a);
  archive_read_support_format_tar(r.a);
  if (archive_read_open_filename(r.a, archivePath.c_str(), 65536) != ARCHIVE_OK)
    throw PackageError(archivePath + ": not a package (" + archive_error_string(r.a) + ")");
  const std::string at = archivePath + ": ";
  std::optional<PackageManifest> manifest;
  std::map<std::string, const PackageFile*> expected;
  archive_entry* entry = nullptr;
  size_t entries = 0;
  for (;;) {
    const int status = archive_read_next_header(r.a, &entry);
    if (status == ARCHIVE_EOF) break;
    if (status != ARCHIVE_OK) throw PackageError(at + "not a package (" + archive_error_string(r.a) + ")");
    if (++entries > 2 * kMaxFiles + 2) throw PackageError(at + "more entries than a package holds");
    const char* raw = archive_entry_pathname(entry);
    const std::string name = raw ? raw : "";
    const mode_t type = archive_entry_filetype(entry);
    if (!manifest) {
      manifest = firstEntryManifest(r.a, name, type, archivePath);
      for (const PackageFile& f : manifest->files) expected[f.path] = &f;
      continue;
    }
    const std::string path = entryPath(entry, name, type, manifest->folder, at);
    if (path.empty()) continue;
    const auto found = expected.find(path);
    if (found == expected.end()) throw PackageError(at + "'" + name + "' is not in its manifest");
    if (!found->second) throw PackageError(at + "'" + name + "' is in it twice");
    const PackageFile& f = *found->second;
    found->second = nullptr;
    const std::string bytes = readData(r.a, f.bytes, at + name);
    if (bytes.size() != f.bytes)
      throw PackageError(at + "'" + name + "' has " + std::to_string(bytes.size()) + " bytes, its manifest says " +
                         std::to_string(f.bytes));
    if (sha256Hex(bytes) != f.sha256) throw PackageError(at + "'" + name + "' is not the file its manifest hashed");
    writeNew(into / manifest->folder / path, bytes);
  }
  if (!manifest) throw PackageError(at + "not a package: it is empty");
  for (const auto& [path, file] : expected)
    if (file) throw PackageError(at + "'" + manifest->folder + "/" + path + "' is in its manifest but not in it");
  return *manifest;
}

}  // namespace

PackageManifest readPackage(const std::string& archive, const std::string& into) {
  try {  // a FIFO, a device or a folder is no package: asked before it is opened
    files::checkBoundedFile(archive, kMaxTotalBytes + (uint64_t{16} << 20));
  } catch (const files::FileError& e) {
    throw PackageError(archive + ": not a package: " + e.reason());
  }
  std::error_code error;
  if (fs::exists(into, error) || !fs::create_directories(into, error))
    throw PackageError(into + ": the folder to unpack into must be new");
  try {
    return unpack(archive, into);
  } catch (...) {
    fs::remove_all(into, error);
    throw;
  }
}

}  // namespace platon::package
