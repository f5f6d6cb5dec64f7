#include "platon/script/scenario.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <cstdio>
#include <map>
#include <vector>

#include "lua_host.h"
#include "platon/core/input.h"
#include "platon/script/script_system.h"

namespace platon::script {
namespace {

struct Box {
  uint64_t frame;
  physics::MapPartId face;
  int32_t x0, y0, x1, y1;
};

struct Plan {
  std::string scene;
  uint64_t frames = 0;
  std::vector<uint8_t> held;  // per frame, from frame 1
  std::optional<uint64_t> goalBy;
  std::optional<int> deaths;
  std::map<uint64_t, physics::MapPartId> faceAt;
  std::vector<Box> inside;
  std::map<uint64_t, std::string> hashAt;

  uint64_t lastCheck() const {
    uint64_t last = 0;
    if (!faceAt.empty()) last = std::max(last, faceAt.rbegin()->first);
    if (!hashAt.empty()) last = std::max(last, hashAt.rbegin()->first);
    for (const Box& b : inside) last = std::max(last, b.frame);
    return last;
  }
};

[[noreturn]] void planError(const std::string& path, const std::string& what) {
  throw ScriptError(path + ": " + what, "");
}

double numberAt(lua_State* L, int table, const char* key, const std::string& path, const std::string& where) {
  lua_getfield(L, table, key);
  if (!lua_isnumber(L, -1)) planError(path, where + ": '" + key + "' must be a number");
  const double v = lua_tonumber(L, -1);
  lua_pop(L, 1);
  return v;
}

core::Button buttonAt(lua_State* L, int index, const std::string& path, const std::string& where) {
  core::Button b{};
  if (!lua_isstring(L, index) || !core::buttonFromName(lua_tostring(L, index), b))
    planError(path, where + ": unknown button (left, right, up, down, jump, restart, pause, reload)");
  return b;
}

Plan readPlan(LuaHost& host, const std::string& path) {
  lua_State* L = host.state();
  lua::StackGuard guard(L);
  host.loadFile(path, Trust::Trusted);
  host.call(0, 1);
  if (!lua_istable(L, -1)) planError(path, "a scenario returns a table");
  const int t = lua_gettop(L);
  Plan plan;
  lua_getfield(L, t, "scene");
  if (!lua_isstring(L, -1)) planError(path, "'scene' (the manifest's path) is missing");
  plan.scene = lua_tostring(L, -1);
  lua_pop(L, 1);
  if (core::hasParentStep(plan.scene)) planError(path, "'scene' may not contain '..' (" + plan.scene + ")");
  const double frames = numberAt(L, t, "frames", path, "scenario");
  if (frames < 1 || frames > 1e8) planError(path, "'frames' must be within 1..10^8");
  plan.frames = static_cast<uint64_t>(frames);
  plan.held.assign(plan.frames + 1, 0);

  lua_getfield(L, t, "input");
  if (lua_istable(L, -1)) {
    const int input = lua_gettop(L);
    for (int i = 1; lua_rawgeti(L, input, i), !lua_isnil(L, -1); ++i) {
      const std::string where = "input[" + std::to_string(i) + "]";
      const int item = lua_gettop(L);
      uint64_t from = 0, to = 0;
      lua_getfield(L, item, "hold");
      lua_getfield(L, item, "press");
      core::Button button{};
      if (!lua_isnil(L, -2)) {
        button = buttonAt(L, -2, path, where);
        from = static_cast<uint64_t>(numberAt(L, item, "from", path, where));
        to = static_cast<uint64_t>(numberAt(L, item, "to", path, where));
      } else if (!lua_isnil(L, -1)) {
        button = buttonAt(L, -1, path, where);
        from = static_cast<uint64_t>(numberAt(L, item, "at", path, where));
        lua_getfield(L, item, "frames");
        to = from + (lua_isnumber(L, -1) ? static_cast<uint64_t>(lua_tonumber(L, -1)) : 1) - 1;
        lua_pop(L, 1);
      } else {
        planError(path, where + ": give hold = \"button\" (from, to) or press = \"button\" (at, frames)");
      }
      if (from < 1 || to < from || to > plan.frames) planError(path, where + ": frames outside 1.." + std::to_string(plan.frames));
      for (uint64_t f = from; f <= to; ++f) plan.held[f] |= core::InputFrame::bit(button);
      lua_settop(L, item - 1);
    }
  }
  lua_settop(L, t);

  lua_getfield(L, t, "expect");
  if (lua_istable(L, -1)) {
    const int e = lua_gettop(L);
    lua_getfield(L, e, "goal_by");
    if (lua_isnumber(L, -1)) plan.goalBy = static_cast<uint64_t>(lua_tonumber(L, -1));
    lua_getfield(L, e, "deaths");
    if (lua_isnumber(L, -1)) plan.deaths = static_cast<int>(lua_tonumber(L, -1));
    lua_settop(L, e);
    lua_getfield(L, e, "face");
    if (lua_istable(L, -1)) {
      for (lua_pushnil(L); lua_next(L, -2); lua_pop(L, 1))
        plan.faceAt[static_cast<uint64_t>(lua_tonumber(L, -2))] = static_cast<physics::MapPartId>(lua_tonumber(L, -1));
    }
    lua_settop(L, e);
    lua_getfield(L, e, "hash");
    if (lua_istable(L, -1)) {
      for (lua_pushnil(L); lua_next(L, -2); lua_pop(L, 1))
        if (lua_isstring(L, -1)) plan.hashAt[static_cast<uint64_t>(lua_tonumber(L, -2))] = lua_tostring(L, -1);
    }
    lua_settop(L, e);
    lua_getfield(L, e, "inside");
    if (lua_istable(L, -1)) {
      const int list = lua_gettop(L);
      for (int i = 1; lua_rawgeti(L, list, i), !lua_isnil(L, -1); ++i) {
        const int item = lua_gettop(L);
        const std::string where = "expect.inside[" + std::to_string(i) + "]";
        Box b{};
        b.frame = static_cast<uint64_t>(numberAt(L, item, "frame", path, where));
        b.face = static_cast<physics::MapPartId>(numberAt(L, item, "face", path, where));
        lua_getfield(L, item, "box");
        if (!lua_istable(L, -1) || lua_objlen(L, -1) != 4) planError(path, where + ": box = {x0, y0, x1, y1}");
        int32_t* corners[] = {&b.x0, &b.y0, &b.x1, &b.y1};
        for (int k = 0; k < 4; ++k) {
          lua_rawgeti(L, -1, k + 1);
          *corners[k] = static_cast<int32_t>(lua_tonumber(L, -1));
          lua_pop(L, 1);
        }
        plan.inside.push_back(b);
        lua_settop(L, item - 1);
      }
    }
  }
  return plan;
}

std::string hex(uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}


// The checks of frame f; "" when they pass.
std::string checkFrame(const Plan& plan, uint64_t f, core::Scene& scene, ScriptSystem* scripts, uint64_t traceEvery,
                       const std::string& path) {
  const std::string at = "frame " + std::to_string(f) + ": ";
  if (traceEvery > 0 && scripts && f % traceEvery == 0) {
    const GameStatus s = scripts->status();
    std::fprintf(stderr, "%s: frame %llu: face %u at (%d, %d)%s\n", path.c_str(), static_cast<unsigned long long>(f), s.face,
                 s.x, s.y, s.won ? ", won" : "");
  }
  if (const size_t overlaps = scene.world().countOverlaps(); overlaps != 0)
    return at + std::to_string(overlaps) + " instance(s) overlap a solid line";
  if (auto h = plan.hashAt.find(f); h != plan.hashAt.end() && hex(scene.world().stateHash()) != h->second)
    return at + "state hash " + hex(scene.world().stateHash()) + ", expected " + h->second;
  if (!scripts) return "";
  if (auto face = plan.faceAt.find(f); face != plan.faceAt.end()) {
    const GameStatus s = scripts->status();
    if (s.face != face->second)
      return at + "player on face " + std::to_string(s.face) + ", expected face " + std::to_string(face->second);
  }
  for (const Box& b : plan.inside) {
    if (b.frame != f) continue;
    const GameStatus s = scripts->status();
    if (s.face != b.face || s.x < b.x0 || s.x > b.x1 || s.y < b.y0 || s.y > b.y1)
      return at + "player at face " + std::to_string(s.face) + " (" + std::to_string(s.x) + ", " + std::to_string(s.y) +
             "), expected inside face " + std::to_string(b.face) + " [" + std::to_string(b.x0) + ", " +
             std::to_string(b.y0) + "]-[" + std::to_string(b.x1) + ", " + std::to_string(b.y1) + "]";
  }
  return "";
}
}  // namespace

namespace {

// Runs a plan: the scene, its input, every check on every frame.
ScenarioResult runPlan(const std::string& path, const std::function<Plan()>& makePlan, const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ScenarioResult result;
  auto finish = [&](bool passed, std::string message) {
    result.passed = passed;
    result.message = std::move(message);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  };
  std::optional<core::ReplayRecorder> recorder;
  auto keepRecording = [&] {
    if (recorder) result.recorded = recorder->replay();
  };
  try {
    const Plan plan = makePlan();
    core::SystemRegistry registry;
    registry.add("scripting", makeScriptSystem);
    registry.addPlugin("meshes", "platon_meshes", options.pluginFolders);
    std::unique_ptr<core::Scene> scene = core::loadScene(plan.scene, registry);
    ScriptSystem* scripts = nullptr;
    for (size_t i = 0; i < scene->systemCount(); ++i)
      if (auto* s = dynamic_cast<ScriptSystem*>(&scene->system(i))) scripts = s;
    if ((plan.goalBy || plan.deaths || !plan.faceAt.empty() || !plan.inside.empty()) && !scripts)
      return finish(false, "the scene has no scripts, so no player to check");
    if (options.record) recorder.emplace(plan.scene, options.hashEvery);
    core::InputEdges edges;
    std::string failure;
    for (uint64_t f = 1; f <= plan.frames && failure.empty(); ++f) {
      scene->step(edges.next(plan.held[f]));
      result.frames = f;
      if (recorder) recorder->frame(plan.held[f], scene->world().stateHash());
      failure = checkFrame(plan, f, *scene, scripts, options.traceEvery, path);
      // With the goal reached there is nothing left to see, unless a check waits for a later frame.
      if (failure.empty() && plan.goalBy && f >= plan.lastCheck() && scripts && scripts->status().won) break;
    }
    keepRecording();
    result.hash = hex(scene->world().stateHash());
    if (scripts) result.status = scripts->status();
    if (!failure.empty()) return finish(false, failure);
    // An error the last frame's checks met (status() keeps its errors for the next frame).
    if (scripts)
      if (std::optional<std::string> error = scripts->takeError()) return finish(false, *error);
    if (scripts) {
      const GameStatus& s = *result.status;
      if (plan.goalBy && (!s.won || s.wonFrame > *plan.goalBy))
        return finish(false, "goal not reached by frame " + std::to_string(*plan.goalBy) + " (player on face " +
                                 std::to_string(s.face) + " at " + std::to_string(s.x) + ", " + std::to_string(s.y) + ")");
      if (plan.deaths && s.deaths != *plan.deaths)
        return finish(false, std::to_string(s.deaths) + " deaths, expected " + std::to_string(*plan.deaths));
      if (!plan.hashAt.empty() && !plan.goalBy)
        return finish(true, std::to_string(plan.hashAt.size()) + " hashes matched" + (s.won ? ", goal at frame " + std::to_string(s.wonFrame) : ""));
      return finish(true, s.won ? "goal at frame " + std::to_string(s.wonFrame) : "ok");
    }
    return finish(true, plan.hashAt.empty() ? "ok" : std::to_string(plan.hashAt.size()) + " hashes matched");
  } catch (const ScriptError& e) {
    keepRecording();
    return finish(false, e.report());
  } catch (const std::exception& e) {
    keepRecording();
    return finish(false, e.what());
  }
}

}  // namespace

ScenarioResult runScenario(const std::string& path, const RunOptions& options) {
  return runPlan(path, [&] {
    LuaHost host;  // the scenario's own state: it only reads the plan
    return readPlan(host, path);
  }, options);
}

ScenarioResult runReplay(const std::string& path, const RunOptions& options) {
  return runPlan(path, [&] {
    const core::Replay replay = core::readReplay(path);
    Plan plan;
    plan.scene = replay.scene;
    plan.frames = replay.frames();
    plan.held.assign(1, 0);
    plan.held.insert(plan.held.end(), replay.held.begin(), replay.held.end());
    for (const core::ReplayHash& h : replay.hashes) plan.hashAt[h.frame] = hex(h.hash);
    return plan;
  }, options);
}

std::string scenarioFromReplay(const core::Replay& replay, const ScenarioResult& outcome, const std::string& name) {
  std::string out = "-- Made by `platon scenario` from " + name + ": the recorded input, and what that run reached.\n";
  out += "return {\n  scene = \"" + replay.scene + "\",\n  frames = " + std::to_string(replay.frames()) + ",\n  input = {\n";
  for (int b = 0; b < core::kButtonCount; ++b) {
    const std::string button(core::buttonName(static_cast<core::Button>(b)));
    for (size_t i = 0; i < replay.held.size();) {
      if (!(replay.held[i] >> b & 1)) {
        ++i;
        continue;
      }
      size_t j = i;
      while (j < replay.held.size() && (replay.held[j] >> b & 1)) ++j;
      out += "    { hold = \"" + button + "\", from = " + std::to_string(i + 1) + ", to = " + std::to_string(j) + " },\n";
      i = j;
    }
  }
  out += "  },\n  expect = {\n";
  if (outcome.status) {
    const GameStatus& s = *outcome.status;
    if (s.won) out += "    goal_by = " + std::to_string(s.wonFrame) + ",\n";
    out += "    deaths = " + std::to_string(s.deaths) + ",\n";
    out += "    face = { [" + std::to_string(outcome.frames) + "] = " + std::to_string(s.face) + " },\n";
  }
  out += "    hash = {";
  for (const core::ReplayHash& h : replay.hashes) {
    if (h.frame > outcome.frames) break;
    out += " [" + std::to_string(h.frame) + "] = \"" + hex(h.hash) + "\",";
  }
  out += " },\n  },\n}\n";
  return out;
}

}  // namespace platon::script
