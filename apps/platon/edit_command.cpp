// `platon edit LEVEL`: the level editor in a window (engine/editor: the document, the tools and
// the picture; here: the window, the files and play-testing). Enter plays the level as edited from
// the cursor's place in the same window, recording the run; Esc comes back; a run that reaches the
// goal is kept with K as a scenario beside the level (test_N.lua), checked headless at once.
// `--new SOLID` (or a mesh file) makes a new level's folder first.
#include "edit_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "commands.h"
#include "engine_registry.h"
#include "level_argument.h"
#include "platon/core/data_root.h"
#include "platon/core/fixed_step.h"
#include "platon/core/live_scene.h"
#include "platon/core/replay.h"
#include "platon/core/visible_text.h"
#include "platon/editor/editor.h"
#include "platon/files/write_file.h"
#include "platon/script/scenario.h"
#include "platon/session/session.h"
#include "platon/stage/polyhedron.h"
#include "save_file.h"

namespace platon::app {
namespace {

namespace fs = std::filesystem;

int editUsage() { return usageError("edit"); }

std::string makeLevelFolder(const std::string& folder, const std::string& solid);

// A new level's folder: scene.lua (the game's rules and player) and NAME.level on `solid` (a
// Platonic solid's name, or a mesh file copied in), the start and the goal on face 0 (no floor yet).
std::string makeNewLevel(std::string folder, const std::string& solid) {
  while (folder.size() > 1 && folder.back() == '/') folder.pop_back();  // levels/mine/ is levels/mine
  std::error_code error;
  if (fs::exists(folder, error))
    throw std::runtime_error(folder + ": already exists (platon edit " + folder + " edits it)");
  try {
    return makeLevelFolder(folder, solid);
  } catch (...) {
    fs::remove_all(folder, error);  // no half-made level left behind
    throw;
  }
}

std::string makeLevelFolder(const std::string& folder, const std::string& solid) {
  std::error_code error;
  const std::string name = fs::path(folder).filename().string();
  if (name.empty() || name.find_first_of("\"\\\n# ") != std::string::npos)
    throw std::runtime_error(folder + ": a level's folder name is a plain word (it names its .level file)");
  std::string header;
  int32_t size = 4096;
  bool known = false;
  for (const stage::Solid s : stage::kSolids) known = known || solid == stage::solidName(s);
  if (known) {
    header = solid;
  } else {
    if (!fs::is_regular_file(solid, error))
      throw std::runtime_error(solid +
                               ": neither a solid (TETRAHEDRON, HEXAHEDRON, OCTAHEDRON, DODECAHEDRON, "
                               "ICOSAHEDRON) nor a mesh file");
    fs::create_directories(folder, error);
    fs::copy_file(solid, fs::path(folder) / fs::path(solid).filename(), error);
    if (error) throw std::runtime_error(solid + ": cannot copy it into " + folder + ": " + error.message());
    header = "MESH " + fs::path(solid).filename().string();
  }
  // The start on face 0's left, the goal on its right, a floor's room under both; the faces are
  // counted from the solid (a mesh's once the editor reads it).
  std::string faces;
  size_t count = 0;
  if (known) {
    for (const stage::Solid s : stage::kSolids)
      if (solid == stage::solidName(s)) count = stage::platonicStage(s, size).faceCount();
  }
  const std::string level = "# " + name + ": made by `platon edit --new`. Draw on the solid; Ctrl+S saves.\n" + header +
                            "\n0 700 400           # start: face x y\n0 " + std::to_string(size - 900) +
                            " 400   # goal\n" + std::to_string(size) + "\n";
  faces = "%                    # face 0: draw a floor under the start and the goal\n";
  for (size_t f = 1; f < count; ++f) faces += "%                    # face " + std::to_string(f) + "\n";

  const std::string scene = "-- " + name + ": made by `platon edit --new`.\nreturn {\n  name = \"" + name +
                            "\",\n  systems = { \"scripting\", \"rendering\", \"audio\"" +
                            (known ? "" : ", \"meshes\"") + " },\n  stage = { level = \"" + name +
                            ".level\" },\n  scripts = { preset = \"game\" },\n}\n";
  for (const auto& [file, text] :
       {std::pair{name + ".level", level + faces}, std::pair{std::string("scene.lua"), scene}})
    if (const std::string why = files::saveWhole((fs::path(folder) / file).string(), text, "the new level");
        !why.empty())
      throw std::runtime_error(why);
  return folder;
}

// A mesh level made by --new has one '%' line: the faces of its mesh, now that the mesh is read.
std::string withFaces(std::string text, size_t faces) {
  if (!text.empty() && text.back() != '\n') text += '\n';  // a last line without its line end
  size_t have = 0;
  for (size_t at = 0; (at = text.find("\n%", at)) != std::string::npos; ++at) ++have;
  for (size_t f = have; f < faces; ++f) text += "%                    # face " + std::to_string(f) + "\n";
  return text;
}

// A new mesh level's start and goal, inside its face 0 whatever its shape: between the face's
// middle and its first two corners.
void placeOnFaceZero(editor::Editor& editor) {
  const auto& corners = editor.solid().faces[0].corners;
  const editor::FacePoint centre = editor::faceCentre(editor.solid(), 0);
  const double cx = centre.x, cy = centre.y;
  auto toward = [&](size_t k) {
    return physics::Vec2{static_cast<int32_t>(std::lround(cx + 0.4 * (corners[k].x - cx))),
                         static_cast<int32_t>(std::lround(cy + 0.4 * (corners[k].y - cy)))};
  };
  editor.document().edit("place the start and the goal", [&](stage::Level& l) {
    l.start.face = l.goal.face = 0;
    l.start.position = toward(0);
    l.goal.position = toward(1);
  });
  editor.rebuild();
}

// The next test_N.lua free in `folder`.
std::string nextTestPath(const std::string& folder) {
  for (int n = 1;; ++n) {
    std::string path = (fs::path(folder) / ("test_" + std::to_string(n) + ".lua")).string();
    std::error_code error;
    if (!fs::exists(fs::symlink_status(path, error))) return path;  // a link, even dangling, takes the name
  }
}

struct EditorWindow {
  std::string scenePath;  // as found (resolveDataPath)
  core::SystemRegistry& registry;
  core::System& window;  // the editor's rendering system: its window is shared with each play
  core::Display& display;
  editor::Editor& editor;
};

// Keeps a run that reached the goal as a scenario beside the level: the level saved first (the
// scenario plays the file), the scenario written and run headless at once.
std::string keepRun(EditorWindow& s, core::Scene& scene, const core::Replay& played, const script::GameStatus& status) {
  editor::LevelDocument& document = s.editor.document();
  if (document.modified()) document.save();
  core::Replay replay = played;
  replay.scene = "scene.lua";  // the scenario sits beside it
  replay.sceneFiles = core::sceneFilesHash(core::sceneSourceFiles(scene));
  script::ScenarioResult outcome;
  outcome.status = status;
  outcome.frames = replay.frames();
  const std::string folder = fs::path(s.scenePath).parent_path().string();
  const std::string path = nextTestPath(folder.empty() ? "." : folder);
  const std::string text = script::scenarioFromReplay(replay, outcome, "a play-test in `platon edit`");
  if (const std::string why = files::saveWhole(path, text, "the scenario"); !why.empty()) return "not kept: " + why;
  script::RunOptions options;
  options.pluginFolders = pluginFolders();
  const script::ScenarioResult check = script::runScenario(path, options);
  return "kept as " + path +
         (check.passed ? " (it passes headless: `platon run " + path + "`)"
                       : " but it does not pass headless: " + check.message);
}

// The play-test's lines under the heads-up text.
std::vector<std::string> playTestLines(const stage::LevelPoint& start, bool won, const std::string& kept) {
  std::vector<std::string> lines{"play-test from face " + std::to_string(start.face) + " (" +
                                 std::to_string(start.position.x) + ", " + std::to_string(start.position.y) +
                                 "): Esc goes back to the editor"};
  if (won) lines.push_back(kept.empty() ? "goal reached: K keeps this run as a test beside the level" : kept);
  return lines;
}

bool pressedK(const core::WindowInput& in) {
  return std::any_of(in.keys.begin(), in.keys.end(), [](const core::KeyPress& k) { return k.name == "K"; });
}

// K on a run that reached the goal: what keepRun says, or why it could not.
std::string keep(EditorWindow& w, session::Session& s) {
  std::string kept;
  try {
    kept = keepRun(w, s.scene(), *s.run().recorded(), s.status());
  } catch (const std::exception& e) {
    kept = std::string("not kept: ") + e.what();
  }
  std::printf("%s\n", kept.c_str());
  std::fflush(stdout);
  return kept;
}

// Plays the level as edited from the editor's cursor in the same window until Esc: a session
// (session.h) like the game's and `play`'s, with their tools (the console, F2, F3, F5, F12); the
// run stops at the goal, the picture goes on (the goal's flash fades), and K keeps the run.
void playFromCursor(EditorWindow& w) {
  const stage::LevelPoint start = w.editor.playStart();
  std::unique_ptr<core::LiveScene> live;
  try {
    live = std::make_unique<core::LiveScene>(w.scenePath, w.registry, false,
                                             core::LevelOverride{w.editor.document().text(), start});
  } catch (const std::exception& e) {
    w.editor.say("cannot play: " + core::visibleText(core::errorReport(e)));
    return;
  }
  core::System* rendering = live->scene().findSystem("rendering");
  if (!rendering) {
    w.editor.say("cannot play here: the scene does not name \"rendering\"");
    return;
  }
  rendering->carryOver(live->scene(), w.window);  // the same window
  session::Session s(std::move(live));
  s.run().record({core::portableScenePath(w.scenePath).value_or("scene.lua"), 60, std::nullopt,
                  core::ReplayStart{start.face, start.position.x, start.position.y}, 100});
  std::string kept;
  bool saidWon = false;
  std::printf("playing from face %d (%d, %d)\n", start.face, start.position.x, start.position.y);
  std::fflush(stdout);
  const auto reached = [](const script::GameStatus& status) { return status.won; };
  for (;;) {
    const core::WindowInput in = s.poll();
    if (in.closed || std::find(in.pressed.begin(), in.pressed.end(), core::Key::Escape) != in.pressed.end()) break;
    const bool won = s.status().won;  // the run ends at the goal: what is kept is the run that reached it
    if (won && kept.empty() && !s.consoleOpen() && pressedK(in)) kept = keep(w, s);
    if (!won) {
      s.playDue(in, 100, false, reached);
    } else {
      for (int due = s.framesDue(); due > 0; --due) s.idle();  // the goal's flash and confetti go on
    }
    const script::GameStatus status = s.status();
    if (status.won && !saidWon) {
      std::printf("goal reached at frame %llu\n", static_cast<unsigned long long>(status.wonFrame));
      std::fflush(stdout);
      saidWon = true;
    }
    s.draw({}, playTestLines(start, status.won, kept));
  }
  w.editor.say(kept.empty() ? std::string(s.status().won ? "back from a run that reached the goal (not kept)"
                                                         : "back from the play-test")
                            : kept);
}

}  // namespace

int editCommand(int argc, char** argv) {
  std::string argument, newSolid, shotPath;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--new" && i + 1 < argc)
      newSolid = argv[++i];
    else if (a == "--shot" && i + 1 < argc)
      shotPath = argv[++i];
    else if (argument.empty() && !a.empty() && a[0] != '-')
      argument = a;
    else
      return editUsage();
  }
  if (argument.empty()) return editUsage();
  LevelArgument level;
  try {
    if (!newSolid.empty()) argument = makeNewLevel(argument, newSolid);
    level = levelArgument(argument);
  } catch (const std::exception& e) {
    return std::fprintf(stderr, "platon edit: %s\n", e.what()), 2;
  }
  if (level.scene.empty())
    return std::fprintf(stderr,
                        "platon edit: %s has no scene.lua beside it: the editor plays the level in its scene "
                        "(its tags, gravity and solid); `platon edit --new SOLID FOLDER` makes both\n",
                        level.levelFile.c_str()),
           2;
  core::SystemRegistry registry = engineRegistry(Presentation::Window);
  const int result = editLevel(level, registry, nullptr, shotPath, !newSolid.empty());
  std::error_code error;
  if (result == 1 && !newSolid.empty()) fs::remove_all(argument, error);  // no half-made level left behind
  return result == kWindowClosed ? 0 : result;
}

