// Frame time of the game's renderer on each campaign level against a floor measured in the same
// run and the same GL context: the same triangles drawn by a minimal program (one buffer, one lit
// shader, one draw call, depth test, the same 1280x720 drawable). The floor is the least this
// rasterizer needs for the scene; the renderer adds the HUD's text, the per-frame shapes and its
// state changes. Each frame ends with glFinish, so the time is the frame's whole cost on a software
// rasterizer (Mesa llvmpipe here) rather than the time to queue it.
//
// Also: start-up to the first frame on screen (`platon game --quit-after-first-frame`, a fresh
// process each time, from fork to exit: an upper bound) and the game's peak memory (that
// process's maximum resident set).
//
// Also: the editor's frames (its picture of a level, steady and right after an edit), on a level of
// the campaign and on cubes of 10^3 and 10^4 segments, against the game's own picture of the same
// level from the same camera, drawn in the same run (the renderer's cost of the level itself).
//
// usage: SDL_VIDEODRIVER=offscreen build/bench/render_frames [--frames N] [--runs R]
#include <SDL2/SDL.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <epoxy/gl.h>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "platon/camera/camera.h"
#include "platon/core/display.h"
#include "platon/core/live_scene.h"
#include "platon/core/replay.h"
#include "platon/editor/editor.h"
#include "platon/script/script_system.h"
#include "platon/testing/rng.h"
#include "spread.h"
#include "stage_mesh.h"
#include "stage_renderer.h"

using namespace platon;
using Clock = std::chrono::steady_clock;

namespace {

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// The least lighting that still shows the faces apart: one dot product a vertex, the colour
// passed through per pixel; back faces culled. (Per-pixel lighting or no culling would make the
// floor slower than the game's renderer, which is no floor.)
const char* kFloorVertex = R"glsl(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 color;
uniform mat4 viewProjection;
uniform vec3 light;
out vec4 c;
void main() {
  gl_Position = viewProjection * vec4(position, 1.0);
  c = vec4(color.rgb * (0.3 + 0.7 * max(dot(normal, light), 0.0)), 1.0);
}
)glsl";
const char* kFloorFragment = R"glsl(#version 330 core
in vec4 c;
out vec4 fragColor;
void main() { fragColor = c; }
)glsl";

GLuint compile(GLenum type, const char* source) {
  const GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  return s;
}

// The floor: one program, one buffer, one draw call, then the swap.
struct Floor {
  GLuint program = 0, vao = 0, vbo = 0;
  GLsizei count = 0;
  Floor() {
    program = glCreateProgram();
    glAttachShader(program, compile(GL_VERTEX_SHADER, kFloorVertex));
    glAttachShader(program, compile(GL_FRAGMENT_SHADER, kFloorFragment));
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
      char log[1024] = "";
      glGetProgramInfoLog(program, sizeof log, nullptr, log);
      std::fprintf(stderr, "the floor's shader does not link: %s\n", log);
      std::exit(1);
    }
    glGenVertexArrays(1, &vao);
    glGenBuffers(1, &vbo);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    render::describeLitVertices();
    glBindVertexArray(0);
  }
  void upload(const std::vector<render::LitVertex>& v) {
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(v[0])), v.data(), GL_STATIC_DRAW);
    count = static_cast<GLsizei>(v.size());
  }
  void draw(const Eigen::Matrix4f& viewProjection) {
    glViewport(0, 0, 1280, 720);
    glClearColor(0.1f, 0.1f, 0.12f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glUseProgram(program);
    glUniformMatrix4fv(glGetUniformLocation(program, "viewProjection"), 1, GL_FALSE, viewProjection.data());
    glUniform3f(glGetUniformLocation(program, "light"), 0.3f, 0.5f, 0.8f);
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, count);
    glBindVertexArray(0);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
  }
};

struct Frames {
  std::vector<double> ours, floor;
  size_t triangles = 0;
  double floorCoverage = 0;  // share of the pixels the floor's draw call covered
};

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0 : s / static_cast<double>(v.size());
}
double p99(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(static_cast<double>(v.size()) * 0.99))];
}

