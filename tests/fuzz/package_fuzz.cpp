// libFuzzer target: the package reader (what `platon install` unpacks) and the filter of what a
// package carries. The input's bytes are either an archive as they are, or (most inputs) a recipe
// for one that gets past the gzip and tar layers: entries of every kind (files, folders, links,
// hard links, devices, FIFOs) under names made of plain and hostile parts ("..", "/", "~", long,
// doubled), with or without a manifest whose sizes and hashes are right, off by one, or listed
// twice. Invariants:
//  - the reader either returns a manifest or throws PackageError, nothing else;
//  - refused, it leaves nothing: the folder it was to make does not exist;
//  - read, the folder holds exactly the manifest's files, each a regular file (no link, no
//    device) whose size and SHA-256 are the manifest's, under FOLDER/;
//  - never is anything made or changed outside that folder (a sentinel file beside it is checked);
//  - the filter of what a package carries (removeUncarriedFiles) either throws an error that says
//    where, or leaves only files of the carried kinds, never touching anything outside the folder.
// Anything else (a crash, a sanitizer report) is a bug.
#include <archive.h>
#include <archive_entry.h>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

#include "fuzz_bug.h"
#include "fuzz_bytes.h"
#include "platon/package/package.h"

using namespace platon;
namespace fs = std::filesystem;

namespace {

const char* const kParts[] = {"lvl",       "scene.lua",  "finish.replay", "level.lua", "a.level", "..",
                              ".",         "",           "x/../..",       "/etc",      "~",       "sub",
                              "README.md", "test_1.lua", "run.sh",        ".hidden"};

std::string nameOf(Bytes& in) {
  std::string name;
  const int parts = 1 + in.next() % 4;
  for (int i = 0; i < parts; ++i) {
    const uint8_t b = in.next();
    if (i) name += (b & 0x80) ? "//" : "/";
    if ((b & 0x70) == 0x70) {
      name += std::string(1 + in.next() % 250, 'n');  // long parts
    } else {
      name += kParts[b % (sizeof kParts / sizeof *kParts)];
    }
  }
  return name;
}

struct Entry {
  std::string path, bytes, link;
  unsigned type = AE_IFREG;
};

// An archive from the recipe: entries, then (usually) a manifest listing the regular ones, its
// sizes and hashes right unless the recipe spoils one.
std::string archiveOf(Bytes& in) {
  std::vector<Entry> entries;
  const int count = in.next() % 12;
  for (int i = 0; i < count; ++i) {
    Entry e;
    e.path = (in.next() & 1 ? "lvl/" : "") + nameOf(in);
    const uint8_t kind = in.next() % 10;
    e.type = kind < 6 ? AE_IFREG : kind == 6 ? AE_IFDIR : kind == 7 ? AE_IFLNK : kind == 8 ? AE_IFIFO : AE_IFCHR;
    if (e.type == AE_IFLNK) e.link = nameOf(in);
    if (e.type == AE_IFREG) {
      const size_t n = in.next() % 64;
      for (size_t k = 0; k < n; ++k) e.bytes += static_cast<char>(in.next());
    }
    entries.push_back(std::move(e));
  }
  std::vector<package::PackageFile> listed;
  for (const Entry& e : entries)
    if (e.type == AE_IFREG && e.path.rfind("lvl/", 0) == 0)
      listed.push_back({e.path.substr(4), e.bytes.size(), package::sha256Hex(e.bytes)});
  const uint8_t spoil = in.next();
  if (!listed.empty() && (spoil & 3) == 1) listed[spoil % listed.size()].bytes += 1;
  if (!listed.empty() && (spoil & 3) == 2) listed[spoil % listed.size()].sha256[0] ^= 1;
  if (!listed.empty() && (spoil & 12) == 4) listed.push_back(listed.front());
  package::PackageManifest m;
  m.name = "fuzz";
  m.folder = (spoil & 16) ? "../lvl" : "lvl";
  m.files = listed;
  m.hash = package::manifestHash(listed);
  const bool manifestFirst = (spoil & 32) == 0, withManifest = (spoil & 64) == 0;

  std::string out;
  archive* a = archive_write_new();
  archive_write_add_filter_gzip(a);
  archive_write_set_format_pax_restricted(a);
  archive_write_open(
      a, &out, nullptr,
      [](archive*, void* to, const void* buffer, size_t n) -> la_ssize_t {
        static_cast<std::string*>(to)->append(static_cast<const char*>(buffer), n);
        return static_cast<la_ssize_t>(n);
      },
      nullptr);
  auto add = [&](const Entry& e) {
    archive_entry* entry = archive_entry_new();
    archive_entry_set_pathname(entry, e.path.c_str());
    archive_entry_set_filetype(entry, e.type);
    archive_entry_set_perm(entry, 0644);
    archive_entry_set_size(entry, static_cast<la_int64_t>(e.bytes.size()));
    if (!e.link.empty()) archive_entry_set_symlink(entry, e.link.c_str());
    if (archive_write_header(a, entry) == ARCHIVE_OK && !e.bytes.empty())
      archive_write_data(a, e.bytes.data(), e.bytes.size());
    archive_entry_free(entry);
  };
  const Entry manifest{"package.lua", package::manifestText(m), "", AE_IFREG};
  if (withManifest && manifestFirst) add(manifest);
  for (const Entry& e : entries) add(e);
  if (withManifest && !manifestFirst) add(manifest);
  archive_write_close(a);
  archive_write_free(a);
  return out;
}

// Every file under `dir`, by its path inside it, with its kind checked.
std::set<std::string> filesUnder(const fs::path& dir, const std::string& text) {
  std::set<std::string> out;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) {
    const fs::file_status s = e.symlink_status();
    if (fs::is_directory(s)) continue;
    if (!fs::is_regular_file(s))
      bug("the reader left something that is not a regular file: " + e.path().string(), text);
    out.insert(e.path().lexically_relative(dir).generic_string());
  }
  return out;
}

