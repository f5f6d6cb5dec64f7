// Level packages (engine/package): a package round-trips, and every hostile one is refused before
// a byte lands outside the folder it unpacks into. Each archive here is made by hand with
// libarchive, as an attacker would make it.
#include "platon/package/package.h"

#include <algorithm>
#include <archive.h>
#include <archive_entry.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sys/stat.h>

#include <gtest/gtest.h>

#include "platon/testing/temp_folder.h"

namespace platon::package {
namespace {

namespace fs = std::filesystem;

struct Entry {
  std::string path;
  std::string bytes = {};
  mode_t type = AE_IFREG;
  std::string link = {};  // a symlink's target or a hard link's
};

// A gzipped tar of `entries`, in order.
void writeArchive(const std::string& out, const std::vector<Entry>& entries) {
  archive* a = archive_write_new();
  archive_write_add_filter_gzip(a);
  archive_write_set_format_pax_restricted(a);
  ASSERT_EQ(archive_write_open_filename(a, out.c_str()), ARCHIVE_OK);
  for (const Entry& e : entries) {
    archive_entry* entry = archive_entry_new();
    archive_entry_set_pathname(entry, e.path.c_str());
    archive_entry_set_filetype(entry, e.type);
    archive_entry_set_perm(entry, 0644);
    if (e.type == AE_IFLNK) archive_entry_set_symlink(entry, e.link.c_str());
    if (!e.link.empty() && e.type == AE_IFREG) archive_entry_set_hardlink(entry, e.link.c_str());
    archive_entry_set_size(entry, static_cast<la_int64_t>(e.bytes.size()));
    archive_write_header(a, entry);
    if (!e.bytes.empty()) archive_write_data(a, e.bytes.data(), e.bytes.size());
    archive_entry_free(entry);
  }
  archive_write_close(a);
  archive_write_free(a);
}

// The manifest of files (path, bytes), folder "lvl".
PackageManifest manifestOf(const std::vector<std::pair<std::string, std::string>>& files,
                           const std::string& folder = "lvl") {
  PackageManifest m;
  m.name = "A level";
  m.folder = folder;
  for (const auto& [path, bytes] : files) m.files.push_back({path, bytes.size(), sha256Hex(bytes)});
  std::sort(m.files.begin(), m.files.end(), [](const auto& a, const auto& b) { return a.path < b.path; });
  m.hash = manifestHash(m.files);
  return m;
}

const std::vector<std::pair<std::string, std::string>> kFiles = {
    {"scene.lua", "return { systems = { 'scripting' } }\n"}, {"finish.replay", "platon replay 1\n"}};

// Entries of an honest package of kFiles.
std::vector<Entry> honest() {
  std::vector<Entry> e = {{"package.lua", manifestText(manifestOf(kFiles))}};
  for (const auto& [path, bytes] : kFiles) e.push_back({"lvl/" + path, bytes});
  return e;
}

class Packages : public ::testing::Test {
 protected:
  testing::TempFolder folder{"packages"};
  // Unpacks `entries` as a package: "" when it was taken, else the error. Checks that nothing but
  // the folder to unpack into was made, and that it is gone after a refusal.
  std::string unpack(const std::vector<Entry>& entries) {  // NOLINT(readability-function-cognitive-complexity)
    const std::string archive = folder.path("u/p" + std::to_string(++count_) + ".platon");
    fs::create_directories(folder.path("u"));
    writeArchive(archive, entries);
    const std::string into = folder.path("u/into" + std::to_string(count_));
    std::string error;
    try {
      readPackage(archive, into);
    } catch (const PackageError& e) {
      error = e.what();
      EXPECT_FALSE(fs::exists(into)) << "a refused package left " << into;
    }
    EXPECT_FALSE(fs::exists("/tmp/platon_evil"));
    for (const auto& entry : fs::directory_iterator(folder.path("u")))
      EXPECT_TRUE(entry.path().filename().string().rfind('p', 0) == 0 ||
                  entry.path().filename().string().rfind("into", 0) == 0)
          << "written outside: " << entry.path();
    return error;
  }
  int count_ = 0;
};

TEST_F(Packages, AnHonestPackageRoundTrips) {
  fs::create_directories(folder.path("src/lvl/sub"));
  std::ofstream(folder.path("src/lvl/scene.lua")) << "return {}\n";
  std::ofstream(folder.path("src/lvl/finish.replay")) << "platon replay 1\n";
  std::ofstream(folder.path("src/lvl/sub/mesh.obj")) << "v 0 0 0\n";
  const PackageManifest written = writePackage(folder.path("src"), "lvl", "Mine", folder.path("lvl.platon"));
  ASSERT_EQ(written.files.size(), 3u);
  const PackageManifest read = readPackage(folder.path("lvl.platon"), folder.path("out"));
  EXPECT_EQ(read.hash, written.hash);
  EXPECT_EQ(read.name, "Mine");
  std::ifstream mesh(folder.path("out/lvl/sub/mesh.obj"));
  std::string line;
  std::getline(mesh, line);
  EXPECT_EQ(line, "v 0 0 0");
  // The same files make the same package, byte for byte.
  writePackage(folder.path("src"), "lvl", "Mine", folder.path("again.platon"));
  std::ifstream a(folder.path("lvl.platon"), std::ios::binary), b(folder.path("again.platon"), std::ios::binary);
  EXPECT_TRUE(std::equal(std::istreambuf_iterator<char>(a), {}, std::istreambuf_iterator<char>(b)));
  EXPECT_EQ(unpack(honest()), "");
}

TEST_F(Packages, WritingRefusesLinksAndOddNames) {
  fs::create_directories(folder.path("src/lvl"));
  std::ofstream(folder.path("src/lvl/scene.lua")) << "return {}\n";
  fs::create_symlink("/etc/passwd", folder.path("src/lvl/passwd"));
  EXPECT_THROW(writePackage(folder.path("src"), "lvl", "x", folder.path("o.platon")), PackageError);
  fs::remove(folder.path("src/lvl/passwd"));
  std::ofstream(folder.path("src/lvl/.hidden")) << "x";
  EXPECT_THROW(writePackage(folder.path("src"), "lvl", "x", folder.path("o.platon")), PackageError);
  EXPECT_THROW(writePackage(folder.path("src"), "..", "x", folder.path("o.platon")), PackageError);
}

// Every way out of the folder, and every lie about the files: refused, naming why.
TEST_F(Packages, EveryHostileArchiveIsRefusedAndLeavesNothing) {
  const std::string scene = kFiles[0].second;
  struct Case {
    const char* what;
    std::function<void(std::vector<Entry>&)> change;
    const char* expected;
  };
  const Case cases[] = {
      {"a parent step",
       [](auto& e) {
         e.push_back({"lvl/../evil", "x"});
       },
       "'lvl/../evil'"},
      {"an absolute path",
       [](auto& e) {
         e.push_back({"/tmp/platon_evil", "x"});
       },
       "outside the package's folder"},
      {"another folder",
       [](auto& e) {
         e.push_back({"other/x", "x"});
       },
       "outside the package's folder"},
      {"a symlink",
       [](auto& e) {
         e.insert(e.begin() + 1, {"lvl/link", "", AE_IFLNK, "/etc"});
       },
       "a link"},
      {"a hard link",
       [](auto& e) {
         e.insert(e.begin() + 1, {"lvl/hard", "", AE_IFREG, "/etc/passwd"});
       },
       "regular files only"},
      {"a fifo",
       [](auto& e) {
         e.insert(e.begin() + 1, {"lvl/fifo", "", AE_IFIFO});
       },
       "not a regular file"},
      {"a device",
       [](auto& e) {
         e.insert(e.begin() + 1, {"lvl/dev", "", AE_IFCHR});
       },
       "not a regular file"},
      {"a hidden file",
       [](auto& e) {
         e.push_back({"lvl/.bashrc", "x"});
       },
       "starting with '.'"},
      {"a file not in the manifest",
       [](auto& e) {
         e.push_back({"lvl/extra.lua", "x"});
       },
       "not in its manifest"},
      {"a file twice", [](auto& e) { e.push_back(e[1]); }, "twice"},
      {"a file under a file (found by package_fuzz: the filesystem's own exception escaped)",
       [](auto& e) {
         auto files = kFiles;
         files.push_back({"scene.lua/x", "x"});
         e = {{"package.lua", manifestText(manifestOf(files))}};
         for (const auto& [path, bytes] : files) e.push_back({"lvl/" + path, bytes});
       },
       "cannot make its folder"},
      {"a changed file", [](auto& e) { e[1].bytes[0] ^= 1; }, "not the file its manifest hashed"},
      {"a longer file", [](auto& e) { e[1].bytes += "more"; }, "larger than"},
      {"a shorter file", [](auto& e) { e[1].bytes.pop_back(); }, "its manifest says"},
      {"a missing file", [](auto& e) { e.pop_back(); }, "in its manifest but not in it"},
      {"the manifest not first", [](auto& e) { std::swap(e[0], e[1]); }, "not package.lua"},
      {"no manifest", [](auto& e) { e.erase(e.begin()); }, "not package.lua"},
      {"a tampered manifest hash",
       [](auto& e) {
         auto m = manifestOf(kFiles);
         m.hash[0] = m.hash[0] == 'a' ? 'b' : 'a';
         e[0].bytes = manifestText(m);
       },
       "the manifest was changed"},
      {"a manifest listing a file it does not hash",
       [&](auto& e) {
         auto m = manifestOf(kFiles);
         m.files[0].sha256 = sha256Hex("something else");
         m.hash = manifestHash(m.files);
         e[0].bytes = manifestText(m);
       },
       "not the file its manifest hashed"},
      {"a manifest folder '..'",
       [&](auto& e) {
         auto m = manifestOf(kFiles);
         m.folder = "..";
         e[0].bytes = manifestText(m);
       },
       "not a plain folder name"},
      {"a manifest path with '..'",
       [&](auto& e) {
         auto files = kFiles;
         files.push_back({"../x", "x"});
         e[0].bytes = manifestText(manifestOf(files));
       },
       "a part starting with '.'"},
      {"a manifest that is code", [](auto& e) { e[0].bytes = "os.execute('rm -rf /')\nreturn {}"; }, "package.lua"},
      {"a package without its run",
       [&](auto& e) {
         e[0].bytes = manifestText(manifestOf({kFiles[0]}));
         e.pop_back();
       },
       "finish.replay"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    std::vector<Entry> e = honest();
    c.change(e);
    const std::string error = unpack(e);
    EXPECT_NE(error, "") << "taken";
    EXPECT_NE(error.find(c.expected), std::string::npos) << error;
  }
  (void)scene;
}

// A file that unpacks to far more than its manifest says is cut at that size: the reader never
// holds more than a listed size (a gzip bomb costs what the manifest allows, no more).
TEST_F(Packages, AGzipBombIsStoppedAtItsListedSize) {
  std::vector<Entry> e = honest();
  e[1].bytes = std::string(size_t{200} << 20, '\0');  // 200 MB of zeros: about 200 KB gzipped
  const std::string error = unpack(e);
  EXPECT_NE(error.find("larger than"), std::string::npos) << error;
}

TEST_F(Packages, WhatIsNoPackageIsSaidSo) {
  std::ofstream(folder.path("text.platon")) << "hello";
  EXPECT_THROW(readPackage(folder.path("text.platon"), folder.path("a")), PackageError);
  { std::ofstream empty(folder.path("empty.platon")); }
  EXPECT_THROW(readPackage(folder.path("empty.platon"), folder.path("b")), PackageError);
  ASSERT_EQ(mkfifo(folder.path("fifo.platon").c_str(), 0600), 0);
  try {  // asked what it is before it is opened: a FIFO would block the reader
    readPackage(folder.path("fifo.platon"), folder.path("c"));
    ADD_FAILURE() << "read a FIFO";
  } catch (const PackageError& e) {
    EXPECT_NE(std::string(e.what()).find("not a package"), std::string::npos) << e.what();
  }
  EXPECT_THROW(readPackage(folder.path("missing.platon"), folder.path("d")), PackageError);
  // An existing folder is never unpacked into.
  writeArchive(folder.path("ok.platon"), honest());
  fs::create_directories(folder.path("exists"));
  EXPECT_THROW(readPackage(folder.path("ok.platon"), folder.path("exists")), PackageError);
}

}  // namespace
}  // namespace platon::package
