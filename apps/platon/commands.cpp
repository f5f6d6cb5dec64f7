#include "commands.h"

#include <cstdio>

#include "defs_command.h"
#include "edit_command.h"
#include "game_command.h"
#include "merge_command.h"
#include "pack_command.h"
#include "play_command.h"
#include "run_command.h"
#include "shot_command.h"
#include "stage_commands.h"

namespace platon::app {
namespace {

// Options shared by run and replay (one parser: runCommand).
#define PLATON_RUN_OPTIONS                                                                                          \
  "  -j N             run N files at a time (1..256; default 1)\n"                                                  \
  "  --timeout S      each file's wall-clock limit in seconds (default 600)\n"                                      \
  "  --trace N        print the player's state every N frames to stderr while it runs: the frame, face,\n"          \
  "                   position and velocity (units, units per frame), grounded, deaths, the switches on\n"          \
  "                   and the last checkpoint (for finding the inputs that finish a level)\n"                       \
  "  --record DIR     write each file's run as a replay into the folder DIR (made if missing): DIR/<name>.replay\n" \
  "  --hash-every N   with --record: a state hash every N frames in the replay (default 60; 0: only the last\n"     \
  "                   frame's), so a replay that stops matching says at which frame\n"                              \
  "  --junit F        a JUnit XML report in F\n"                                                                    \
  "  --shard I/N      run only the I-th of N shards (1 <= I <= N); without it, Bazel's, GoogleTest's\n"             \
  "                   and GitLab's sharding variables are read (docs/shipping.md)\n"                                \
  "  --shards N       N shards, this one JOB_COMPLETION_INDEX's (a Kubernetes indexed job)\n"                       \
  "  --durations F    balance the shards by the times in JUnit report F (an earlier run's)\n"                       \
  "  --list           print this shard's files, one a line, and run nothing\n"

constexpr const char* kLevelArgument =
    "  LEVEL            a level's folder (levels/cube_intro), its scene.lua, its .level file, or a folder\n"
    "                   name under levels/ (cube_intro)\n";

const Command kCommands[] = {
    {"game", "the game in a window: title screen, campaign, settings",
     "usage: platon game [--campaign levels/campaign.txt] [--progress file] [--settings file] [--record DIR]\n"
     "                   [--levels DIR]\n"
     "  --campaign F     the campaign's level list (default levels/campaign.txt)\n"
     "  --progress F     the finished levels and best times (default $XDG_DATA_HOME/platon/progress.txt)\n"
     "  --settings F     volumes, keys, display (default $XDG_CONFIG_HOME/platon/settings.txt)\n"
     "  --record DIR     write a replay of each level played to DIR/<level>.replay\n"
     "  --levels DIR     the player's own levels, listed after the campaign (default\n"
     "                   $XDG_DATA_HOME/platon/levels: platon install puts them there)\n"
     "keys: arrows or WASD move, Space jumps, R restarts, Esc pauses, Tab settings, F5 reloads,\n"
     "      F2 debug view, ` console (Lua in the level's sandbox), F3 frame rate, F11 fullscreen,\n"
     "      F12 screenshot; a gamepad works too (A jumps and chooses, Start pauses, Y settings)\n",
     gameCommand},
    {"play", "one level in a window (or headless), with hot reload",
     "usage: platon play LEVEL [--frames N] [--input run.replay] [--record out.replay]\n"
     "                         [--watch] [--fast] [--headless] [--shot out.png]\n"
     "  --frames N       stop after N frames, N >= 1 (default: at the goal, or never with --watch)\n"
     "  --input F        the buttons of a recorded run (nothing held without it)\n"
     "  --record F       write this run's input and hashes to F as a replay (also when stopped by\n"
     "                   SIGINT or SIGTERM; F is checked before playing)\n"
     "  --watch          reload the scene when its files are saved\n"
     "  --fast           do not wait for real time\n"
     "  --headless       no window, even when the scene names \"rendering\"; exits 1 if a frame had a\n"
     "                   script error\n"
     "  --shot F         save the last frame shown to F (PNG) at the end\n"
     "keys in the window: arrows or WASD move, Space jumps, R restarts, F2 debug view, F3 frame rate,\n"
     "F11 fullscreen, F12 screenshot, Esc quits\n"
     "SIGINT or SIGTERM ends the play after the frame; if the frame does not end, a second signal, or\n"
     "3 s after the first ($PLATON_STOP_GRACE seconds if set), ends it at once, without writing the recording\n",
     playCommand},
    {"edit", "the level editor: draw on the solid, check, play from the cursor, keep a run as a test",
     "usage: platon edit LEVEL [--new SOLID|mesh-file]\n"
     "  LEVEL            the level's folder, scene.lua, .level file or name\n"
     "  --new S          make LEVEL (a new folder) first: a level on the solid S (TETRAHEDRON,\n"
     "                   HEXAHEDRON, OCTAHEDRON, DODECAHEDRON, ICOSAHEDRON) or on a mesh file (copied in)\n"
     "  --shot F         save the editor's first picture to F (PNG) and quit\n"
     "in the window: left button draws (drag, or click and click), S selects (drag moves ends,\n"
     "segments, the start and the goal), right button turns the solid, the wheel zooms; T tag,\n"
     "[ ] number, O one-way, P start, G goal, V gravity, F face, Ctrl+Z/Y, Ctrl+C/V, Del,\n"
     "Ctrl+S save, Enter plays from the cursor (K keeps a run that reached the goal as a test), Esc\n"
     "(docs/editing.md)\n",
     editCommand},
    {"shot", "a level's picture after N frames, as a PNG (offscreen)",
     "usage: platon shot LEVEL [--frame N] [--size WxH] [--input run.replay] [--debug] --out file.png\n"
     "  --frame N        the picture after N frames (default 0: the start)\n"
     "  --size WxH       pixels (default 1280x720)\n"
     "  --input F        the buttons of a recorded run\n"
     "  --debug          the debug view over it (F2 in a window): lines by kind and tag, platforms,\n"
     "                   bodies and their copies across edges, velocities, contacts and normals\n"
     "  --out F          the PNG to write\n",
     shotCommand},
    {"run", "scenarios and replays, headless: pass or fail each",
     "usage: platon run [options] scenario.lua|run.replay...\n" PLATON_RUN_OPTIONS, runCommand},
    {"replay", "replays, headless: each must reproduce its recorded hashes bit for bit",
     "usage: platon replay [options] run.replay...   (the same as platon run, for replays)\n" PLATON_RUN_OPTIONS,
     runCommand},
    {"scenario", "a scenario made from a replay that finishes its level",
     "usage: platon scenario run.replay [-o scenario.lua]\n"
     "  -o F             write the scenario to F (default: stdout)\n",
     scenarioCommand},
    {"merge", "the JUnit reports of sharded runs joined, each scenario checked to have run once",
     "usage: platon merge -o all.xml shard.xml...\n"
     "  joins the JUnit reports of `platon run --shard I/N ... --junit shard.xml` (or another\n"
     "  runner's sharding); fails, naming it, when a shard is missing or given twice, when the\n"
     "  reports are of different suites, or when a scenario ran twice or not at all\n",
     mergeCommand},
    {"check", "a level's errors and warnings, at file:line:column",
     "usage: platon check LEVEL...\n"
     "  prints each error and warning a level designer wants (a start or goal inside a wall, a sealed\n"
     "  goal, a segment leaving its face, ...); exits 1 when a level has an error\n",
     checkCommand},
    {"net", "a solid's or a level's faces unfolded, as an SVG",
     "usage: platon net SOLID|LEVEL -o net.svg\n"
     "  SOLID            TETRAHEDRON, HEXAHEDRON, OCTAHEDRON, DODECAHEDRON or ICOSAHEDRON\n",
     netCommand},
    {"pack", "a level and a run that finishes it, as one package to share",
     "usage: platon pack LEVEL --replay run.replay [-o out.platon] [--timeout S]\n"
     "  LEVEL            the level's folder (or its scene.lua): every file in it goes in\n"
     "  --replay F       a run that reaches the goal (platon play --record, platon game --record), or\n"
     "                   a test the editor kept with K (test_N.lua, played to its recording);\n"
     "                   replayed headless first: the level must check and the run reach its goal\n"
     "  -o F             the package (default FOLDER.platon)\n"
     "  --timeout S      the replay's wall-clock limit (default 120)\n",
     packCommand},
    {"install", "a level package into the player's levels (listed on the title screen)",
     "usage: platon install PACKAGE [--levels DIR] [--timeout S]\n"
     "  unpacks it only inside its own folder (links, devices, '..' and files not in its manifest or\n"
     "  not matching their SHA-256 are refused), checks the level and replays its run headless in\n"
     "  a worker process; installs it only when the run reaches the goal\n"
     "  --levels DIR     where (default $XDG_DATA_HOME/platon/levels)\n"
     "  --timeout S      the replay's wall-clock limit (default 120)\n",
     installCommand},
    {"defs", "the Lua language server's definitions of the scripting API",
     "usage: platon defs DIR [--for LEVEL]\n"
     "  writes DIR/trusted (the engine's own scripts) and DIR/sandbox (level scripts and mods): ---@meta\n"
     "  definitions made from the engine's binding tables, and a .luarc.json pointing the server at them\n"
     "  --for LEVEL      also LEVEL/.luarc.json, pointing at DIR/sandbox by a path from LEVEL\n",
     defsCommand},
};

}  // namespace

std::span<const Command> commands() { return kCommands; }

const Command* findCommand(std::string_view name) {
  for (const Command& c : kCommands)
    if (name == c.name) return &c;
  return nullptr;
}

int usageError(std::string_view name) {
  if (const Command* c = findCommand(name)) {
    std::fputs(c->usage, stderr);
    if (std::string_view(c->usage).find("LEVEL") != std::string_view::npos) std::fputs(kLevelArgument, stderr);
  }
  return 2;
}

void printCommands(bool toStdout) {
  FILE* out = toStdout ? stdout : stderr;
  std::fprintf(out, "usage: platon COMMAND [options]   (platon COMMAND --help: its options)\n");
  for (const Command& c : kCommands) std::fprintf(out, "  %-10s %s\n", c.name, c.summary);
  std::fprintf(out, "  (none)     the headless demo: a ball rolling on a cube [--frames N]\n");
}

}  // namespace platon::app
