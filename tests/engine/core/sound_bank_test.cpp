// The sound bank: the engine's own has every sound the game's scripts play, each audible and
// bounded; a level's bank adds and replaces names; every malformed field is refused at its
// file:line:column; a scene that cannot make a sound reads no bank.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "platon/core/data_root.h"
#include "platon/core/scene.h"
#include "platon/core/sound.h"
#include "platon/testing/temp_folder.h"

namespace platon::core {
namespace {

using Folder = testing::TempFolder;

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}

double rms(const std::vector<float>& s) {
  double sum = 0;
  for (float v : s) sum += double(v) * v;
  return std::sqrt(sum / double(s.size()));
}

// Every effect the engine's scripts play by a literal name, found in the scripts themselves (so a
// sound added to a script and not to the bank fails here, not in a player's game).
TEST(SoundBank, TheEngineBankHasEverySoundTheGamesScriptsPlay) {
  const SoundBank& bank = engineSoundBank();
  size_t found = 0;
  // Every quoted name inside a play(...) call: play("jump"), play(killed and "death" or "respawn").
  // (Found by hand: std::regex trips GCC 12's maybe-uninitialized warning in the sanitizer build.)
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dataRoot() + "/scripts")) {
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    for (size_t call = s.find("play("); call != std::string::npos; call = s.find("play(", call + 5)) {
      const std::string arguments = s.substr(call + 5, s.find(')', call) - call - 5);
      for (size_t q = arguments.find('"'); q != std::string::npos; q = arguments.find('"', q + 1)) {
        const size_t end = arguments.find('"', q + 1);
        if (end == std::string::npos) break;
        const std::string name = arguments.substr(q + 1, end - q - 1);
        ++found;
        EXPECT_TRUE(bank.hasEffect(name)) << entry.path() << " plays '" << name << "'";
        q = end;
      }
    }
  }
  EXPECT_GE(found, 9u);  // jump, land, cross, death, respawn, checkpoint, switch, door, goal
  for (const char* menu : {"menu_move", "menu_select"}) EXPECT_TRUE(bank.hasEffect(menu)) << menu;
}

TEST(SoundBank, EveryEffectIsAudibleAndBoundedAndEveryTuneToo) {
  const SoundBank& bank = engineSoundBank();
  for (const auto& [name, effect] : bank.effects) {
    const std::vector<float> s = synth::render(effect, 44100);
    EXPECT_GT(rms(s), 0.01) << name;
    EXPECT_LE(synth::lengthOf(effect), 2.0) << name << ": an effect, not a tune";
  }
  EXPECT_GE(bank.music.size(), 4u);
  for (const auto& [name, tune] : bank.music) {
    synth::MusicPlayer player(tune, 22050);
    std::vector<float> s(2 * 22050 * 8, 0.0f);  // 8 s
    player.mix(s.data(), s.size() / 2, 0.6f);
    size_t clipped = 0;
    double mean = 0;
    for (float v : s) clipped += std::fabs(v) >= 1.0f, mean += v;
    EXPECT_EQ(clipped, 0u) << name;
    EXPECT_NEAR(mean / double(s.size()), 0, 0.02) << name << ": an offset";
    EXPECT_GT(rms(s), 0.02) << name;
  }
}

TEST(SoundBank, EveryMalformedFieldIsRefusedAtItsPlace) {
  Folder folder("sound_bank_bad");
  struct Case {
    const char* text;
    const char* error;  // after "file:"
  };
  const Case cases[] = {
      {"return 5", "1:8: a sound bank is a table"},
      {"return { noises = {} }", "1:10: unknown field 'noises' (known: effects, music)"},
      {"return { effects = 3 }", "1:20: 'effects' must be a table"},
      {"return { effects = { Jump = {} } }", "1:22: effect names are 1 to 32 of a-z, 0-9 and _"},
      {"return { effects = { jump = 1 } }", "1:29: 'jump' must be a table of fields"},
      {"return { effects = { jump = { wave = 'organ' } } }",
       "1:38: 'wave' must be \"square\", \"saw\", \"triangle\", \"sine\" or \"noise\", not 'organ'"},
      {"return { effects = { jump = { frequency = 5 } } }", "1:43: 'frequency' must be within [20, 20000], not 5"},
      {"return { effects = { jump = { volume = 2 } } }", "1:40: 'volume' must be within [0, 1], not 2"},
      {"return { effects = { jump = { slide_to = 10 } } }", "1:42: 'slide_to' must be 0 (none) or 20..20000 Hz"},
      {"return { effects = { jump = { pitch = 1 } } }", "1:31: unknown field 'pitch'"},
      {"return { music = { a = { voices = {} } } }", "1:35: 'voices' must be a list of 1 to 8 voices"},
      {"return { music = { a = { tempo = 1000, voices = { { notes = 'C4' } } } } }",
       "1:34: 'tempo' must be within [20, 400], not 1000"},
      {"return { music = { a = { voices = { { notes = 'C4 H4' } } } } }",
       "1:47: note 'H4' at character 4: expected a note A..G"},
      {"return { music = { a = { voices = { { wave = 'sine' } } } } }", "1:37: a voice's 'notes' is a string"},
      {"return { music = { a = { voices = { { notes = '' } } } } }", "1:47: a voice has 1 to 4096 notes and rests"},
      {"return { music = { a = { voices = { 5 } } } }", "1:37: a voice is a table"},
      {"return { music = { a = { voices = { { notes = 'C4', drum = true } } } } }", "1:53: unknown field 'drum'"},
      {"return { effects = { jump = {}, jump = {} } }", "1:33: the key 'jump' is given twice in one table"},
      {"return { effects = { jump = {} } } + 1", "1:36:"},
  };
  for (const Case& c : cases) {
    const std::string path = folder.write("bank.lua", c.text);
    SoundBank bank;
    const std::string error = errorOf([&] { readSoundBank(path, bank); });
    EXPECT_EQ(error.rfind(path + ":" + c.error, 0), 0u) << c.text << "\n" << error;
  }
  // Not a file: the reader opens only regular files of bounded size.
  SoundBank bank;
  EXPECT_NE(errorOf([&] { readSoundBank(folder.path(), bank); }).find("the sound bank: "), std::string::npos);
}