namespace {

// The editor over the level's file, its solid built by the scene's systems in `host` (made in
// place: it is not moved); false (said why) when the level cannot be opened.
bool openEditor(const LevelArgument& level, core::SystemRegistry& registry, const std::string& scenePath,
                core::Scene& host, bool newLevel, std::optional<editor::Editor>& editor) {
  try {
    host.setManifest(core::loadManifest(scenePath));
    std::string text = stage::readLevelFile(level.levelFile);
    auto tags = core::sceneTags(scenePath, engineRegistry(Presentation::Headless));
    stage::Level parsed = stage::parseLevel(text, level.levelFile, tags);
    stage::Stage solid = core::levelStage(parsed, registry, host);
    // A mesh level without a '%' line for each face (a new one: its faces were not known before
    // the mesh was read) gets them; the file says so once saved (unsaved until then).
    const std::string onDisk = text;
    if (parsed.faces.size() < solid.faceCount() && !parsed.solid) text = withFaces(text, solid.faceCount());
    editor::LevelDocument document(level.levelFile, text, tags);
    document.assumeSaved(onDisk);
    editor.emplace(std::move(document), std::move(solid), std::llround(host.manifest().gravity * 65536.0));
    if (newLevel && !parsed.solid) placeOnFaceZero(*editor);
    if (newLevel && editor->document().modified()) editor->document().save();  // a new level is valid from the start
    return true;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "platon edit: %s\n", core::visibleText(core::errorReport(e), true).c_str());
    return false;
  }
}

