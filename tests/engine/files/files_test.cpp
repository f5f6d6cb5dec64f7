// The file layer: a save never writes through a link nor replaces anything but a regular file,
// whatever is planted beside the saved file and under whatever name; a file content names is read
// only beneath its folder, and only if it is a regular file. Families: every kind of planted thing
// (a link to a file, to a folder, dangling, a FIFO, a folder) under every name a save might use.
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "beneath.h"  // both ways of resolving
#include "platon/files/read_file.h"
#include "platon/files/write_file.h"
#include "platon/testing/temp_folder.h"

using namespace platon;
namespace fs = std::filesystem;

namespace {

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

enum class Planted { LinkToFile, LinkToFolder, DanglingLink, Fifo, Folder };
constexpr Planted kPlanted[] = {Planted::LinkToFile, Planted::LinkToFolder, Planted::DanglingLink, Planted::Fifo,
                                Planted::Folder};
const char* name(Planted p) {
  switch (p) {
    case Planted::LinkToFile:
      return "a link to a file outside";
    case Planted::LinkToFolder:
      return "a link to a folder outside";
    case Planted::DanglingLink:
      return "a link to a file not yet outside";
    case Planted::Fifo:
      return "a FIFO";
    case Planted::Folder:
      return "a folder";
  }
  return "";
}

// Plants `p` at `at`; what is outside lies in `outside`.
void plant(Planted p, const fs::path& at, const fs::path& outside) {
  switch (p) {
    case Planted::LinkToFile:
      fs::create_symlink(outside / "victim.txt", at);
      break;
    case Planted::LinkToFolder:
      fs::create_symlink(outside, at);
      break;
    case Planted::DanglingLink:
      fs::create_symlink(outside / "made.txt", at);
      break;
    case Planted::Fifo:
      ASSERT_EQ(mkfifo(at.c_str(), 0644), 0);
      break;
    case Planted::Folder:
      fs::create_directories(at / "inside");
      break;
  }
}

// What lies outside is as it was: the victim's text, nothing made, nothing added to the folder.
void expectOutsideUntouched(const fs::path& outside) {
  EXPECT_EQ(read((outside / "victim.txt").string()), "the player's own file\n");
  EXPECT_FALSE(fs::exists(outside / "made.txt"));
  size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(outside)) ++entries;
  EXPECT_EQ(entries, 1u);
}

}  // namespace

TEST(SaveWhole, NeverWritesThroughAnythingPlantedBesideTheFile) {
  for (const Planted p : kPlanted)
    for (const char* suffix : {".new", ".partial", ".tmp", "~", ".new-00000000", ".swp"}) {
      SCOPED_TRACE(std::string(name(p)) + " named x.level" + suffix);
      platon::testing::TempFolder folder("save_beside");
      folder.write("outside/victim.txt", "the player's own file\n");
      const fs::path level = folder.path("level");
      folder.write("level/x.level", "old\n");
      plant(p, level / (std::string("x.level") + suffix), folder.path("outside"));
      EXPECT_EQ(files::saveWhole((level / "x.level").string(), "new\n", "the level"), "");
      EXPECT_EQ(read((level / "x.level").string()), "new\n");
      EXPECT_FALSE(fs::is_symlink(level / "x.level"));
      expectOutsideUntouched(folder.path("outside"));
      EXPECT_TRUE(fs::exists(fs::symlink_status(level / (std::string("x.level") + suffix))));  // left as it was
    }
}

TEST(SaveWhole, RefusesToReplaceAnythingButARegularFile) {
  for (const Planted p : kPlanted) {
    SCOPED_TRACE(name(p));
    platon::testing::TempFolder folder("save_over");
    folder.write("outside/victim.txt", "the player's own file\n");
    const fs::path level = folder.path("level");
    fs::create_directories(level);
    plant(p, level / "x.level", folder.path("outside"));
    const std::string why = files::saveWhole((level / "x.level").string(), "new\n", "the level");
    EXPECT_EQ(why.rfind((level / "x.level").string() + ": cannot write the level: it is ", 0), 0u) << why;
    expectOutsideUntouched(folder.path("outside"));
    size_t entries = 0;  // no new file left behind
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(level)) ++entries;
    EXPECT_EQ(entries, 1u);
    EXPECT_THROW(files::saveWholeOrThrow((level / "x.level").string(), "new\n", "the level"), std::runtime_error);
  }
}

TEST(SaveWhole, WritesANewFileAndReplacesAnOldOne) {
  platon::testing::TempFolder folder("save_plain");
  const std::string path = folder.path("deep/er/settings.txt");  // folders made
  EXPECT_EQ(files::saveWhole(path, "a\n", "the settings"), "");
  EXPECT_EQ(read(path), "a\n");
  EXPECT_EQ(files::saveWhole(path, std::string(1 << 20, 'b'), "the settings"), "");
  EXPECT_EQ(read(path), std::string(1 << 20, 'b'));
  size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(folder.path("deep/er"))) ++entries;
  EXPECT_EQ(entries, 1u);                                                         // no temporary file left
  EXPECT_NE(files::saveWhole(folder.path("deep/er/"), "x", "the settings"), "");  // no file's name
}

