// Extending the game, never copying it: line tags that mods add (docs/scripting.md, "Tags"), a
// word the level file writes with its look and its handlers, on top of the game's rules, several
// mods in the manifest's order; and a level's player built on the game's (docs/scripting.md, "The
// player"). Played through the engine as such a level is.
#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "platon/core/display.h"
#include "platon/core/live_scene.h"
#include "platon/core/replay.h"
#include "platon/core/run.h"
#include "platon/script/script_system.h"
#include "platon/stage/level.h"
#include "platon/testing/temp_folder.h"

namespace platon::script {
namespace {

using Folder = testing::TempFolder;

// A cube: the player starts on face 0 above a floor whose words are `floorWords`; a wall across
// the walk to the right (x 2000) has the words `wallWords`. Mods are written as given, in order.
struct ModLevel {
  Folder folder;
  std::string scene;
  ModLevel(const std::string& name, const std::string& floorWords, const std::string& wallWords,
           const std::vector<std::string>& mods, const std::string& player = "")
      : folder(name) {
    folder.write("cube.level", "HEXAHEDRON\n0 600 700\n2 2000 800\n4096\n%\n256 512 4096 512 " + floorWords +
                                   "\n2000 513 2000 1400 " + wallWords +
                                   "\n%\n0 512 4096 512\n%\n0 512 4096 512\n%\n0 512 4096 512\n%\n%\n");
    std::string list;
    for (size_t i = 0; i < mods.size(); ++i) {
      const std::string file = "mod" + std::to_string(i + 1) + ".lua";
      folder.write(file, mods[i]);
      list += "'" + file + "', ";
    }
    if (!player.empty()) folder.write("player.lua", player);
    scene =
        folder.write("scene.lua",
                     "return { systems = { 'scripting' }, stage = { level = 'cube.level' }, gravity = 0.35,"
                     " scripts = { preset = 'game', " +
                         std::string(player.empty() ? "" : "player = 'player.lua', ") + "mods = { " + list + "} } }\n");
  }
};

core::SystemRegistry scripting() {
  core::SystemRegistry registry;
  registry.add("scripting", makeScriptSystem);
  return registry;
}

ScriptSystem& scriptsOf(core::LiveScene& live) {
  return dynamic_cast<ScriptSystem&>(*live.scene().findSystem("scripting"));
}

struct Played {
  int32_t highest = 0, farthest = 0;  // the player's largest y and x on face 0
  GameStatus last;
  std::set<std::string> messages;  // every message shown
};

// Plays `frames` frames, holding right when asked, jumping on the frames in `jumps` (counted from
// this call's first); no frame may fail.
Played play(core::LiveScene& live, int frames, bool right, const std::set<int>& jumps = {}) {
  Played run;
  core::InputEdges edges;
  for (int f = 0; f < frames; ++f) {
    const core::Buttons held = (right ? core::InputFrame::bit(core::Button::Right) : 0) |
                               (jumps.count(f) ? core::InputFrame::bit(core::Button::Jump) : 0);
    const std::optional<std::string> error = live.step(edges.next(held));
    EXPECT_FALSE(error.has_value()) << *error;
    run.last = scriptsOf(live).status();
    run.messages.insert(run.last.message);
    if (run.last.face == live.scene().stage()->part(0)) {
      run.highest = std::max(run.highest, run.last.y);
      run.farthest = std::max(run.farthest, run.last.x);
    }
  }
  return run;
}

// A springboard in five lines: what the issue asked of a mod's tag.
const char* kSprings =
    "return { tags = { spring = { color = '#cc79a7', glow = true,\n"
    "  contact = function(game, entity, tag, kind, part, line, nx, ny)\n"
    "    game.world.setVelocity(entity, nx * 20, ny * 20)\n"
    "    return { keepVelocity = true }\n"
    "  end } } }\n";

TEST(Tags, AModsWordInTheLevelFileLaunchesThePlayer) {
  ModLevel sprung("tags_spring", "spring", "", {kSprings});
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(sprung.scene, registry, false);
  const Played withSpring = play(live, 240, false);
  // The same level on a plain floor: the player lands at y 608 and stays.
  ModLevel plain("tags_plain", "solid", "", {kSprings});
  core::LiveScene still(plain.scene, registry, false);
  const Played withoutSpring = play(still, 240, false);
  EXPECT_LT(withoutSpring.highest, 710);
  // Thrown up at 20 units a frame against 0.35 of gravity: about 570 units over the floor.
  EXPECT_GT(withSpring.highest, 1100) << "the spring did not throw the player";
  EXPECT_EQ(withSpring.last.deaths, 0);
}

// A conveyor: its line carries what stands on it. `contact` runs where a move meets a line; a body
// at rest is not moved, so it meets nothing and no `contact` runs for it (a belt switched on under
// a player who has long stood still did not start it). What acts on what rests on a line reads the
// contacts in `tick`: the documented way (docs/scripting.md, Tags), which starts a standing player.
TEST(Tags, AConveyorStartsAPlayerStandingOnItFromItsTick) {
  const std::string on = "game.frame() >= 200";  // switched on once the player has long stood still
  const std::string byContact =
      "return { tags = { conveyor = { color = '#56b4e9',\n"
      "  contact = function(game, entity)\n"
      "    if not (" +
      on +
      ") then return nil end\n"
      "    local _, vy = game.world.velocity(entity)\n"
      "    game.world.setVelocity(entity, 6, vy)\n"
      "    return { keepVelocity = true }\n"
      "  end } } }\n";
  const std::string byTick =
      "local CONVEYOR\n"
      "return { tags = { conveyor = { color = '#56b4e9' } },\n"
      "  tick = function(game)\n"
      "    CONVEYOR = CONVEYOR or platon.tags.conveyor\n"
      "    local w, p = game.world, game.player()\n"
      "    if not p or not (" +
      on +
      ") then return end\n"
      "    for i = 1, w.contactCount(p) do\n"
      "      local _, _, tag = w.contact(p, i)\n"
      "      if tag == CONVEYOR then\n"
      "        local _, vy = w.velocity(p)\n"
      "        w.setVelocity(p, 6, vy)  -- along the belt, whatever the player did\n"
      "        return\n"
      "      end\n"
      "    end\n"
      "  end }\n";
  const core::SystemRegistry registry = scripting();
  ModLevel contactBelt("tags_conveyor_contact", "conveyor", "", {byContact});
  core::LiveScene resting(contactBelt.scene, registry, false);
  EXPECT_LT(play(resting, 400, false).farthest, 700) << "contact ran for a body at rest (docs say it does not)";
  ModLevel tickBelt("tags_conveyor_tick", "conveyor", "", {byTick});
  core::LiveScene carried(tickBelt.scene, registry, false);
  const Played run = play(carried, 400, false);
  EXPECT_GT(run.farthest, 1500) << "the belt's tick did not start the standing player";
  ModLevel plain("tags_conveyor_plain", "solid", "", {byTick});
  core::LiveScene still(plain.scene, registry, false);
  EXPECT_LT(play(still, 400, false).farthest, 700) << "off the belt the player stands";
}

TEST(Tags, TheModsTagIsInTheTableWithItsLookAndNumberForTheRendererAndLua) {
  ModLevel level("tags_look", "spring", "", {kSprings});
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const stage::TagKind* spring = live.scene().tags()->find("spring");
  ASSERT_NE(spring, nullptr);
  EXPECT_GE(spring->number, stage::kFirstModTag);
  EXPECT_NE(spring->owner.find("mod1.lua"), std::string::npos) << spring->owner;
  EXPECT_EQ(spring->style.r, 0xcc);
  EXPECT_TRUE(spring->style.glow);
  // The renderer's view of the floor: the spring's colour, from the table.
  const auto view = core::stageView(live.scene(), live.scene().stage()->part(0));
  bool drawn = false;
  for (const core::ViewLine& l : view->faces[0].lines)
    drawn = drawn || (l.tag == spring->number && l.style.r == 0xcc && l.style.g == 0x79 && l.style.glow);
  EXPECT_TRUE(drawn) << "the floor is not drawn in the spring's look";
  // Lua sees the same table.
  EXPECT_EQ(scriptsOf(live).evaluate("return platon.tags.spring", "t"), std::to_string(spring->number));
  EXPECT_EQ(scriptsOf(live).evaluate("return platon.tags.hazard", "t"), "1");
  EXPECT_EQ(scriptsOf(live).evaluate("for _, k in ipairs(platon.tagKinds) do if k.word == 'spring' then "
                                     "return k.color .. ' ' .. k.passable end end",
                                     "t"),
            "#cc79a7 wall");
}

TEST(Tags, APassableModTagLetsThePlayerThroughAndSaysWhenEntered) {
  const std::string gate =
      "return { tags = { gate = { passable = true, color = '#56b4e9',\n"
      "  beginContact = function(game) game.message('through the gate') end } } }\n";
  ModLevel level("tags_gate", "", "gate", {gate});
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played run = play(live, 300, true);
  EXPECT_EQ(run.last.message, "through the gate");
  EXPECT_GT(run.farthest, 2200) << "the gate stopped the player";
  // The same wall as a plain wall stops it.
  ModLevel wall("tags_wall", "", "solid", {gate});
  core::LiveScene stopped(wall.scene, registry, false);
  EXPECT_LT(play(stopped, 300, true).farthest, 2000);
}

TEST(Tags, AModTagsPassageMayBeAFunctionLikeADoor) {
  // Open from frame 100 on: the player, walking from frame 0, waits at it until then.
  const std::string gate =
      "return { tags = { gate = { passable = function(game) return game.frame() >= 100 end } } }\n";
  ModLevel level("tags_door", "", "gate", {gate});
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  EXPECT_LT(play(live, 95, true).farthest, 2000);
  EXPECT_GT(play(live, 200, true).farthest, 2200);
}

TEST(Tags, ModsAddHandlersToTheGamesTagsAndComposeInTheManifestsOrder) {
  // Both mods answer the spring's contact; the second's answer (later in the manifest) is the
  // contact's: a spring the second mod made dead.
  const std::string second =
      "return { tags = { spring = { contact = function(game) game.message('second') return {} end },\n"
      "                  hazard = { contact = function(game) game.message('hazard seen') end } } }\n";
  ModLevel level("tags_order", "spring", "", {kSprings, second});
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  const Played run = play(live, 240, false);
  EXPECT_EQ(run.last.message, "second");
  EXPECT_LT(run.highest, 710) << "the later mod's answer did not win";
  // The game's hazard still kills, and the mod saw it.
  ModLevel deadly("tags_hazard", "hazard", "", {kSprings, second});
  core::LiveScene dying(deadly.scene, registry, false);
  const Played died = play(dying, 120, false);
  EXPECT_GE(died.last.deaths, 1);
  EXPECT_TRUE(died.messages.count("hazard seen")) << "the mod's hazard handler never ran";
}

// Every way a mod's tags can be wrong is refused when the scene loads, naming the mod and the word.
TEST(Tags, AWrongDeclarationIsTheModsErrorByName) {
  const std::pair<std::string, std::string> cases[] = {
      {"return { tags = { spring = { color = 'pink' } } }", "mod1.lua: tags.spring.color: expected a colour"},
      {"return { tags = { spring = { glow = 1 } } }", "mod1.lua: tags.spring.glow: expected true or false"},
      {"return { tags = { spring = { bounce = 2 } } }", "mod1.lua: tags.spring.bounce: expected one of color"},
      {"return { tags = { spring = { contact = 3 } } }", "mod1.lua: tags.spring.contact: expected a function"},
      {"return { tags = { spring = 5 } }", "mod1.lua: tags.spring: expected a table"},
      {"return { tags = 'spring' }", "mod1.lua: tags: expected a table of tag words"},
      {"return { tags = { [1] = {} } }", "mod1.lua: tags: the keys are tag words"},
      {"return { tags = { hazard = { color = '#000000' } } }",
       "mod1.lua: tags.hazard: the tag 'hazard' is the game's: a mod may add handlers to it, not change its look"},
      {"return { tags = { spring = { contact = function() end } } }",
       "mod1.lua: tags.spring: no tag 'spring' to add handlers to"},
      {"return { tags = { tag = { color = '#000000' } } }", "mod1.lua: tags.tag: 'tag' is the level format's own"},
      {"return { tags = { oneway = { glow = true } } }", "mod1.lua: tags.oneway: 'oneway' is the level format's own"},
      {"return { tags = { ['2x'] = { glow = true } } }", "mod1.lua: tags.2x: '2x' is no tag word"},
  };
  const core::SystemRegistry registry = scripting();
  int i = 0;
  for (const auto& [mod, expected] : cases) {
    SCOPED_TRACE(mod);
    ModLevel level("tags_wrong_" + std::to_string(i++), "", "", {mod});
    try {
      core::LiveScene live(level.scene, registry, false);
      ADD_FAILURE() << "loaded";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
  // The same word from two mods: the second is told whose it is.
  ModLevel twice("tags_twice", "", "", {kSprings, kSprings});
  try {
    core::LiveScene live(twice.scene, registry, false);
    ADD_FAILURE() << "loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("mod2.lua: tags.spring: the tag 'spring' is "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("mod1.lua's: a mod may add handlers to it"), std::string::npos) << e.what();
  }
}

TEST(Tags, ALevelWritingAWordNoModDeclaresListsTheKnownOnes) {
  ModLevel level("tags_unknown", "springy", "", {kSprings});
  const core::SystemRegistry registry = scripting();
  try {
    core::LiveScene live(level.scene, registry, false);
    ADD_FAILURE() << "loaded";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cube.level:6:18: unknown segment word 'springy'"), std::string::npos) << what;
    EXPECT_NE(what.find("door N, switch N, spring, tag N"), std::string::npos) << what;
  }
}

TEST(Tags, AReloadKeepsTheModsTags) {
  ModLevel level("tags_reload", "spring", "", {kSprings});
  const core::SystemRegistry registry = scripting();
  core::LiveScene live(level.scene, registry, false);
  play(live, 30, false);
  const core::ReloadReport r = live.reload();
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_GT(play(live, 240, false).highest, 1100);
}

// The player: a double jump and a wall jump, each a few lines on top of the game's player, which a
// level's own player script is handed (docs/scripting.md, "The player").
const char* kDoubleJump =
    "local game, Player = ...\n"
    "local canJump = Player.canJump\n"
    "function Player.canJump(self)\n"
    "  if self.grounded then self.airJumps = 1 end\n"
    "  if canJump(self) then return true end\n"
    "  if (self.airJumps or 0) == 0 then return false end\n"
    "  self.airJumps = self.airJumps - 1\n"
    "  return true\n"
    "end\n"
    "return Player\n";

const char* kWallJump =
    "local game, Player = ...\n"
    "local canJump, jump = Player.canJump, Player.jump\n"
    "function Player.canJump(self) return canJump(self) or self.wall ~= 0 end\n"
    "function Player.jump(self, along)\n"
    "  if self.grounded or self.wall == 0 then return jump(self, along) end\n"
    "  return self.wall * Player.WALK_SPEED, -Player.JUMP_SPEED  -- off the wall\n"
    "end\n"
    "return Player\n";

TEST(ExtendedPlayer, ADoubleJumpJumpsAgainInTheAirAndOnlyOnce) {
  const core::SystemRegistry registry = scripting();
  // Landed by frame 60; jump at 60, again near the top (75), and once more (90), each held for 12
  // frames (a released jump is cut short).
  std::set<int> jumps;
  for (int at : {60, 75, 90})
    for (int f = at; f < at + 12; ++f) jumps.insert(f);
  ModLevel game("player_game", "", "", {}), doubled("player_double", "", "", {}, kDoubleJump);
  core::LiveScene plain(game.scene, registry, false), extended(doubled.scene, registry, false);
  const Played one = play(plain, 160, false, jumps), two = play(extended, 160, false, jumps);
  // One jump held 12 frames: about 130 units over the 608 it stands at; the second adds as much
  // again, and the third nothing.
  EXPECT_LT(one.highest, 608 + 150);
  EXPECT_GT(two.highest, one.highest + 80) << "no second jump";
  EXPECT_LT(two.highest, 608 + 2 * 150) << "a third jump: the air jump came back without landing";
  // Landed again, it has its air jump back.
  std::set<int> later;
  for (int at : {10, 25})
    for (int f = at; f < at + 12; ++f) later.insert(f);
  const Played again = play(extended, 160, false, later);
  EXPECT_GT(again.highest, one.highest + 80);
}

TEST(ExtendedPlayer, AWallJumpPushesOffTheWallTheGamesPlayerOnlySlidesDown) {
  const core::SystemRegistry registry = scripting();
  // Walk right into the wall at x 2000 (reached by frame 200), jump, and jump again against it,
  // each held for 10 frames.
  std::set<int> jumps;
  for (int at : {200, 212})
    for (int f = at; f < at + 10; ++f) jumps.insert(f);
  ModLevel game("wall_game", "", "", {}), walled("wall_jump", "", "", {}, kWallJump);
  core::LiveScene plain(game.scene, registry, false), extended(walled.scene, registry, false);
  play(plain, 213, true, jumps);
  play(extended, 213, true, jumps);
  const Played stays = play(plain, 12, true), off = play(extended, 12, true);
  EXPECT_GT(stays.last.x, 1880) << "the game's player left the wall";
  EXPECT_LT(off.last.x, 1880) << "no push off the wall";
  EXPECT_GT(off.highest, stays.highest) << "the wall jump did not go up";
}

TEST(ExtendedPlayer, TheBaseIsTheLevelsOwnCopyRunInItsLimits) {
  // What the level changes in its player is its own: the game's player (another level, the same
  // process) is untouched; and a loop in the base's overridden hook is stopped by the budget.
  const core::SystemRegistry registry = scripting();
  ModLevel fast("player_fast", "", "", {}, "local game, Player = ...\nPlayer.WALK_SPEED = 30\nreturn Player\n");
  core::LiveScene quick(fast.scene, registry, false);
  ModLevel game("player_plain", "", "", {});
  core::LiveScene plain(game.scene, registry, false);
  EXPECT_GT(play(quick, 60, true).farthest, play(plain, 60, true).farthest + 300) << "the level's speed is not used";
  EXPECT_EQ(scriptsOf(plain).evaluate("local game = ... return game.Player.WALK_SPEED", "t"), "9");
  ModLevel looping("player_loop", "", "", {},
                   "local game, Player = ...\nfunction Player.canJump() while true do end end\nreturn Player\n");
  core::LiveScene loops(looping.scene, registry, false);
  core::InputEdges edges;
  std::optional<std::string> error;
  for (int f = 0; f < 80 && !error; ++f)
    error = loops.step(edges.next(f == 70 ? core::InputFrame::bit(core::Button::Jump) : 0));
  ASSERT_TRUE(error.has_value()) << "the loop ran unchecked";
  EXPECT_NE(error->find("player.lua:2"), std::string::npos) << *error;
}

}  // namespace
}  // namespace platon::script

namespace platon::script {
namespace {

// A mod's contact handler that answers what the world cannot take (a string, a restitution out of
// range) is the mod's error, named by the mod's file: never the scene driver's (which hands the
// answers on). The frame goes on, with no answer from that handler.
TEST(Tags, AModsBadContactAnswerIsTheModsError) {
  for (const std::string answer : {"'bouncy'", "{ restitution = 2 }", "42"}) {
    SCOPED_TRACE(answer);
    ModLevel level(
        "tags_bad_answer", "spring", "",
        {"return { tags = { spring = { color = '#cc79a7', contact = function() return " + answer + " end } } }\n"});
    const core::SystemRegistry registry = scripting();
    core::LiveScene live(level.scene, registry, false);
    core::InputEdges edges;
    std::string errors;
    for (int f = 0; f < 90; ++f)
      if (const std::optional<std::string> e = live.step(edges.next(0))) errors += *e + "\n";
    EXPECT_EQ(
        errors.rfind("mod1.lua: the contact handler of tag " + std::to_string(stage::kFirstModTag) + " returned", 0),
        0u)
        << errors;
    EXPECT_EQ(errors.find("0x"), std::string::npos) << "an address in the report:\n" << errors;
  }
}

}  // namespace
}  // namespace platon::script

namespace platon::script {
namespace {

// The ```lua block of `kind` that first follows `heading` in docs/scripting.md.
std::string docsBlock(const std::string& heading, const std::string& kind) {
  std::ifstream in(std::string(PLATON_SOURCE_ROOT) + "/docs/scripting.md");
  std::string line, code;
  bool after = false, inside = false;
  while (std::getline(in, line)) {
    if (line == heading) after = true;
    if (inside && line == "```") return code;
    if (inside) code += line + "\n";
    if (after && line == "```lua " + kind) inside = true;
  }
  return "";
}

// The docs' table of the engine's actions is the code's: names, keys, pad buttons, what they do.
TEST(Actions, TheDocsListTheEnginesActions) {
  std::ifstream in(std::string(PLATON_SOURCE_ROOT) + "/docs/scripting.md");
  std::vector<std::string> rows;
  bool after = false;
  for (std::string line; std::getline(in, line);) {
    if (line == "## Actions")
      after = true;
    else if (after && line.rfind("## ", 0) == 0)
      break;
    if (after && line.rfind("| `", 0) == 0) rows.push_back(line);
  }
  auto list = [](const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? std::string("-") : out;
  };
  const std::vector<core::Action>& actions = core::engineActions();
  ASSERT_EQ(rows.size(), actions.size());
  for (size_t i = 0; i < actions.size(); ++i) {
    const core::Action& a = actions[i];
    EXPECT_EQ(rows[i], "| `" + a.name + "` | " + list(a.keys) + " | " + list(a.pad) + " | " + a.does + " |");
  }
}

// The docs' dash (a mod's action and the level's player that uses it) dashes, and a recorded run
// of it plays back by the action's name.
TEST(Actions, TheDocumentedDashDashes) {
  const std::string mod = docsBlock("## Actions", "mod"), player = docsBlock("## Actions", "player");
  ASSERT_NE(mod.find("dash"), std::string::npos) << "the docs' dash mod is gone";
  ASSERT_NE(player.find("Player.move"), std::string::npos) << "the docs' dash player is gone";
  ModLevel level("actions_dash", "solid", "", {mod}, player);
  const core::SystemRegistry registry = scripting();
  auto walk = [&](bool dash, std::optional<core::Replay>* recorded) {
    core::LiveScene live(level.scene, registry, false);
    const std::optional<int> bit = core::actionIndex(live.scene().actions(), "dash");
    EXPECT_EQ(bit, 8) << "the mod's action follows the engine's eight";
    core::Run run(live);
    if (recorded) run.record({"scene.lua", 10, std::nullopt, std::nullopt, 100});
    for (int f = 1; f <= 60; ++f) {
      const auto held = static_cast<core::Buttons>(core::InputFrame::bit(core::Button::Right) |
                                                   (dash && bit && f >= 20 && f < 23 ? 1u << *bit : 0u));
      const std::optional<std::string> error = run.step(held);
      EXPECT_FALSE(error.has_value()) << *error;
    }
    if (recorded) *recorded = run.stopRecording();
    return scriptsOf(live).status().x;
  };
  std::optional<core::Replay> replay;
  const int32_t walked = walk(false, nullptr), dashed = walk(true, &replay);
  EXPECT_GT(dashed, walked + 150) << "the dash carried the player no farther than walking";
  ASSERT_TRUE(replay.has_value());
  const std::string text = core::formatReplay(*replay);
  EXPECT_NE(text.find(" right dash\n"), std::string::npos) << text;
  const core::Replay back = core::parseReplay(text, "dash.replay");
  core::LiveScene again(level.scene, registry, false);
  core::Run playback(again);
  core::ReplayInput input(back, again.scene());
  while (!input.over(playback.frame())) playback.step(input.next(playback));
  EXPECT_EQ(again.scene().world().stateHash(), back.hashes.back().hash);
  EXPECT_EQ(scriptsOf(again).status().x, dashed);
}

// A mod's action that cannot be is the mod's error by name, when the scene loads.
TEST(Actions, AModsActionThatCannotBeIsItsErrorByName) {
  const std::pair<std::string, std::string> cases[] = {
      {"return { actions = { jump = {} } }", "mod1.lua: actions.jump: the action 'jump' is the engine's"},
      {"return { actions = { dash = { keys = 'X' } } }", "mod1.lua: actions.dash.keys: expected a list of names"},
      {"return { actions = { dash = { speed = 3 } } }",
       "mod1.lua: actions.dash.speed: expected one of keys, pad, label, does"},
      {"return { actions = { ['2x'] = {} } }", "mod1.lua: actions.2x: '2x' is no action name"},
      {"return { actions = { pressed = {} } }", "mod1.lua: actions.pressed: 'pressed' is input.pressed"},
      {"return { actions = { a = {}, b = {}, c = {}, d = {}, e = {}, f = {}, g = {}, h = {}, i = {} } }",
       "mod1.lua: actions: more than 8 actions"},
  };
  const core::SystemRegistry registry = scripting();
  for (const auto& [code, error] : cases) {
    ModLevel level("actions_bad", "solid", "", {code});
    try {
      core::LiveScene live(level.scene, registry, false);
      ADD_FAILURE() << code << " loaded";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(error), std::string::npos) << e.what();
    }
  }
  // Two mods may not take one name.
  ModLevel twice("actions_twice", "solid", "",
                 {"return { actions = { dash = {} } }", "return { actions = { dash = {} } }"});
  try {
    core::LiveScene live(twice.scene, registry, false);
    ADD_FAILURE() << "two dashes loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("mod2.lua: actions.dash: the action 'dash' is "), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace platon::script