TEST(SoundBank, ALevelsBankAddsAndReplacesNamesAndItsTuneIsChecked) {
  Folder folder("sound_bank_level");
  folder.write("sounds.lua",
               "return {\n  effects = { jump = { wave = 'sine', frequency = 300 }, boing = { wave = 'triangle' } },\n"
               "  music = { hum = { voices = { { notes = 'C3 - - -' } } } },\n}\n");
  const std::string manifest =
      folder.write("scene.lua", "return { systems = { 'audio' }, sounds = 'sounds.lua', music = 'hum' }\n");
  const SystemRegistry headless;
  const auto scene = loadScene(manifest, headless);
  const SoundBank& bank = scene->sounds().bank();
  EXPECT_TRUE(bank.hasEffect("boing"));
  EXPECT_TRUE(bank.hasEffect("land"));  // the engine's, kept
  EXPECT_EQ(bank.effects.at("jump").wave, synth::Wave::Sine);
  EXPECT_EQ(scene->sounds().music(), "hum");

  const std::string unknownTune = folder.write("b.lua", "return { systems = { 'audio' },\n  music = 'humm' }\n");
  EXPECT_EQ(errorOf([&] {
              loadScene(unknownTune, headless);
            }).rfind(unknownTune + ":2:11: music 'humm': no such tune (known: ", 0),
            0u);
  const std::string outside = folder.write("c.lua", "return { systems = { 'audio' }, sounds = '../x.lua' }\n");
  EXPECT_EQ(errorOf([&] { loadScene(outside, headless); }),
            outside + ":1:42: '../x.lua': a sound bank is a path inside the scene's folder (no '..', not absolute)");
  const std::string missing = folder.write("d.lua", "return { systems = { 'audio' }, sounds = 'none.lua' }\n");
  EXPECT_EQ(errorOf([&] { loadScene(missing, headless); }).rfind(missing + ":1:42: ", 0), 0u);
  const std::string broken = folder.write("e.lua", "return { systems = { 'audio' }, sounds = 'bad.lua' }\n");
  const std::string bad = folder.write("bad.lua", "return {\n  effects = { jump = { volume = 3 } } }\n");
  EXPECT_EQ(errorOf([&] { loadScene(broken, headless); }).rfind(bad + ":2:33: 'volume' must be within", 0), 0u);
}

// docs/sound.md's example bank is a bank, read as the reader reads any.
TEST(SoundBank, TheDocsExampleIsABank) {
  std::ifstream in(std::string(PLATON_SOURCE_ROOT) + "/docs/sound.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const size_t start = doc.find("```lua\n"), end = doc.find("```\n", start + 7);
  ASSERT_NE(start, std::string::npos);
  ASSERT_NE(end, std::string::npos);
  Folder folder("sound_bank_docs");
  SoundBank bank;
  readSoundBank(folder.write("bank.lua", doc.substr(start + 7, end - start - 7)), bank);
  EXPECT_TRUE(bank.hasEffect("boing"));
  EXPECT_TRUE(bank.hasMusic("hum"));
}

// A scene that cannot make a sound (no scripts, no audio) reads no bank.
TEST(SoundBank, ASceneThatCannotMakeASoundReadsNone) {
  Folder folder("sound_bank_none");
  const std::string manifest = folder.write("scene.lua", "return { systems = { 'rendering' } }\n");
  const auto scene = loadScene(manifest, SystemRegistry{});
  EXPECT_TRUE(scene->sounds().bank().effects.empty());
}

}  // namespace
}  // namespace platon::core