// Both ways a name is resolved: the kernel's (openat2) and the walk where a kernel has none.
class ReadFileInside : public ::testing::TestWithParam<bool> {
 protected:
  static std::string read(const std::string& folder, const std::string& name, size_t maxBytes) {
    return GetParam() ? files::readInside(folder, name, maxBytes, files::openWalking)
                      : files::readFileInside(folder, name, maxBytes);
  }
};
INSTANTIATE_TEST_SUITE_P(ByTheKernelAndByTheWalk, ReadFileInside, ::testing::Bool());

TEST_P(ReadFileInside, RefusesEveryWayOutOfTheFolderAndEveryFileThatIsNotRegular) {
  platon::testing::TempFolder folder("inside");
  folder.write("outside/secret.txt", "secret\n");
  const std::string level = folder.path("level");
  folder.write("level/a.mtl", "inside\n");
  folder.write("level/sub/b.mtl", "deeper\n");
  fs::create_symlink("sub/b.mtl", fs::path(level) / "link_in.mtl");
  fs::create_symlink("../a.mtl", fs::path(level) / "sub/up_in.mtl");
  fs::create_symlink(folder.path("outside/secret.txt"), fs::path(level) / "link_out.mtl");
  fs::create_symlink("../outside/secret.txt", fs::path(level) / "relative_out.mtl");
  fs::create_symlink(folder.path("outside"), fs::path(level) / "folder_out");
  fs::create_symlink("/dev/zero", fs::path(level) / "zero.bin");
  fs::create_symlink("sub", fs::path(level) / "sub_link");           // a folder inside
  fs::create_symlink("link_in.mtl", fs::path(level) / "chain.mtl");  // a link to a link inside
  fs::create_symlink("loop_b.mtl", fs::path(level) / "loop_a.mtl");  // a loop
  fs::create_symlink("loop_a.mtl", fs::path(level) / "loop_b.mtl");
  fs::create_symlink("../../outside/secret.txt", fs::path(level) / "sub/up_out.mtl");  // out, from below
  fs::create_symlink("../sub_link/../../outside", fs::path(level) / "sub/twisted");    // out, by a link inside
  ASSERT_EQ(mkfifo((fs::path(level) / "fifo.mtl").c_str(), 0644), 0);
  fs::create_directories(fs::path(level) / "dir.mtl");
  folder.write("level/big.bin", std::string(2000, 'x'));

  for (const auto& [name, text] :
       std::vector<std::pair<std::string, std::string>>{{"a.mtl", "inside\n"},
                                                        {"./a.mtl", "inside\n"},
                                                        {"sub/b.mtl", "deeper\n"},
                                                        {"link_in.mtl", "deeper\n"},
                                                        {"sub/up_in.mtl", "inside\n"},
                                                        {"sub/../a.mtl", "inside\n"},
                                                        {"sub_link/b.mtl", "deeper\n"},
                                                        {"chain.mtl", "deeper\n"},
                                                        {"sub_link/up_in.mtl", "inside\n"},
                                                        {"sub/./../sub/b.mtl", "deeper\n"}}) {
    SCOPED_TRACE(name);
    EXPECT_EQ(read(level, name, 1000), text);
  }
  const std::pair<std::string, std::string> refused[] = {
      {"../outside/secret.txt", "leads out of its folder"},
      {"sub/../../outside/secret.txt", "leads out of its folder"},
      {folder.path("outside/secret.txt"), "not a name inside the folder"},
      {"link_out.mtl", "leads out of its folder"},
      {"relative_out.mtl", "leads out of its folder"},
      {"folder_out/secret.txt", "leads out of its folder"},
      {"zero.bin", "leads out of its folder"},
      {"loop_a.mtl", "leads out of its folder"},
      {"sub/up_out.mtl", "leads out of its folder"},
      {"sub/twisted/secret.txt", "leads out of its folder"},
      {"sub_link/../../outside/secret.txt", "leads out of its folder"},
      {"a.mtl/", "cannot open it"},
      {"sub/", "not a regular file (a folder)"},
      {"fifo.mtl", "not a regular file (a FIFO)"},
      {"dir.mtl", "not a regular file (a folder)"},
      {"big.bin", "2000 bytes, more than the 1000 bytes"},
      {"missing.mtl", "cannot open it"},
      {"", "not a name inside the folder"}};
  for (const auto& [name, reason] : refused) {
    SCOPED_TRACE(name);
    try {
      read(level, name, 1000);
      ADD_FAILURE() << "read";
    } catch (const files::FileError& e) {
      EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
    }
  }
}
