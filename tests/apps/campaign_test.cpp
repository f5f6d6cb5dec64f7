// The campaign file and the progress file: a campaign names levels that exist, or says which line
// does not; progress survives a damaged file (the lines it cannot read are dropped, the rest kept),
// keeps the best time and fewest deaths, lives in the XDG data folder, and a failed save leaves
// the old file whole and the game going.
#include "campaign.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "platon/testing/temp_folder.h"

using namespace platon::app;

namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Campaign, ListsItsLevelsInOrder) {
  platon::testing::TempFolder folder("campaign");
  folder.write("a/scene.lua", "return {}");
  folder.write("b/scene.lua", "return {}");
  const auto levels = readCampaign(folder.write("campaign.txt", "# the order\nb   # second in the file\n\na\n"));
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels[0].folder, "b");
  EXPECT_EQ(levels[0].scene, folder.path("b/scene.lua"));
  EXPECT_EQ(levels[1].folder, "a");
}

TEST(Campaign, AMissingLevelIsNamedWithItsLine) {
  platon::testing::TempFolder folder("campaign");
  folder.write("a/scene.lua", "return {}");
  const std::string path = folder.write("campaign.txt", "a\n\nnowhere\n");
  try {
    readCampaign(path);
    FAIL() << "accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":3:1: level 'nowhere' has no "), std::string::npos) << e.what();
  }
  EXPECT_THROW(readCampaign(folder.write("empty.txt", "# nothing\n")), std::runtime_error);
  folder.write("my level/scene.lua", "return {}");
  try {
    readCampaign(folder.write("spaces.txt", "a\nmy level\n"));
    FAIL() << "a folder with a space accepted (the progress file could not hold it)";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("spaces.txt:2:4: 'level': a par time is minutes and seconds"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(readCampaign(folder.path("no_such_file.txt")), std::runtime_error);
}

// A level's par time follows its folder, as M:SS; anything else there is an error at its column.
TEST(Campaign, ParTimesAreMinutesAndSeconds) {
  platon::testing::TempFolder folder("campaign_par");
  folder.write("a/scene.lua", "return {}");
  folder.write("b/scene.lua", "return {}");
  const auto levels = readCampaign(folder.write("c.txt", "a 0:20  # twenty seconds\nb\n"));
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels[0].parFrames, 1200u);
  EXPECT_EQ(levels[1].parFrames, 0u);
  EXPECT_EQ(readCampaign(folder.write("d.txt", "a\t12:05\n"))[0].parFrames, 725u * 60);
  const std::pair<const char*, const char*> bad[] = {
      {"a 20\n", ":1:3: '20': a par time is minutes and seconds, M:SS (0:20), above 0"},
      {"a 0:5\n", ":1:3: '0:5': a par time"},
      {"a 0:60\n", ":1:3: '0:60': a par time"},
      {"a 0:00\n", ":1:3: '0:00': a par time"},
      {"a x:10\n", ":1:3: 'x:10': a par time"},
      {"a -1:10\n", ":1:3: '-1:10': a par time"},
      {"a 1:1x\n", ":1:3: '1:1x': a par time"},
      {"a 0:20 b\n", ":1:8: 'b': a line is a level's folder and its par time (M:SS)"},
      {"a  0:20 a\n", ":1:9: 'a': a line is a level's folder and its par time (M:SS)"},
  };
  for (const auto& [text, error] : bad) {
    const std::string path = folder.write("bad.txt", text);
    try {
      readCampaign(path);
      ADD_FAILURE() << text << ": accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path + error, 0), 0u) << e.what();
    }
  }
}

// Levels unlock in order: the first, every level done, and the one after a level done.
TEST(Progress, LevelsOpenInOrder) {
  platon::testing::TempFolder folder("campaign_open");
  for (const char* l : {"a", "b", "c", "d"}) folder.write(std::string(l) + "/scene.lua", "return {}");
  const auto levels = readCampaign(folder.write("c.txt", "a\nb\nc\nd\n"));
  Progress progress(folder.path("progress.txt"));
  EXPECT_TRUE(progress.open(levels, 0));
  EXPECT_FALSE(progress.open(levels, 1));
  EXPECT_FALSE(progress.open(levels, 3));
  ASSERT_TRUE(progress.finish("a", 600, 0));
  EXPECT_TRUE(progress.open(levels, 1));
  EXPECT_FALSE(progress.open(levels, 2));
  ASSERT_TRUE(progress.finish("c", 600, 0));  // a level done stays open (and opens the next)
  EXPECT_TRUE(progress.open(levels, 2));
  EXPECT_TRUE(progress.open(levels, 3));
}

TEST(Progress, KeepsTheBestAndSurvivesADamagedFile) {
  platon::testing::TempFolder folder("progress");
  const std::string path = folder.path("deep/er/progress.txt");  // folders made on the first save
  {
    Progress p(path);
    EXPECT_FALSE(p.done("cube_intro"));
    EXPECT_TRUE(p.finish("cube_intro", 1200, 2));
    EXPECT_TRUE(p.finish("cube_intro", 1500, 0));  // slower, fewer deaths: each record kept apart
  }
  Progress again(path);
  ASSERT_TRUE(again.done("cube_intro"));
  EXPECT_EQ(again.record("cube_intro")->bestFrames, 1200u);
  EXPECT_EQ(again.record("cube_intro")->fewestDeaths, 0);
  // Damage: garbage, a negative count, a half line. The good line survives; the rest is dropped.
  std::ofstream(path, std::ios::app)
      << "\x01\x02 garbage\nprism -5 0\nicosa_drop 18446744073709551615 0\nsoccer_ball 77\n"
         "cube_lift 5 0 extra\nocta_ring 900 1\n";
  Progress damaged(path);
  EXPECT_TRUE(damaged.done("cube_intro"));
  EXPECT_TRUE(damaged.done("octa_ring"));
  EXPECT_FALSE(damaged.done("prism"));        // a negative time: no wrap to 2^64 - 5
  EXPECT_FALSE(damaged.done("icosa_drop"));   // a time past any game
  EXPECT_FALSE(damaged.done("soccer_ball"));  // half a line
  EXPECT_FALSE(damaged.done("cube_lift"));    // one field too many
}

// An assist-speed finish opens the next level, but its time is no par run: a full-speed finish
// replaces it whatever its time, and an assisted one never beats a full-speed record.
TEST(Progress, AssistedRunsOpenTheNextLevelButAreNoParRuns) {
  platon::testing::TempFolder folder("progress_assist");
  const std::string path = folder.path("progress.txt");
  {
    Progress p(path);
    ASSERT_TRUE(p.finish("a", 500, 0, true));
    EXPECT_TRUE(p.done("a"));
    EXPECT_TRUE(p.record("a")->assisted);
  }
  Progress again(path);  // kept as such in the file
  ASSERT_NE(again.record("a"), nullptr);
  EXPECT_TRUE(again.record("a")->assisted);
  EXPECT_EQ(again.record("a")->bestFrames, 500u);
  ASSERT_TRUE(again.finish("a", 900, 2));  // slower, at full speed: it is the record now
  EXPECT_FALSE(again.record("a")->assisted);
  EXPECT_EQ(again.record("a")->bestFrames, 900u);
  ASSERT_TRUE(again.finish("a", 300, 0, true));  // faster, assisted: changes nothing
  EXPECT_EQ(again.record("a")->bestFrames, 900u);
  EXPECT_EQ(again.record("a")->fewestDeaths, 2);
  Progress last(path);
  EXPECT_FALSE(last.record("a")->assisted);
  EXPECT_EQ(last.record("a")->bestFrames, 900u);
}

TEST(Progress, AFailedSaveSaysWhyAndKeepsTheOldFile) {
  platon::testing::TempFolder folder("progress");
  const std::string path = folder.path("progress.txt");
  Progress p(path);
  ASSERT_TRUE(p.finish("a", 100, 0));
  const std::string before = read(path);
  // The file became a link (a save never replaces one, nor writes through it): the save fails,
  // says so, and the file the link names is as it was.
  std::filesystem::rename(path, folder.path("kept.txt"));
  std::filesystem::create_symlink("kept.txt", path);
  EXPECT_FALSE(p.finish("b", 50, 0));
  EXPECT_NE(p.lastError().find("cannot write the progress file: it is a link"), std::string::npos) << p.lastError();
  EXPECT_EQ(read(folder.path("kept.txt")), before);
  EXPECT_TRUE(std::filesystem::is_symlink(path));
  // Nor can a progress file live under a file.
  folder.write("plain_file", "x");
  Progress under(folder.path("plain_file/progress.txt"));
  EXPECT_FALSE(under.finish("a", 1, 0));
  EXPECT_FALSE(under.lastError().empty());
}

TEST(Progress, LivesInTheXdgDataFolder) {
  const std::string home = std::getenv("HOME") ? std::getenv("HOME") : "";
  setenv("XDG_DATA_HOME", "/tmp/xdg_here", 1);
  EXPECT_EQ(Progress::defaultPath(), "/tmp/xdg_here/platon/progress.txt");
  setenv("XDG_DATA_HOME", "relative/is/ignored", 1);  // the spec: only absolute paths count
  setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(Progress::defaultPath(), "/home/someone/.local/share/platon/progress.txt");
  unsetenv("XDG_DATA_HOME");
  EXPECT_EQ(Progress::defaultPath(), "/home/someone/.local/share/platon/progress.txt");
  setenv("HOME", home.c_str(), 1);
}

}  // namespace