// Plays the level's recorded run; every frame is drawn by the game's renderer and, right after, the
// same triangles by the floor program.
Frames measureLevel(const std::string& scenePath, const std::string& replayPath, const core::SystemRegistry& registry,
                    int frames, Floor*& floor) {
  core::LiveScene live(scenePath, registry, false);
  core::Display& display = *live.scene().findSystem("rendering")->display();
  display.resize(1280, 720);
  const core::Replay replay = core::readReplay(replayPath);
  auto status = [&] { return dynamic_cast<script::ScriptSystem*>(live.scene().findSystem("scripting"))->status(); };
  const auto stage = core::stageView(live.scene(), status().face);
  const render::StageMesh mesh(*stage);
  camera::Camera camera;
  auto target = [&] {
    const script::GameStatus s = status();
    return core::cameraTarget(*stage, live.scene(), s.face, static_cast<float>(s.x), static_cast<float>(s.y));
  };
  camera.set(target(), 1280, 720);
  core::InputEdges edges;
  Frames out;
  for (int f = 0; f < frames; ++f) {
    live.step(edges.next(static_cast<size_t>(f) < replay.held.size() ? replay.held[static_cast<size_t>(f)] : 0));
    camera.lerp(target(), 1.0 / 60);
    const script::GameStatus s = status();
    core::View view;
    view.stage = stage;
    view.face = s.face;
    view.camera = camera.pose();
    if (!std::getenv("NOHUD")) view.hud = {live.scene().manifest().name + "    0:12.34    deaths 0", s.message};
    core::DrawList draw(true);
    live.scene().draw(draw);

    auto t0 = Clock::now();
    display.present(view, draw);
    glFinish();
    out.ours.push_back(msSince(t0));

    if (!floor) {  // after the level's first present: its window and context exist
      floor = new Floor();
      GLint samples = 0;
      glGetIntegerv(GL_SAMPLES, &samples);
      static bool told = false;
      if (!told)
        std::printf("GL: %s | %s | %d samples a pixel\n", glGetString(GL_RENDERER), glGetString(GL_VERSION), samples);
      told = true;
    }
    std::vector<render::LitVertex> triangles = mesh.fixed();
    mesh.addDoors(s.openTags, triangles);
    mesh.addShapes(draw, s.face, triangles, triangles);  // no overlay in the bench
    floor->upload(triangles);
    out.triangles = triangles.size() / 3;
    const Eigen::Matrix4f vp = mesh.viewProjection(view.camera, view.verticalFov, 1280.0 / 720.0);
    t0 = Clock::now();
    floor->draw(vp);
    if (f == frames / 2) {  // the floor draws the scene: some pixels are not the clear colour
      std::vector<uint8_t> px(size_t{1280} * 720 * 4);
      glReadPixels(0, 0, 1280, 720, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
      size_t drawn = 0;
      for (size_t i = 0; i < px.size(); i += 4) drawn += px[i] != px[0] || px[i + 1] != px[1] || px[i + 2] != px[2];
      out.floorCoverage = static_cast<double>(drawn) / (1280.0 * 720.0);
    }
    SDL_GL_SwapWindow(SDL_GL_GetCurrentWindow());  // a frame on screen, as the game's is
    glFinish();
    out.floor.push_back(msSince(t0));
  }
  return out;
}

// The editor's frames (`platon edit`): its picture of a level (the solid, its lines, the overlays and
// the palette) drawn by the same renderer, steady and on the frame right after an edit (the stage
// as drawn is made again, so the renderer builds its mesh anew). `busy` levels: a cube with
// `segments` random short segments.
struct EditorFrames {
  std::vector<double> steady, afterEdit, game;  // game: the same level's picture as the game draws it
};

EditorFrames measureEditor(const std::string& name, const std::string& text, const core::SystemRegistry& registry,
                           int frames) {
  core::Scene host;
  std::unique_ptr<core::System> window = registry.create("rendering", host);
  core::Display& display = *window->display();
  display.resize(1280, 720);
  editor::LevelDocument document(name, text, stage::gameTags());
  stage::Stage solid = stage::platonicStageOf(document.level());
  editor::Editor e(std::move(document), std::move(solid), 22938);
  core::WindowInput input;
  input.width = 1280, input.height = 720, input.mouseX = 640, input.mouseY = 400;
  EditorFrames out;
  platon::testing::Rng rng{5};
  for (int f = 0; f < frames; ++f) {
    const bool edit = f % 10 == 9;
    if (edit) {
      const int x = rng.between(300, 3700), y = rng.between(2500, 3700);
      e.document().edit("draw", [&](stage::Level& l) { l.faces[0].lines.push_back({{x, y}, {x + 128, y}, false, 0}); });
      e.rebuild();
    }
    e.handle(input);
    core::DrawList list(true);
    e.draw(list);
    auto t0 = Clock::now();
    display.present(e.view(), list);
    glFinish();
    (edit ? out.afterEdit : out.steady).push_back(msSince(t0));
    if (edit) continue;
    core::View game = e.view();  // the baseline: the same stage and camera, the game's two HUD lines
    game.hud = {"cube_switches    0:12.34    deaths 0", "a message"};
    t0 = Clock::now();
    display.present(game, core::DrawList(true));
    glFinish();
    out.game.push_back(msSince(t0));
  }
  return out;
}

std::string busyCube(int segments) {
  platon::testing::Rng rng{7};
  std::string text = "HEXAHEDRON\n0 600 400\n0 3400 400\n4096\n";
  for (int f = 0; f < 6; ++f) {
    text += "%\n";
    if (f == 0) text += "100 200 3996 200\n";
    for (int i = 0; i < segments / 6; ++i) {
      const int x = rng.between(50, 3990), y = rng.between(f == 0 ? 800 : 50, 3990);
      text += std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(x + rng.between(-40, 40)) + " " +
              std::to_string(y + rng.between(1, 40)) + "\n";
    }
  }
  return text;
}

// Runs `platon game --quit-after-first-frame` and returns its wall time in ms and peak RSS in MiB.
std::pair<double, double> startUp(const std::string& platon) {
  const auto t0 = Clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    const std::string progress = "/tmp/platon_bench_progress_" + std::to_string(getpid());
    execl(platon.c_str(), platon.c_str(), "game", "--progress", progress.c_str(), "--quit-after-first-frame", nullptr);
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  return {msSince(t0), static_cast<double>(usage.ru_maxrss) / 1024.0};
}

}  // namespace

