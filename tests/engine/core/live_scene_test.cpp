// Hot reload's file watching, without Lua: a save that lands while a reload runs is not lost, and
// a file that only a refused edit introduced is watched, so that saving its fix reloads.
//
// The scripting system is stood in for by ScriptsFromManifest: it reads the files the manifest
// names (its level script and mods), refuses a file that says "broken", and, when a test asks it
// to, saves a file while it loads: the editor's second save landing during the reload.
#include "platon/core/live_scene.h"

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "platon/core/file_watch.h"
#include "platon/core/manifest.h"
#include "platon/core/scene.h"
#include "platon/testing/temp_folder.h"

namespace platon::core {
namespace {

using Folder = testing::TempFolder;

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// What a test wants to happen during the next load: save `file` with `text` after reading it.
struct SaveDuringLoad {
  std::string file, text;
};

// Engine scripts ("scripts/...") are read under `engineRoot`, whose scripts/scene.lua it always
// reads first, as the scripting system reads its driver.
class ScriptsFromManifest : public System {
 public:
  ScriptsFromManifest(const Scene& scene, std::optional<SaveDuringLoad>& save, const std::string& engineRoot) {
    const SceneManifest& m = scene.manifest();
    files_ = m.mods;
    if (!m.level.empty()) files_.insert(files_.begin(), m.level);
    if (!m.rules.empty()) files_.insert(files_.begin(), engineRoot + "/" + m.rules);
    files_.insert(files_.begin(), engineRoot + "/scripts/scene.lua");
    for (const std::string& file : files_) {
      const std::string text = contents(file);
      versions_ += text;
      if (text.find("broken") != std::string::npos) throw std::runtime_error(file + ":1: broken");
    }
    if (save) {  // read, then saved again before the load ends
      std::ofstream(save->file, std::ios::binary | std::ios::trunc) << save->text;
      save.reset();
    }
  }
  void sourceFiles(std::vector<std::string>& out) const override {
    out.insert(out.end(), files_.begin(), files_.end());
  }
  const std::string& versions() const { return versions_; }

 private:
  std::vector<std::string> files_;
  std::string versions_;  // the texts read, in order
};

class LiveSceneTest : public ::testing::Test {
 protected:
  LiveSceneTest() {
    folder_.write("engine/scripts/scene.lua", "");
    registry_.add("scripting", [this](Scene& scene) {
      return std::make_unique<ScriptsFromManifest>(scene, save_, folder_.path("engine"));
    });
  }
  std::string manifest(const std::string& mods) {
    return folder_.write("scene.lua", "return { systems = { 'scripting' }, scripts = { level = 'level.lua', mods = { " +
                                          mods + " } } }\n");
  }
  // What the live version read.
  static std::string versions(LiveScene& live) {
    return dynamic_cast<ScriptsFromManifest&>(*live.scene().findSystem("scripting")).versions();
  }
  // Polls as the game loop does until a reload happens, for up to a second.
  // Lets the clock files are stamped with move past the files written so far: a file written
  // during a reload is one newer than the reload's start.
  static void settle() { std::this_thread::sleep_for(std::chrono::milliseconds(30)); }
  static std::optional<ReloadReport> awaitReload(LiveScene& live) {
    for (int i = 0; i < 100; ++i)
      if (std::optional<ReloadReport> r = live.poll(10)) return r;
    return std::nullopt;
  }

