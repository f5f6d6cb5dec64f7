// Writing a package: the level's regular files, hashed, into a gzipped tar through libarchive.
#include <algorithm>
#include <archive.h>
#include <archive_entry.h>
#include <filesystem>
#include <memory>

#include "package_paths.h"
#include "platon/files/read_file.h"
#include "platon/package/package.h"

namespace platon::package {
namespace {

namespace fs = std::filesystem;

struct Writer {
  archive* a = archive_write_new();
  ~Writer() { archive_write_free(a); }
};

void add(archive* a, const std::string& path, const std::string& bytes, const std::string& out) {
  std::unique_ptr<archive_entry, decltype(&archive_entry_free)> entry(archive_entry_new(), archive_entry_free);
  archive_entry_set_pathname(entry.get(), path.c_str());
  archive_entry_set_filetype(entry.get(), AE_IFREG);
  archive_entry_set_perm(entry.get(), 0644);
  archive_entry_set_size(entry.get(), static_cast<la_int64_t>(bytes.size()));
  archive_entry_set_mtime(entry.get(), 0, 0);  // the same files make the same package
  if (archive_write_header(a, entry.get()) != ARCHIVE_OK ||
      archive_write_data(a, bytes.data(), bytes.size()) != static_cast<la_ssize_t>(bytes.size()))
    throw PackageError(out + ": cannot write " + path + ": " + archive_error_string(a));
}

}  // namespace

PackageManifest writePackage(const std::string& root, const std::string& folder, const std::string& name,
                             const std::string& out) {
  if (!plainName(folder)) throw PackageError(folder + ": not a plain folder name (letters, digits, '.', '-' and '_')");
  const fs::path dir = fs::path(root) / folder;
  PackageManifest m;
  m.name = name;
  m.folder = folder;
  std::vector<std::pair<std::string, std::string>> contents;  // path, bytes
  uint64_t total = 0;
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(dir, error); !error && it != fs::recursive_directory_iterator();
       it.increment(error)) {
    const fs::path rel = it->path().lexically_relative(dir);
    const fs::file_status status = it->symlink_status();
    if (fs::is_directory(status)) continue;
    if (fs::is_symlink(status))
      throw PackageError(it->path().string() + ": a link: a package holds regular files only (copy the file in)");
    if (!fs::is_regular_file(status)) throw PackageError(it->path().string() + ": not a regular file");
    const std::string path = rel.generic_string();
    if (const std::string why = pathProblem(path); !why.empty())
      throw PackageError(it->path().string() + ": a package cannot hold this name: " + why);
    std::string bytes;
    try {
      bytes = files::readBoundedFile(it->path().string(), kMaxFileBytes);
    } catch (const files::FileError& e) {
      throw PackageError(e.what());
    }
    total += bytes.size();
    if (contents.size() >= kMaxFiles || total > kMaxTotalBytes)
      throw PackageError(dir.string() + ": more than a package holds (" + std::to_string(kMaxFiles) + " files, " +
                         std::to_string(kMaxTotalBytes >> 20) + " MB)");
    m.files.push_back({path, bytes.size(), sha256Hex(bytes)});
    contents.emplace_back(path, std::move(bytes));
  }
  if (error) throw PackageError(dir.string() + ": " + error.message());
  std::sort(m.files.begin(), m.files.end(), [](const PackageFile& a, const PackageFile& b) { return a.path < b.path; });
  std::sort(contents.begin(), contents.end());
  m.hash = manifestHash(m.files);
  const std::string partial = out + ".partial";
  {
    Writer w;
    if (archive_write_add_filter_gzip(w.a) != ARCHIVE_OK ||
        archive_write_set_format_pax_restricted(w.a) != ARCHIVE_OK ||
        archive_write_open_filename(w.a, partial.c_str()) != ARCHIVE_OK)
      throw PackageError(out + ": cannot write it: " + archive_error_string(w.a));
    add(w.a, "package.lua", manifestText(m), out);  // first: the reader knows what to expect before any file
    for (const auto& [path, bytes] : contents) add(w.a, folder + "/" + path, bytes, out);
    if (archive_write_close(w.a) != ARCHIVE_OK) throw PackageError(out + ": " + archive_error_string(w.a));
  }
  fs::rename(partial, out, error);
  if (error) throw PackageError(out + ": " + error.message());
  return m;
}

}  // namespace platon::package