int main(int argc, char** argv) {
  int frames = 300, runs = 5;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--frames") == 0)
      frames = std::atoi(argv[++i]);
    else if (std::strcmp(argv[i], "--runs") == 0)
      runs = std::atoi(argv[++i]);
  }
  setenv("SDL_VIDEODRIVER", "offscreen", 0);
  if (chdir(PLATON_SOURCE_ROOT) != 0) return 1;
  core::SystemRegistry registry;
  registry.add("scripting", script::makeScriptSystem);
  registry.addPlugin("meshes", "platon_meshes", {PLATON_PLUGIN_DIR});
  registry.addPlugin("rendering", "platon_render", {PLATON_PLUGIN_DIR});

  // The campaign's levels and, for each, the recorded play-through its frames follow.
  std::vector<std::pair<std::string, std::string>> levels;
  std::ifstream campaign("levels/campaign.txt");
  for (std::string line; std::getline(campaign, line);) {
    const std::string folder = line.substr(0, line.find_first_of(" #"));
    if (folder.empty()) continue;
    const std::string scene = "levels/" + folder + "/scene.lua";
    std::string replay;
    for (const char* r : {"_walk", "_run", "_drop", "_solve", "_ride"}) {
      std::ifstream probe("tests/replays/" + folder + r + ".replay");
      if (probe) replay = "tests/replays/" + folder + r + ".replay";
    }
    if (!replay.empty()) levels.push_back({scene, replay});
  }

  std::printf("render_frames: %d frames a level at 1280x720, glFinish after each\n", frames);
  Floor* floor = nullptr;
  std::printf("%-34s %9s %9s %9s %9s %9s %7s %6s\n", "level", "triangles", "ours mean", "ours p99", "floor mean",
              "floor p99", "ratio", "drawn");
  std::vector<double> ratios, worstMeans;
  for (const auto& [scene, replay] : levels) {
    floor = nullptr;  // each level's scene opens its own window and GL context: a floor in each (the
                      // old one's objects went with its context)
    const Frames f = measureLevel(scene, replay, registry, frames, floor);
    const double ratio = mean(f.ours) / std::max(mean(f.floor), 1e-9);
    ratios.push_back(ratio);
    worstMeans.push_back(mean(f.ours));
    std::printf("%-34s %9zu %7.2fms %7.2fms %8.2fms %8.2fms %6.2fx %5.0f%%\n", scene.c_str(), f.triangles, mean(f.ours),
                p99(f.ours), mean(f.floor), p99(f.floor), ratio, f.floorCoverage * 100);
    std::fflush(stdout);
  }
  std::printf("ratio to the floor: median %s; worst mean frame %.2f ms (goal: <= 1.5x, <= 7 ms)\n",
              bench::Spread::of(ratios).show("%.2f").c_str(), *std::max_element(worstMeans.begin(), worstMeans.end()));

  std::printf("\nthe editor's frames (platon edit), 1280x720, an edit every 10th frame\n");
  std::printf("%-34s %14s %14s %16s %16s %16s %7s\n", "level", "steady mean", "steady p99", "after edit mean",
              "after edit p99", "game's picture", "ratio");
  std::ifstream switches("levels/cube_switches/cube_switches.level");
  const std::string switchesText{std::istreambuf_iterator<char>(switches), {}};
  for (const auto& [name, text] : {std::pair{std::string("cube_switches"), switchesText},
                                   std::pair{std::string("a cube of 1,000 segments"), busyCube(1000)},
                                   std::pair{std::string("a cube of 10,000 segments"), busyCube(10000)}}) {
    const EditorFrames f = measureEditor(name, text, registry, frames);
    std::printf("%-34s %12.2fms %12.2fms %14.2fms %14.2fms %14.2fms %6.2fx\n", name.c_str(), mean(f.steady),
                p99(f.steady), mean(f.afterEdit), p99(f.afterEdit), mean(f.game), mean(f.steady) / mean(f.game));
    std::fflush(stdout);
  }

  std::vector<double> startMs, rssMiB;
  for (int r = 0; r < runs; ++r) {
    const auto [ms, mib] = startUp(std::string(PLATON_BUILD_DIR) + "/apps/platon");
    startMs.push_back(ms);
    rssMiB.push_back(mib);
  }
  std::printf("start-up to the first frame (platon game, fork to exit), %d runs: %s ms (goal: <= 300)\n", runs,
              bench::Spread::of(startMs).show("%.0f").c_str());
  std::printf("the game's peak memory (max RSS of that process): %s MiB\n",
              bench::Spread::of(rssMiB).show("%.1f").c_str());
  return 0;
}