// What happened this frame, in the terminal too (and for the window tests): each press's point,
// each screenshot, each message.
void echoFrame(const core::WindowInput& input, editor::Editor& editor, core::Display& display) {
  for (const core::MouseEvent& e : input.mouse)
    if (e.kind == core::MouseEvent::Kind::Down && e.button == 1)
      if (const auto p = editor.pointAt(e.x, e.y))
        std::printf("press at pixel (%.0f, %.0f): face %d (%.1f, %.1f)\n", double(e.x), double(e.y), p->face, p->x,
                    p->y);
  for (const core::KeyPress& key : input.keys)
    if (key.name == "F12") std::printf("%s\n", saveScreenshot(display).c_str());  // after this frame is shown
  for (const std::string& message : editor.takeMessages())
    std::printf("editor: %s\n", core::visibleText(message).c_str());
  std::fflush(stdout);
}

}  // namespace

int editLevel(const LevelArgument& level, core::SystemRegistry& registry, core::System* shown,
              const std::string& shotPath, bool newLevel) {
  const std::string scenePath = core::resolveDataPath(level.scene);
  core::Scene host;  // the editor's own scene: its window and, for a mesh, its meshes system
  std::optional<editor::Editor> editor;
  if (!openEditor(level, registry, scenePath, host, newLevel, editor)) return 1;
  std::unique_ptr<core::System> own = registry.create("rendering", host);
  if (own && shown) own->carryOver(host, *shown);  // the game's window, when the game opened the editor
  core::System* window = own.get();
  core::Display* display = window ? window->display() : nullptr;
  try {
    if (!display) throw std::runtime_error("this program has no renderer");
    display->pollEvents();  // opens the window
  } catch (const std::exception& e) {
    return std::fprintf(stderr, "platon edit: %s: the editor needs a window\n", e.what()), 1;
  }
  std::printf("editing %s (the window lists the keys at its top; docs/editing.md tells more)\n",
              level.levelFile.c_str());
  std::fflush(stdout);
  EditorWindow session{scenePath, registry, *window, *display, *editor};
  int frames = 0;
  bool closed = false;
  for (;;) {
    const core::WindowInput input = display->pollEvents();
    const editor::Editor::Request request = editor->handle(input);
    echoFrame(input, *editor, *display);
    if (request == editor::Editor::Request::Quit) {
      closed = input.closed;  // the window closed (or SIGTERM, which SDL turns into the same): all quit
      break;
    }
    if (request == editor::Editor::Request::Play) playFromCursor(session);
    core::DrawList list(true);
    editor->draw(list);
    display->present(editor->view(), list);
    if (!shotPath.empty() && ++frames == 3) {  // a picture of the editor as it opens, for the docs
      display->saveScreenshot(shotPath);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(4));
  }
  if (editor->document().modified())
    std::printf("quit with unsaved edits (not written to %s)\n", level.levelFile.c_str());
  return closed ? kWindowClosed : 0;
}

}  // namespace platon::app
