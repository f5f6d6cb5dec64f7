// The settings file: saved and read back to the same settings; missing, it is the defaults with no
// complaint; damaged, each line it cannot read keeps its default and is named at file:line; a file
// that is none (a folder) is the defaults, said so.
#include "settings.h"

#include <gtest/gtest.h>

#include "platon/testing/temp_folder.h"

using namespace platon::app;

namespace {

TEST(Settings, ASavedFileReadsBackTheSame) {
  platon::testing::TempFolder folder("settings");
  Settings changed;
  changed.musicVolume = 0, changed.effectsVolume = 100, changed.screenShake = false, changed.fullscreen = true;
  changed.vsync = false, changed.gameSpeed = 50, changed.multisamples = 0;
  changed.keys.keys["jump"] = {"L", "Keypad 0"};  // jump on two keys, one with a space in its name
  changed.keys.keys["left"] = {"J"};
  changed.keys.pad["jump"] = {"x", "rightshoulder"};
  changed.keys.keys["dash"] = {"Left Shift"};  // a mod's action, kept for the scenes that have it
  changed.keys.pad["dash"] = {"y"};
  for (const Settings& s : {Settings{}, changed}) {
    const std::string path = folder.path("config/platon/settings.txt");
    ASSERT_EQ(s.save(path), "");
    std::vector<std::string> problems;
    const Settings back = Settings::load(path, problems);
    EXPECT_TRUE(problems.empty());
    EXPECT_EQ(back.musicVolume, s.musicVolume);
    EXPECT_EQ(back.effectsVolume, s.effectsVolume);
    EXPECT_EQ(back.screenShake, s.screenShake);
    EXPECT_EQ(back.fullscreen, s.fullscreen);
    EXPECT_EQ(back.vsync, s.vsync);
    EXPECT_EQ(back.gameSpeed, s.gameSpeed);
    EXPECT_EQ(back.multisamples, s.multisamples);
    std::vector<platon::core::Action> actions = platon::core::engineActions();
    platon::core::addAction(actions, {"dash", "Dash", {"X"}, {"x"}, "", true, "dash.lua"});
    const platon::core::KeyBindings a = platon::core::bindingsFor(actions, back.keys);
    const platon::core::KeyBindings b = platon::core::bindingsFor(actions, s.keys);
    EXPECT_EQ(a.keys, b.keys);
    EXPECT_EQ(a.pad, b.pad);
  }
}

TEST(Settings, ADamagedFileKeepsTheDefaultsOfWhatItCannotRead) {
  platon::testing::TempFolder folder("settings_bad");
  std::vector<std::string> problems;
  const Settings none = Settings::load(folder.path("absent.txt"), problems);
  EXPECT_TRUE(problems.empty()) << "no file yet is no problem";
  EXPECT_EQ(none.musicVolume, Settings{}.musicVolume);

  const std::string path = folder.write("settings.txt",
                                        "music_volume 150\n"
                                        "effects_volume 40\n"
                                        "screen_shake maybe\n"
                                        "volume 3\n"
                                        "music_volume -1 # a sign\n"
                                        "\x01\xff garbage\n"
                                        "game_speed 30\n"
                                        "vsync sometimes\n"
                                        "keys_jump   # none\n"
                                        "keys_left J, K\n"
                                        "multisampling 3\n"
                                        "keys_reload Q\n"
                                        "keys_down F12, S\n");
  const Settings s = Settings::load(path, problems);
  EXPECT_EQ(s.musicVolume, Settings{}.musicVolume);
  EXPECT_EQ(s.effectsVolume, 40);  // the good line is kept
  EXPECT_EQ(s.screenShake, Settings{}.screenShake);
  ASSERT_EQ(problems.size(), 11u);
  EXPECT_EQ(problems[0].rfind(path + ":1: 'music_volume 150': music_volume is a whole number 0..100", 0), 0u)
      << problems[0];
  EXPECT_EQ(problems[1].rfind(path + ":3: 'screen_shake maybe': screen_shake is on or off", 0), 0u) << problems[1];
  EXPECT_EQ(problems[2].rfind(path + ":4: unknown setting 'volume'", 0), 0u) << problems[2];
  EXPECT_EQ(problems[3].rfind(path + ":5: ", 0), 0u) << problems[3];
  EXPECT_EQ(problems[4].rfind(path + ":6: unknown setting", 0), 0u) << problems[4];
  EXPECT_EQ(problems[5].rfind(path + ":7: 'game_speed 30': game_speed is a whole number 50..100", 0), 0u)
      << problems[5];
  EXPECT_EQ(problems[6].rfind(path + ":8: 'vsync sometimes': vsync is on or off", 0), 0u) << problems[6];
  EXPECT_EQ(problems[7].rfind(path + ":9: 'keys_jump   # none': keys_jump names one key or more", 0), 0u)
      << problems[7];
  EXPECT_EQ(problems[8].rfind(path + ":11: 'multisampling 3': multisampling is auto, 0, 2, 4 or 8", 0), 0u)
      << problems[8];
  EXPECT_EQ(problems[9].rfind(path + ":12: keys_reload: reload is not the player's to bind", 0), 0u) << problems[9];
  EXPECT_EQ(s.gameSpeed, Settings{}.gameSpeed);
  EXPECT_EQ(s.keys.keys.count("jump"), 0u) << "jump keeps its default";
  EXPECT_EQ(s.keys.keys.at("left"), (std::vector<std::string>{"J", "K"}));
  EXPECT_EQ(s.keys.keys.count("reload"), 0u);
  EXPECT_EQ(problems[10].rfind(path + ":13: keys_down: F12 is a tool's key", 0), 0u) << problems[10];
  EXPECT_EQ(s.keys.keys.at("down"), std::vector<std::string>{"S"});

  problems.clear();
  const Settings folderInstead = Settings::load(folder.path(), problems);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("the default settings are used"), std::string::npos) << problems[0];
  EXPECT_EQ(folderInstead.screenShake, Settings{}.screenShake);
}

TEST(Settings, LiveInTheXdgConfigFolder) {
  setenv("XDG_CONFIG_HOME", "/tmp/xdg_config", 1);
  EXPECT_EQ(Settings::defaultPath(), "/tmp/xdg_config/platon/settings.txt");
  setenv("XDG_CONFIG_HOME", "relative", 1);  // not absolute: ignored, as the XDG spec says
  setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(Settings::defaultPath(), "/home/someone/.config/platon/settings.txt");
  unsetenv("XDG_CONFIG_HOME");
}

}  // namespace
