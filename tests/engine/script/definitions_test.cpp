// The Lua language server's definitions (`platon defs`, docs/scripting.md "Editors") are made from
// the live binding tables: every binding has a definition and every definition a binding, in the
// trusted set and the sandboxed one, and the shipped definitions are what the engine makes now.
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "platon/core/live_scene.h"
#include "platon/script/script_system.h"
#include "platon/testing/temp_folder.h"

namespace platon::script {
namespace {

std::string fileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Game {
  testing::TempFolder folder{"definitions"};
  core::SystemRegistry registry;
  std::unique_ptr<core::LiveScene> live;
  Game() {
    registry.add("scripting", makeScriptSystem);
    live = std::make_unique<core::LiveScene>(
        folder.write("scene.lua", "return { systems = { 'scripting' }, scripts = { preset = 'game' } }\n"), registry,
        false);
  }
  ScriptSystem& scripts() { return dynamic_cast<ScriptSystem&>(*live->scene().findSystem("scripting")); }
};

TEST(Definitions, EveryBindingHasOneAndEveryOneABindingInBothSets) {
  Game game;
  for (const bool sandboxed : {false, true}) {
    std::vector<std::string> problems;
    const std::string text = game.scripts().definitions(sandboxed, problems);
    for (const std::string& p : problems) ADD_FAILURE() << (sandboxed ? "sandbox: " : "trusted: ") << p;
    EXPECT_EQ(text.rfind("---@meta\n", 0), 0u);
    EXPECT_NE(text.find("function platon.world.setVelocity(entity, vx, vy) end"), std::string::npos);
    EXPECT_NE(text.find("---@type table<string, integer>\nplaton.tags = {}"), std::string::npos);
    EXPECT_EQ(text.find("function Game.message(text) end") != std::string::npos, sandboxed);
  }
}

// The check can fail both ways: a binding the table lacks, an entry with no binding.
TEST(Definitions, ABindingWithoutADefinitionAndADefinitionWithoutABindingAreNamed) {
  Game game;
  const std::string root = std::string(PLATON_SOURCE_ROOT) + "/engine/script/lua/";
  const std::string code =
      "local game = ...\n"
      "local make = loadstring(" +
      std::string("[==[") + fileText(root + "definitions.lua") + "]==])\n" + "local signatures = loadstring([==[" +
      fileText(root + "api_signatures.lua") + "]==])()\n" +
      "signatures['platon.world.position'] = nil\n"
      "signatures['platon.world.teleport'] = { 'entity: integer', '', 'no such binding' }\n"
      "local data = { actions = { 'left' }, hooks = { 'tick' }, tagHandlers = { 'contact' },\n"
      "  player = { tick = function() end, fly = function() end } }\n"
      "local _, problems = make(platon, game.levelApi, signatures, false, data, {})\n"
      "return table.concat(problems, '\\n')\n";
  const std::string problems = game.scripts().evaluate(code, "=definitions check");
  EXPECT_NE(problems.find("platon.world.position: a binding with no definition"), std::string::npos) << problems;
  EXPECT_NE(problems.find("platon.world.teleport: a definition with no binding"), std::string::npos) << problems;
  EXPECT_NE(problems.find("Player.fly: a player function with no definition"), std::string::npos) << problems;
}

// Every name docs/scripting.md uses of the API (platon.world.x, game.world.x, game.x(...),
// Player.x, platon.x) is in the sandbox's definitions: a documented name `platon defs` lacks fails.
TEST(Definitions, EveryNameTheDocsUseIsDefined) {
  Game game;
  std::vector<std::string> problems;
  const std::string defs = game.scripts().definitions(true, problems);
  const std::string docs = fileText(std::string(PLATON_SOURCE_ROOT) + "/docs/scripting.md");
  // Names the docs' own examples make (a constant of the dash's), not the API's.
  const std::set<std::string> examples = {"Player.DASH_SPEED"};
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  // Each use of `prefix` followed by a name (and by "(" when `call`): what defines it in `defs`.
  struct Use {
    std::string prefix, defined, after;  // defined + name + after is looked for
    bool call;
  };
  const Use uses[] = {
      {"platon.world.", "platon.world.", "(", false},
      {"game.world.", "platon.world.", "(", false},
      {"platon.draw.", "platon.draw.", "(", false},
      {"platon.sound.", "platon.sound.", "(", false},
      {"game.", "Game.", "(", true},
      {"Player.", "Player.", "", false},
  };
  size_t checked = 0;
  for (const Use& u : uses) {
    for (size_t at = docs.find(u.prefix); at != std::string::npos; at = docs.find(u.prefix, at + 1)) {
      if (at > 0 && (word(docs[at - 1]) || docs[at - 1] == '.')) continue;
      size_t end = at + u.prefix.size();
      while (end < docs.size() && word(docs[end])) ++end;
      const std::string name = docs.substr(at + u.prefix.size(), end - at - u.prefix.size());
      if (name.empty() || name == "world" || (u.call && (docs[end] != '(' || !std::islower(name[0])))) continue;
      if (examples.count(u.prefix + name)) continue;
      ++checked;
      EXPECT_NE(defs.find(u.defined + name + u.after), std::string::npos)
          << u.prefix << name << " is in docs/scripting.md, " << u.defined << name << u.after << " not in platon defs";
    }
  }
  EXPECT_GT(checked, 30u) << "the docs' names were not found";
}

// docs/lua-definitions/ is what `platon defs` writes now (PLATON_UPDATE_DEFINITIONS=1 writes it).
TEST(Definitions, TheShippedDefinitionsAreTheEnginesNow) {
  Game game;
  for (const bool sandboxed : {false, true}) {
    std::vector<std::string> problems;
    const std::string made = game.scripts().definitions(sandboxed, problems);
    const std::string path = std::string(PLATON_SOURCE_ROOT) + "/docs/lua-definitions/" +
                             (sandboxed ? "sandbox" : "trusted") + "/platon.lua";
    if (std::getenv("PLATON_UPDATE_DEFINITIONS")) std::ofstream(path, std::ios::binary) << made;
    EXPECT_EQ(fileText(path), made) << path << " is stale: run platon defs docs/lua-definitions";
  }
}

}  // namespace
}  // namespace platon::script