std::string contents(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fs::path root = fs::temp_directory_path() / ("platon_package_fuzz_" + std::to_string(getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "levels");
  std::ofstream(root / "levels" / "sentinel.txt") << "untouched\n";
  Bytes in{data, size};
  const bool raw = size > 0 && (data[0] & 7) == 7;
  if (raw) in.next();
  const std::string archive = raw ? std::string(reinterpret_cast<const char*>(data) + 1, size - 1) : archiveOf(in);
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::ofstream(root / "in.platon", std::ios::binary) << archive;
  const fs::path into = root / "levels" / ".installing";
  package::PackageManifest m;
  bool read = false;
  try {
    m = package::readPackage((root / "in.platon").string(), into.string());
    read = true;
  } catch (const package::PackageError&) {
    if (fs::exists(fs::symlink_status(into))) bug("a refused package left its folder", text);
  }
  // Nothing beside the folder: the sentinel as it was, nothing else made.
  std::set<std::string> beside;
  for (const fs::directory_entry& e : fs::directory_iterator(root / "levels")) beside.insert(e.path().filename());
  if (contents(root / "levels" / "sentinel.txt") != "untouched\n") bug("the sentinel beside the folder changed", text);
  for (const std::string& name : beside)
    if (name != "sentinel.txt" && name != ".installing") bug("the reader made " + name + " beside its folder", text);
  if (fs::exists(root / "etc") || fs::exists(root / "lvl")) bug("the reader wrote outside its folder", text);
  if (read) {
    std::set<std::string> listed;
    for (const package::PackageFile& f : m.files) {
      listed.insert(m.folder + "/" + f.path);
      const std::string bytes = contents(into / m.folder / f.path);
      if (bytes.size() != f.bytes || package::sha256Hex(bytes) != f.sha256)
        bug("a file read is not the manifest's: " + f.path, text);
    }
    if (filesUnder(into, text) != listed) bug("the folder does not hold exactly the manifest's files", text);
    try {
      (void)package::removeUncarriedFiles((into / m.folder).string());
      for (const std::string& f : filesUnder(into / m.folder, text)) {
        const std::string ending = fs::path(f).extension().string();
        if (ending != ".lua" && ending != ".level" && ending != ".replay" && ending != ".md" && ending != ".txt" &&
            ending != ".obj" && ending != ".mtl" && ending != ".gltf" && ending != ".glb" && ending != ".bin" &&
            ending != ".ply" && ending != ".stl")
          bug("the filter kept " + f, text);
      }
    } catch (const std::runtime_error& e) {
      const std::string why = e.what();
      if (why.find("scene.lua") == std::string::npos) bug("the filter's error names no file: " + why, text);
    }
  }
  fs::remove_all(root);
  return 0;
}