  Folder folder_{"live_scene"};
  SystemRegistry registry_;
  std::optional<SaveDuringLoad> save_;
};

TEST(FileWatcher, ASaveQueuedBeforeTheSetChangesIsStillReported) {
  Folder folder("watch_keep");
  const std::string a = folder.write("a.lua", "1"), b = folder.write("b.lua", "2");
  FileWatcher watcher;
  EXPECT_EQ(watcher.watch({a}), std::vector<std::string>{a});
  folder.write("a.lua", "saved");                                 // queued, not looked at yet
  EXPECT_EQ(watcher.watch({a, b}), std::vector<std::string>{b});  // only b is new
  EXPECT_EQ(watcher.changes(1000), std::vector<std::string>{a});
  // A folder no longer wanted is dropped.
  Folder other("watch_keep_other");
  const std::string c = other.write("c.lua", "3");
  watcher.watch({c});
  folder.write("a.lua", "not watched any more");
  EXPECT_TRUE(watcher.changes(50).empty());
}

TEST(FileWatcher, AMissingFolderIsReportedAndTheOtherFilesAreStillWatched) {
  Folder folder("watch_missing");
  const std::string a = folder.write("a.lua", "1");
  FileWatcher watcher;
  try {
    watcher.watch({folder.path("missing/b.lua"), a});
    ADD_FAILURE() << "no error for a missing folder";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing: cannot watch for changes"), std::string::npos) << e.what();
  }
  folder.write("a.lua", "saved");
  EXPECT_EQ(watcher.changes(1000), std::vector<std::string>{a});
}

TEST_F(LiveSceneTest, ASaveDuringAReloadReloadsAgain) {
  const std::string scene = manifest("");
  const std::string level = folder_.write("level.lua", "v0");
  LiveScene live(scene, registry_, true);
  folder_.write("level.lua", "v1");
  save_ = SaveDuringLoad{level, "v2"};  // the second save lands while v1 loads
  std::optional<ReloadReport> first = awaitReload(live);
  ASSERT_TRUE(first && first->ok) << (first ? first->error : "no reload");
  EXPECT_EQ(versions(live), "v1");
  std::optional<ReloadReport> second = awaitReload(live);
  ASSERT_TRUE(second.has_value()) << "the save during the reload was lost: v1 stays live";
  EXPECT_TRUE(second->ok) << second->error;
  EXPECT_EQ(versions(live), "v2");
}

TEST_F(LiveSceneTest, ASaveDuringAReloadToAFileInANewFolderReloadsAgain) {
  const std::string scene = manifest("");
  folder_.write("level.lua", "v0");
  const std::string mod = folder_.write("sub/mod.lua", "m1");
  LiveScene live(scene, registry_, true);  // sub/ is not watched yet
  settle();
  manifest("'sub/mod.lua'");
  save_ = SaveDuringLoad{mod, "m2"};  // read by the load, saved before sub/ is watched
  std::optional<ReloadReport> first = awaitReload(live);
  ASSERT_TRUE(first && first->ok) << (first ? first->error : "no reload");
  EXPECT_EQ(versions(live), "v0m1");
  std::optional<ReloadReport> second = awaitReload(live);
  ASSERT_TRUE(second.has_value()) << "the save during the reload was lost: m1 stays live";
  EXPECT_EQ(second->files, std::vector<std::string>{mod});
  EXPECT_EQ(versions(live), "v0m2");
}

TEST_F(LiveSceneTest, AFileOnlyARefusedEditNamedIsWatchedAndItsFixReloads) {
  const std::string scene = manifest("'mod.lua'");
  folder_.write("level.lua", "v0");
  folder_.write("mod.lua", "m");
  const std::string mod2 = folder_.write("other/mod2.lua", "broken");
  LiveScene live(scene, registry_, true);
  settle();
  manifest("'mod.lua', 'other/mod2.lua'");
  std::optional<ReloadReport> refused = awaitReload(live);
  ASSERT_TRUE(refused.has_value());
  EXPECT_FALSE(refused->ok);
  EXPECT_NE(refused->error.find("mod2.lua:1: broken"), std::string::npos) << refused->error;
  EXPECT_FALSE(awaitReload(live).has_value()) << "a reload with nothing saved";
  folder_.write("other/mod2.lua", "fixed");
  std::optional<ReloadReport> fixed = awaitReload(live);
  ASSERT_TRUE(fixed.has_value()) << "the fix of a file only the refused edit named was not seen";
  EXPECT_TRUE(fixed->ok) << fixed->error;
  EXPECT_EQ(fixed->files, std::vector<std::string>{mod2});
  EXPECT_EQ(versions(live), "v0mfixed");
}

TEST_F(LiveSceneTest, AnEngineScriptOnlyARefusedEditNamedIsWatched) {
  const std::string scene = manifest("");
  folder_.write("level.lua", "v0");
  folder_.write("engine/scripts/rules/new.lua", "broken");
  LiveScene live(scene, registry_, true);
  settle();
  folder_.write(
      "scene.lua",
      "return { systems = { 'scripting' }, scripts = { level = 'level.lua', rules = 'scripts/rules/new.lua' } }\n");
  std::optional<ReloadReport> refused = awaitReload(live);
  ASSERT_TRUE(refused.has_value());
  EXPECT_FALSE(refused->ok);
  folder_.write("engine/scripts/rules/new.lua", "rules");
  std::optional<ReloadReport> fixed = awaitReload(live);
  ASSERT_TRUE(fixed.has_value()) << "the fix of an engine script only the refused edit named was not seen";
  EXPECT_TRUE(fixed->ok) << fixed->error;
  EXPECT_EQ(versions(live), "rulesv0");
}

TEST_F(LiveSceneTest, ALevelFileOnlyARefusedManifestNamedIsWatched) {
  // The manifest switches to a level file that does not exist yet: creating it reloads.
  const std::string scene = manifest("");
  folder_.write("level.lua", "v0");
  LiveScene live(scene, registry_, true);
  folder_.write(
      "scene.lua",
      "return { systems = { 'scripting' }, stage = { level = 'next.level' }, scripts = { level = 'level.lua' } }\n");
  std::optional<ReloadReport> refused = awaitReload(live);
  ASSERT_TRUE(refused.has_value());
  EXPECT_FALSE(refused->ok);
  folder_.write("next.level", "not a level");
  std::optional<ReloadReport> again = awaitReload(live);
  ASSERT_TRUE(again.has_value()) << "creating the level file the manifest names did not reload";
  EXPECT_EQ(again->files, std::vector<std::string>{folder_.path("next.level")});
}

}  // namespace
}  // namespace platon::core
