// Every Lua example in docs/scripting.md runs: each ```lua block is tagged with what it is, and
// run as that (a manifest loaded and played, a level or rules script played in a scene, a
// scenario or a replay run). An untagged or unknown block fails, so no example goes untested.
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "platon/core/live_scene.h"
#include "platon/core/replay.h"
#include "platon/script/scenario.h"
#include "platon/script/script_system.h"
#include "platon/testing/temp_folder.h"

namespace platon::script {
namespace {

struct Example {
  std::string kind, code;
  int line;
};

std::vector<Example> examples() {
  std::ifstream file(std::string(PLATON_SOURCE_ROOT) + "/docs/scripting.md");
  std::vector<Example> out;
  std::string line, kind, code;
  bool inside = false;
  int number = 0, start = 0;
  while (std::getline(file, line)) {
    ++number;
    if (!inside && line.rfind("```lua", 0) == 0) {
      inside = true;
      kind = line.size() > 7 ? line.substr(7) : "";
      code.clear();
      start = number;
    } else if (inside && line == "```") {
      inside = false;
      out.push_back({kind, code, start});
    } else if (inside) {
      code += line + "\n";
    }
  }
  return out;
}

const char* kManifest =
    "return { systems = { 'scripting' }, gravity = 0.35, scripts = { player = 'scripts/player.lua',\n"
    "  progression = 'scripts/progression.lua', level = 'level.lua', rules = '%RULES%' } }\n";
const char* kFloor =
    "local level = { start = { face = 0, x = 600, y = 700 } }\n"
    "function level.build(game) for i = 1, game.world.faceCount() do game.world.line(game.world.face(i), 0, 512, 4096, "
    "512) end end\n"
    "return level\n";

core::SystemRegistry scripting() {
  core::SystemRegistry registry;
  registry.add("scripting", makeScriptSystem);
  return registry;
}

// Plays the scene for a while, walking and jumping, then reloads it once: no error anywhere.
void play(const std::string& manifest) {
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(manifest, registry, false);
  core::InputEdges edges;
  for (int f = 0; f < 400; ++f) {
    const core::Buttons held = core::InputFrame::bit(f % 200 < 100 ? core::Button::Right : core::Button::Left) |
                               (f % 50 < 5 ? core::InputFrame::bit(core::Button::Jump) : 0);
    const std::optional<std::string> error = live.step(edges.next(held));
    ASSERT_FALSE(error.has_value()) << *error;
  }
  const core::ReloadReport r = live.reload();
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_FALSE(live.step(edges.next(0)).has_value()) << live.lastError();
}

std::string withRules(const std::string& rules) {
  std::string m = kManifest;
  m.replace(m.find("%RULES%"), 7, rules);
  return m;
}

TEST(DocsExamples, EveryLuaExampleInScriptingMdRuns) {
  const std::vector<Example> all = examples();
  ASSERT_FALSE(all.empty()) << "docs/scripting.md not found or without examples";
  std::map<std::string, int> counts;
  testing::TempFolder folder("docs_examples");
  for (const Example& e : all) {
    SCOPED_TRACE("docs/scripting.md:" + std::to_string(e.line) + " (" + e.kind + ")");
    ++counts[e.kind];
    if (e.kind == "manifest") {
      folder.write("m/level.lua", kFloor);
      // The manifest example names the intro's level file.
      std::ifstream in(std::string(PLATON_SOURCE_ROOT) + "/levels/cube_intro/cube_intro.level");
      folder.write("m/cube_intro.level", std::string(std::istreambuf_iterator<char>(in), {}));
      folder.write("m/mod.lua", "return { tick = function(game, frame) end }\n");
      play(folder.write("m/scene.lua", e.code));
    } else if (e.kind == "level") {
      folder.write("l/level.lua", e.code);
      play(folder.write("l/scene.lua", withRules("scripts/rules/game.lua")));
    } else if (e.kind == "rules") {
      folder.write("r/level.lua", kFloor);
      folder.write("r/rules.lua", e.code);
      play(folder.write("r/scene.lua", withRules("rules.lua")));
    } else if (e.kind == "mod") {
      // A mod that declares a word: the first face's floor is written with it, and the player
      // lands on it.
      const size_t open = e.code.find("tags = { ");
      const size_t from = open == std::string::npos ? open : open + 9;
      const std::string word = from == std::string::npos ? "" : e.code.substr(from, e.code.find(' ', from) - from);
      const std::string floor = "0 512 4096 512" + (word.empty() ? std::string() : " " + word);
      folder.write("mod/cube.level", "HEXAHEDRON\n0 600 700\n2 2000 800\n4096\n%\n" + floor + "\n%\n%\n%\n%\n%\n");
      folder.write("mod/mod.lua", e.code);
      play(folder.write("mod/scene.lua",
                        "return { systems = { 'scripting' }, stage = { level = 'cube.level' }, gravity = 0.35,"
                        " scripts = { preset = 'game', mods = { 'mod.lua' } } }\n"));
    } else if (e.kind == "player") {
      folder.write("p/level.lua", kFloor);
      folder.write("p/player.lua", e.code);
      play(folder.write("p/scene.lua",
                        "return { systems = { 'scripting' }, gravity = 0.35, scripts = { preset = "
                        "'game', level = 'level.lua', player = 'player.lua' } }\n"));
    } else if (e.kind == "scenario") {
      const ScenarioResult r = runScenario(folder.write("s.lua", e.code));
      EXPECT_TRUE(r.passed) << r.message;
    } else if (e.kind == "replay") {
      const ScenarioResult r = runReplay(folder.write("run.replay", e.code));
      EXPECT_TRUE(r.passed) << r.message;
    } else if (e.kind == "signatures") {
      // A list of callback signatures, not a program: each names one of the documented callbacks.
      for (const char* name :
           {"pierce", "beginContact", "overContact", "endContact", "contact", "touchContact", "crushed"})
        EXPECT_NE(e.code.find(name), std::string::npos) << name;
    } else {
      ADD_FAILURE() << "untagged or unknown example kind '" << e.kind << "'";
    }
  }
  for (const char* kind : {"manifest", "level", "rules", "mod", "player", "scenario", "replay"})
    EXPECT_GT(counts[kind], 0) << kind;
}

}  // namespace
}  // namespace platon::script
