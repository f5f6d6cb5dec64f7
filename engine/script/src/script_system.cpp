#include "platon/script/script_system.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <limits.h>
#include <map>
#include <optional>
#include <stdlib.h>
#include <unordered_map>

#include "embedded_lua.h"
#include "lua_rules.h"
#include "lua_stack.h"
#include "platon/core/data_root.h"
#include "platon/files/read_file.h"
#include "script_context.h"

namespace platon::script {

// What one line or body a move was tested against costs, in the steps of the frame's budget
// (physics::EntityView::work): a test is an exact sweep of a polygon against a segment or another
// polygon, about as long as this many interpreted Lua instructions (measured: 10,000 bodies at
// rest take about 1.5 us each a frame, a sandboxed step about 3.4 ns; docs/scripting.md, Limits).
constexpr int64_t kStepsPerTest = 20;

struct ScriptSystem::State {
  core::Scene* scene = nullptr;
  std::string root;
  LuaHost host;
  ScriptContext context;
  lua::Ref driver;  // the table scripts/scene.lua returned
  std::unique_ptr<LuaRules> rules;
  std::vector<std::string> files;                      // every script file loaded: hot reload watches them
  bool ffi = std::getenv("PLATON_NO_FFI") == nullptr;  // the FFI fast paths (off: for the benches)
  // The console's own globals when the level has no sandbox: made by its first line, kept for the
  // rest (each line is a sandbox of its own in them, released when it ends).
  int consoleGlobals = kNoSandbox;

  State(core::Scene& s, std::string r, LuaLimits limits) : scene(&s), root(std::move(r)), host(limits) {
    context.scene = &s;
    context.host = &host;
  }

  lua::Ref beforeStep, afterStep;  // driver.beforeStep and driver.afterStep: called every frame
  GameStatus lastStatus;           // the last status() that worked
  // Errors of status() and draw(), which never throw (the game loop calls them outside a frame):
  // reported with the next frame's errors.
  std::vector<ScriptError> deferred;

  // The physics of the bodies each sandbox made, charged to it as steps of the frame's budget: a
  // level that piles up thousands of bodies pays for their collisions as it would for a loop, and
  // past the budget it is stopped, and what it made is removed (else the next frames would cost the
  // same). A body's work is the lines and bodies its moves were tested against.
  void chargePhysics() {
    if (context.madeBy.empty() && context.platforms.empty()) return;
    physics::World& world = scene->world();
    struct Cost {
      uint64_t tested = 0;
      size_t bodies = 0, platforms = 0;
    };
    std::map<int, Cost> costs;
    for (auto it = context.madeBy.begin(); it != context.madeBy.end();) {
      const physics::EntityId id{static_cast<uint32_t>(it->first >> 32), static_cast<uint32_t>(it->first)};
      if (!world.valid(id)) {  // destroyed by trusted code
        it = context.madeBy.erase(it);
        continue;
      }
      Cost& cost = costs[it->second];
      cost.tested += world.entity(id).work();
      ++cost.bodies;
      ++it;
    }
    // Platforms too: moving and turning one tests its lines against the bodies near it.
    for (const auto& [number, sandbox] : context.platforms) {
      const lua::HandleBits bits = lua::platformBits(number);
      Cost& cost = costs[sandbox];
      cost.tested += world.platform({bits.index, bits.generation}).work;
      ++cost.platforms;
    }
    for (const auto& [sandbox, cost] : costs) {
      const std::string what = "the physics of the " + std::to_string(cost.bodies) + " bodies and " +
                               std::to_string(cost.platforms) + " platforms it made (" + std::to_string(cost.tested) +
                               " tests of a line or a body, a body's step counting as 16; " +
                               std::to_string(kStepsPerTest) + " steps a test)";
      if (std::optional<ScriptError> stop =
              host.chargeWork(sandbox, static_cast<int64_t>(cost.tested) * kStepsPerTest, what)) {
        removeMadeBy(sandbox);
        host.keepError(std::move(*stop));
      }
    }
  }

  // Destroys the bodies and platforms sandbox `sandbox` made (never the player's body).
  void removeMadeBy(int sandbox) {
    physics::World& world = scene->world();
    for (auto it = context.madeBy.begin(); it != context.madeBy.end();) {
      const physics::EntityId id{static_cast<uint32_t>(it->first >> 32), static_cast<uint32_t>(it->first)};
      if (it->second != sandbox || id == context.protectedEntity) {
        ++it;
        continue;
      }
      if (world.valid(id)) world.destroyEntity(id);
      it = context.madeBy.erase(it);
    }
    for (auto it = context.platforms.begin(); it != context.platforms.end();) {
      if (it->second != sandbox) {
        ++it;
        continue;
      }
      const lua::HandleBits bits = lua::platformBits(it->first);
      world.destroyPlatform({bits.index, bits.generation});
      it = context.platforms.erase(it);
    }
  }

  // Pushes driver[name] and calls it with nargs arguments already pushed after it.
  void callDriver(const char* name, int nargs, int nresults) {
    lua_State* L = host.state();
    driver.push();
    lua_getfield(L, -1, name);
    lua_remove(L, -2);
    if (nargs > 0) lua_insert(L, -(nargs + 1));
    host.call(nargs, nresults);
  }

  // The errors kept since the last look (sandboxed calls behind engine.call, and deferred ones),
  // thrown as one: the first one's message and traceback, then the others'.
  void throwKeptErrors() {
    if (!host.hasErrors() && deferred.empty()) [[likely]]
      return;
    std::vector<ScriptError> all = std::move(deferred);
    deferred.clear();
    for (ScriptError& e : host.takeErrors()) all.push_back(std::move(e));
    if (all.size() == 1) throw all.front();
    std::string details = all.front().traceback();
    for (size_t i = 1; i < all.size(); ++i) details += (details.empty() ? "" : "\n") + all[i].report();
    throw ScriptError(all.front().what(), details);
  }
};

namespace {

ScriptSystem::State& stateOf(lua_State* L) {
  return *static_cast<ScriptSystem::State*>(lua_touserdata(L, lua_upvalueindex(1)));
}

std::string realPath(const std::string& path) {
  char resolved[PATH_MAX];
  return ::realpath(path.c_str(), resolved) ? std::string(resolved) : std::string();
}

// An engine script's file: `path` ("scripts/...", as the manifest wrote it) under the engine's
// root, with every link resolved, and still under the root's scripts/ folder.
std::string engineScript(const std::string& root, const std::string& path) {
  if (path.rfind("scripts/", 0) != 0) throw lua::ArgError("'" + path + "': an engine script is a path under scripts/");
  const std::string folder = realPath(root + "/scripts");
  std::string file = realPath(root + "/" + path);
  if (folder.empty() || file.empty()) throw ScriptError(root + "/" + path + ": cannot open the script", "");
  if (file.rfind(folder + "/", 0) != 0)
    throw lua::ArgError("'" + path + "' is " + file + ", outside the engine's scripts (" + folder + "/)");
  return file;
}

// engine.load(path, trusted or "base", ...) -> the chunk's result (and, sandboxed, its sandbox's id). Trust
// is what the manifest decided from what it wrote (setup.trusted): a trusted path is an engine
// script (scripts/..., resolved under the engine's root); any other was resolved and checked by
// the manifest (inside the level's folder) and runs sandboxed.
// how may also be "base": an engine script run sandboxed, as the base a level's own script
// extends (scripts/player.lua under a level's player: its functions then run inside the level's
// limits, as the level's own do).
// `file` as a path from `folder` ("level.lua", "mods/dash.lua"); its own name when it is elsewhere.
std::string nameInFolder(const std::string& file, const std::string& folder) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path inside = fs::path(file).lexically_relative(fs::weakly_canonical(folder.empty() ? "." : folder, error));
  if (error || inside.empty() || *inside.begin() == "..") return fs::path(file).filename().string();
  return inside.generic_string();
}

int engineLoad(lua_State* L) {
  ScriptSystem::State& state = stateOf(L);
  const std::string path(lua::checkString(L, 1));
  const bool base = lua_type(L, 2) == LUA_TSTRING && std::string_view(lua_tostring(L, 2)) == "base";
  const bool trusted = !base && lua::checkBoolean(L, 2);
  const int nargs = lua_gettop(L) - 2;
  // A file that cannot be found is named at the manifest's line:column that names it.
  const auto place = state.scene->manifest().placeOf.find(path);
  const std::string named = place == state.scene->manifest().placeOf.end() ? "" : " (named at " + place->second + ")";
  std::string file;
  try {
    file = trusted || base ? engineScript(state.root, path) : path;
  } catch (const ScriptError& e) {
    throw ScriptError(e.what() + named, e.traceback());
  }
  state.files.push_back(file);
  try {  // a file that is no script (a FIFO, a folder, too big) is the naming line's error
    files::checkBoundedFile(file, LuaHost::kMaxScriptBytes);
  } catch (const files::FileError& e) {
    throw ScriptError(file + ": the script: " + e.reason() + named, "");
  }
  // Sandboxed code carries a name from its level's folder (an engine script run as a level's base:
  // "scripts/player.lua"), never the absolute path.
  const std::string shown = trusted ? "" : base ? path : nameInFolder(file, state.scene->manifest().directory);
  const int sandbox = state.host.loadFile(file, trusted ? Trust::Trusted : Trust::Sandboxed, shown);
  lua_insert(L, 3);
  if (trusted) {
    state.host.call(nargs, 1);
    return 1;
  }
  if (!state.host.callSandboxed(sandbox, nargs, 1)) lua_pushnil(L);
  lua_pushinteger(L, sandbox);
  return 2;
}

// engine.setRules(rules [, sandbox]): rules is a table of callbacks or nil (the C++ defaults);
// sandbox the id of the sandbox that made it (its functions run with the JIT off, under the
// frame's budget), nil for trusted rules.
int engineSetRules(lua_State* L) {
  ScriptSystem::State& state = stateOf(L);
  const int sandbox = lua_isnoneornil(L, 2) ? kNoSandbox : static_cast<int>(lua::checkInteger(L, 2, 0, INT_MAX));
  state.scene->world().setRules(nullptr);
  state.rules.reset();
  if (!lua_isnil(L, 1)) {
    const LuaRules::Call how = state.ffi && sandbox == kNoSandbox ? LuaRules::Call::Ffi : LuaRules::Call::Classic;
    try {
      state.rules = std::make_unique<LuaRules>(state.host, 1, how, sandbox);
    } catch (const ScriptError& e) {
      // The rules script's name (its third argument) before what is wrong with its table.
      if (lua_type(L, 3) != LUA_TSTRING) throw;
      throw ScriptError(std::string(lua_tostring(L, 3)) + ": " + e.what(), e.traceback());
    }
    state.scene->world().setRules(state.rules.get());
  }
  return 0;
}

// engine.readonly(t, name) -> a read-only view of t (nested tables are views too).
int engineReadOnly(lua_State* L) {
  ScriptSystem::State& state = stateOf(L);
  lua::checkTable(L, 1);
  state.host.pushReadOnly(1, lua::checkString(L, 2));
  return 1;
}

// engine.sandboxApi() -> what sandboxes see as `platon` (LuaHost::pushSandboxApi), before its view.
int engineSandboxApi(lua_State* L) {
  stateOf(L).host.pushSandboxApi();
  return 1;
}

// engine.disabled(sandbox) -> whether a limit stopped it for good.
int engineDisabled(lua_State* L) {
  lua_pushboolean(L, stateOf(L).host.disabled(static_cast<int>(lua::checkInteger(L, 1, 0, INT_MAX))));
  return 1;
}

// engine.protect(entity | nil): the player's entity, which no sandbox may destroy or erase.
int engineProtect(lua_State* L) {
  ScriptSystem::State& state = stateOf(L);
  state.context.protectedEntity = {};
  if (const std::optional<lua::HandleBits> bits = lua::toHandle(L, 1))
    state.context.protectedEntity = {bits->index, bits->generation};
  return 0;
}

// engine.invoke(sandbox, f, ...) -> f's results: f called as that sandbox's code, under its limits,
// its errors raised to the caller as if it had called f itself. For the functions of a level's own
// player or progression script, which trusted code calls.
int engineInvoke(lua_State* L) {
  ScriptSystem::State& state = stateOf(L);
  const int sandbox = static_cast<int>(lua::checkInteger(L, 1, 0, INT_MAX));
  lua::checkFunction(L, 2);
  lua_remove(L, 1);
  if (!state.host.callSandboxed(sandbox, lua_gettop(L) - 1, LUA_MULTRET))
    throw ScriptError(
        state.host.sandboxName(sandbox) + ": not run: it is disabled, or the frame's script budget is spent", "");
  return lua_gettop(L);
}

constexpr luaL_Reg kEngine[] = {
    {"load", lua::bound<engineLoad>},         {"setRules", lua::bound<engineSetRules>},
    {"readonly", lua::bound<engineReadOnly>}, {"sandboxApi", lua::bound<engineSandboxApi>},
    {"disabled", lua::bound<engineDisabled>}, {"protect", lua::bound<engineProtect>},
    {"invoke", lua::bound<engineInvoke>},     {nullptr, nullptr},
};

// Copies plain data from one Lua state to another: nil, booleans, numbers, strings, and tables of
// them keyed by strings or numbers. Functions, userdata and coroutines are left out. A value met
// twice is copied once: a table (shared, or a cycle) is shared (or cyclic) the same way in the
// copy, and a string is copied once however many places hold it (99,999 references to one 24 MB
// string hung the reload when each was copied anew). The copy runs in C, where no hook runs, so
// it is bounded: at most kMaxCopiedEntries table entries, kMaxCopiedBytes of distinct strings and
// kMaxCopySeconds of time; past any of them the reload is refused. Runs inside a protected call
// of the destination, so running out of its memory is an error there, not a panic.
constexpr int kMaxCopyDepth = 200;
constexpr size_t kMaxCopiedEntries = 1'000'000;
constexpr size_t kMaxCopiedBytes = size_t{32} << 20;
constexpr double kMaxCopySeconds = 1.0;

struct PlainCopy {
  lua_State* from;
  int index;
  int copies = 0;  // `to`'s stack slot of the table: source table or string -> its copy
  size_t entries = 0;
  size_t bytes = 0;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  const char* tooMuch = nullptr;  // why the copy stopped: it is refused
};

// Whether the copy may go on; flags why not.
bool withinBounds(PlainCopy& job) {
  if (job.tooMuch) return false;
  if (job.entries > kMaxCopiedEntries) job.tooMuch = "more than 1000000 table entries";
  if (job.bytes > kMaxCopiedBytes) job.tooMuch = "more than 32 MB of strings";
  if (job.entries % 4096 == 0 &&
      std::chrono::duration<double>(std::chrono::steady_clock::now() - job.start).count() > kMaxCopySeconds)
    job.tooMuch = "more than a second of copying";
  return !job.tooMuch;
}

// Pushes the copy of `from`'s value at `index` onto `to` (nil for what is not plain data).
// Errors are flagged in the job and nil pushed (no Lua error unwinds this C++ frame).
void copyPlain(PlainCopy& job, int index, lua_State* to, int depth) {
  lua_State* from = job.from;
  if (job.tooMuch) return lua_pushnil(to);
  if (depth > kMaxCopyDepth || !lua_checkstack(to, 4) || !lua_checkstack(from, 4)) {
    job.tooMuch = "tables nested more than 200 deep";
    return lua_pushnil(to);
  }
  switch (lua_type(from, index)) {
    case LUA_TBOOLEAN:
      return lua_pushboolean(to, lua_toboolean(from, index));
    case LUA_TNUMBER:
      return lua_pushnumber(to, lua_tonumber(from, index));
    case LUA_TSTRING: {
      // LuaJIT interns strings: one object per distinct string, so its address names its copy.
      const void* original = lua_topointer(from, index);
      lua_pushlightuserdata(to, const_cast<void*>(original));
      lua_rawget(to, job.copies);
      if (!lua_isnil(to, -1)) return;
      lua_pop(to, 1);
      size_t n = 0;
      const char* text = lua_tolstring(from, index, &n);
      job.bytes += n;
      if (!withinBounds(job)) return lua_pushnil(to);
      lua_pushlstring(to, text, n);
      lua_pushlightuserdata(to, const_cast<void*>(original));
      lua_pushvalue(to, -2);
      lua_rawset(to, job.copies);
      return;
    }
    case LUA_TTABLE:
      break;
    default:
      return lua_pushnil(to);
  }
  const int source = index < 0 ? lua_gettop(from) + index + 1 : index;
  // Copied already (shared, or a cycle back up): the same copy.
  lua_pushlightuserdata(to, const_cast<void*>(lua_topointer(from, source)));
  lua_rawget(to, job.copies);
  if (!lua_isnil(to, -1)) return;
  lua_pop(to, 1);
  lua_newtable(to);
  lua_pushlightuserdata(to, const_cast<void*>(lua_topointer(from, source)));
  lua_pushvalue(to, -2);
  lua_rawset(to, job.copies);
  for (lua_pushnil(from); lua_next(from, source); lua_pop(from, 1)) {
    ++job.entries;
    if (!withinBounds(job)) {
      lua_pop(from, 2);
      return;
    }
    const int keyType = lua_type(from, -2);
    if (keyType != LUA_TSTRING && keyType != LUA_TNUMBER) continue;
    copyPlain(job, -2, to, depth + 1);
    copyPlain(job, lua_gettop(from), to, depth + 1);
    if (lua_isnil(to, -1))
      lua_pop(to, 2);
    else
      lua_rawset(to, -3);
    if (job.tooMuch) {
      lua_pop(from, 2);
      return;
    }
  }
}

int copyPlainProtected(lua_State* to) {
  auto* job = static_cast<PlainCopy*>(lua_touserdata(to, 1));
  lua_pop(to, 1);
  lua_newtable(to);  // source table -> copy
  job->copies = lua_gettop(to);
  copyPlain(*job, job->index, to, 0);
  if (job->tooMuch) return luaL_error(to, "save(): too much to carry over (%s)", job->tooMuch);
  return 1;
}

}  // namespace

ScriptSystem::ScriptSystem(core::Scene& scene, std::string root) {
  const core::SceneManifest& m = scene.manifest();
  // A level's manifest may lower the engine's limits, never raise them.
  LuaLimits limits;
  limits.memoryBytes = std::min(limits.memoryBytes, m.memoryMegabytes << 20);
  limits.frameSteps = std::min(limits.frameSteps, m.frameSteps);
  limits.deadlineNanoseconds = std::min(limits.deadlineNanoseconds, static_cast<int64_t>(m.deadlineMilliseconds * 1e6));
  state_ = std::make_unique<State>(scene, std::move(root), limits);
  registerWorldApi(state_->host, state_->context);
  if (state_->ffi) registerWorldFfi(state_->host, state_->context);
  registerDrawApi(state_->host, state_->context);
  registerSoundApi(state_->host, state_->context);
}

ScriptSystem::~ScriptSystem() {
  if (state_ && state_->rules) state_->scene->world().setRules(nullptr);
}

// Loads scripts/scene.lua with the manifest's setup, once: declareTags and build both need it.
void ScriptSystem::prepare(core::Scene& scene) {
  if (state_->driver.isSet()) return;
  lua_State* L = state_->host.state();
  const core::SceneManifest& m = scene.manifest();
  // The trusted `platon` global: the API table itself (sandboxes get read-only views of it).
  state_->host.pushApi();
  lua_newtable(L);  // platon.tags and platon.tagKinds: filled once the scene's tags are known (setTagsApi)
  lua_setfield(L, -2, "tags");
  lua_newtable(L);
  lua_setfield(L, -2, "tagKinds");
  lua_setglobal(L, "platon");
  state_->files.push_back(state_->root + "/scripts/scene.lua");
  state_->host.loadFile(state_->files.back(), Trust::Trusted);
  lua_newtable(L);  // engine: what only trusted scripts may call
  lua_pushlightuserdata(L, state_.get());
  for (const luaL_Reg* f = kEngine; f->name; ++f) {
    lua_pushvalue(L, -1);
    lua_pushcclosure(L, f->func, 1);
    lua_setfield(L, -3, f->name);
  }
  lua_pop(L, 1);
  state_->host.pushCallFunction();
  lua_setfield(L, -2, "call");
  lua_getfield(L, LUA_REGISTRYINDEX, "platon.tostring");  // what the level API shows of a value
  lua_setfield(L, -2, "tostring");
  lua_newtable(L);  // setup: the manifest's scripts and numbers
  auto field = [&](const char* key, const std::string& value) {
    lua_pushlstring(L, value.data(), value.size());
    lua_setfield(L, -2, key);
  };
  field("rules", m.rules);
  field("player", m.player);
  field("progression", m.progression);
  field("level", m.level);
  field("name", m.name);
  lua_newtable(L);  // trusted: which scripts are the engine's, as the manifest decided
  auto trusted = [&](const char* key, bool value) {
    lua_pushboolean(L, value);
    lua_setfield(L, -2, key);
  };
  trusted("rules", m.rulesTrusted);
  trusted("player", m.playerTrusted);
  trusted("progression", m.progressionTrusted);
  trusted("level", m.levelTrusted);
  lua_setfield(L, -2, "trusted");
  lua_newtable(L);
  for (size_t i = 0; i < m.mods.size(); ++i) {
    lua_pushlstring(L, m.mods[i].data(), m.mods[i].size());
    lua_rawseti(L, -2, static_cast<int>(i + 1));
  }
  lua_setfield(L, -2, "mods");
  lua_newtable(L);  // the engine's actions, by bit: the `input` table's names
  for (size_t i = 0; i < core::engineActions().size(); ++i) {
    const std::string& name = core::engineActions()[i].name;
    lua_pushlstring(L, name.data(), name.size());
    lua_rawseti(L, -2, static_cast<int>(i + 1));
  }
  lua_setfield(L, -2, "actions");
  lua_pushnumber(L, m.seed);
  lua_setfield(L, -2, "seed");
  state_->host.call(2, 1);
  state_->driver = lua::Ref(L, -1);
  lua_getfield(L, -1, "beforeStep");
  state_->beforeStep = lua::Ref(L, -1);
  lua_getfield(L, -2, "afterStep");
  state_->afterStep = lua::Ref(L, -1);
  lua_pop(L, 3);
}

// platon.tags: each kind's word and its number (a numbered kind's base), as the scene has them.
void ScriptSystem::setTagsApi(const stage::TagTable& tags) {
  lua_State* L = state_->host.state();
  lua::StackGuard guard(L);
  state_->host.pushApi();
  lua_getfield(L, -1, "tags");
  lua_getfield(L, -2, "tagKinds");
  int i = 0;
  for (const stage::TagKind& k : tags.kinds()) {
    lua_pushnumber(L, k.number);
    lua_setfield(L, -3, k.word.c_str());
    lua_createtable(L, 0, 8);
    auto field = [&](const char* key, auto push) {
      push();
      lua_setfield(L, -2, key);
    };
    field("word", [&] { lua_pushlstring(L, k.word.data(), k.word.size()); });
    field("number", [&] { lua_pushnumber(L, k.number); });
    field("count", [&] { lua_pushnumber(L, k.count); });
    field("passable", [&] {
      lua_pushstring(L, k.passage == stage::Passage::Through ? "through"
                        : k.passage == stage::Passage::Door  ? "door"
                                                             : "wall");
    });
    char colour[8];
    std::snprintf(colour, sizeof colour, "#%02x%02x%02x", k.style.r, k.style.g, k.style.b);
    field("color", [&] { lua_pushstring(L, colour); });
    field("glow", [&] { lua_pushboolean(L, k.style.glow); });
    field("spikes", [&] { lua_pushboolean(L, k.style.spikes); });
    field("owner", [&] { lua_pushlstring(L, k.owner.data(), k.owner.size()); });
    lua_rawseti(L, -2, ++i);
  }
  tagsSet_ = true;
  state_->host.refreshSandboxApi();  // the mods, loaded before the tags were known, see them too
}

void ScriptSystem::declareTags(core::Scene& scene, stage::TagTable& tags) {
  prepare(scene);
  lua_State* L = state_->host.state();
  lua::StackGuard guard(L);
  state_->host.beginFrame();
  state_->callDriver("declare", 0, 2);  // loads the mods: { owner =, word =, ... }s, { owner =, name =, ... }s
  state_->throwKeptErrors();
  declareActions(scene, lua_gettop(L));
  lua_pop(L, 1);
  const int list = lua_gettop(L);
  for (int i = 1;; ++i) {
    lua_rawgeti(L, list, i);
    if (!lua_istable(L, -1)) break;
    auto text = [&](const char* key) {
      lua_getfield(L, -1, key);
      std::string v = lua_isstring(L, -1) ? lua_tostring(L, -1) : "";
      lua_pop(L, 1);
      return v;
    };
    auto number = [&](const char* key) {
      lua_getfield(L, -1, key);
      const double v = lua_tonumber(L, -1);
      lua_pop(L, 1);
      return v;
    };
    auto flag = [&](const char* key) {
      lua_getfield(L, -1, key);
      const bool v = lua_toboolean(L, -1) != 0;
      lua_pop(L, 1);
      return v;
    };
    stage::TagKind kind;
    kind.owner = text("owner");
    kind.word = text("word");
    try {
      if (!flag("look")) {  // handlers for a word declared before: it must exist
        if (!tags.find(kind.word))
          throw stage::TagError("no tag '" + kind.word + "' to add handlers to, and no look or passage to make one (" +
                                tags.words() + ")");
      } else {
        if (const stage::TagKind* k = tags.find(kind.word))
          throw stage::TagError("the tag '" + kind.word + "' is " + k->owner +
                                "'s: a mod may add handlers to it, not change its look or passage");
        uint32_t next = stage::kFirstModTag;
        for (const stage::TagKind& k : tags.kinds())
          if (k.number >= next) next = k.number + stage::kModTagStep;
        kind.number = next;
        kind.count = flag("numbered") ? 999 : 0;
        const std::string passage = text("passage");
        kind.passage = passage == "through" ? stage::Passage::Through
                       : passage == "door"  ? stage::Passage::Door
                                            : stage::Passage::Wall;
        kind.style = {static_cast<uint8_t>(number("r")), static_cast<uint8_t>(number("g")),
                      static_cast<uint8_t>(number("b")), flag("glow"), flag("spikes")};
        tags.add(kind);
      }
    } catch (const stage::TagError& e) {
      throw ScriptError(kind.owner + ": tags." + kind.word + ": " + e.what(), "");
    }
    lua_pop(L, 1);
  }
  setTagsApi(tags);
}

namespace {

// The string at t[key] (t on the top of the stack), or "".
std::string textField(lua_State* L, const char* key) {
  lua_getfield(L, -1, key);
  std::string v = lua_isstring(L, -1) ? lua_tostring(L, -1) : "";
  lua_pop(L, 1);
  return v;
}

// The strings of the list at t[key] (t on the top of the stack).
std::vector<std::string> textList(lua_State* L, const char* key) {
  std::vector<std::string> out;
  lua_getfield(L, -1, key);
  for (int i = 1; lua_istable(L, -1); ++i) {
    lua_rawgeti(L, -1, i);
    const bool more = lua_isstring(L, -1);
    if (more) out.emplace_back(lua_tostring(L, -1));
    lua_pop(L, 1);
    if (!more) break;
  }
  lua_pop(L, 1);
  return out;
}

}  // namespace

// The mods' actions (the list at `list`, checked by scene.lua) after the engine's, into the scene's
// table; scene.lua's `input` takes the names in the same order.
void ScriptSystem::declareActions(core::Scene& scene, int list) {
  lua_State* L = state_->host.state();
  std::vector<core::Action> actions = core::engineActions();
  for (int i = 1;; ++i) {
    lua_rawgeti(L, list, i);
    if (!lua_istable(L, -1)) break;
    core::Action a{textField(L, "name"), textField(L, "label"), textList(L, "keys"),
                   textList(L, "pad"),   textField(L, "does"),  true,
                   textField(L, "owner")};
    lua_pop(L, 1);
    try {
      core::addAction(actions, a);
    } catch (const std::runtime_error& e) {
      throw ScriptError(a.owner + ": actions." + a.name + ": " + e.what(), "");
    }
  }
  lua_pop(L, 1);
  if (actions.size() == core::engineActions().size()) return;
  lua_createtable(L, static_cast<int>(actions.size()), 0);
  for (size_t i = 0; i < actions.size(); ++i) {
    lua_pushlstring(L, actions[i].name.data(), actions[i].name.size());
    lua_rawseti(L, -2, static_cast<int>(i + 1));
  }
  state_->callDriver("setActions", 1, 0);
  state_->throwKeptErrors();
  scene.setActions(std::move(actions));
}

void ScriptSystem::build(core::Scene& scene) {
  prepare(scene);
  if (!tagsSet_) setTagsApi(*scene.tags());
  lua_State* L = state_->host.state();
  state_->host.beginFrame();
  lua_pushnumber(L, carriedFrames_);
  state_->callDriver("build", 1, 0);
  state_->throwKeptErrors();
}

void ScriptSystem::carryBeforeBuild(core::System& previous) {
  auto* old = dynamic_cast<ScriptSystem*>(&previous);
  if (!old) return;
  lua_State* L = old->state_->host.state();
  lua::StackGuard guard(L);
  old->state_->host.beginFrame();
  old->state_->callDriver("frame", 0, 1);
  carriedFrames_ = lua_isnumber(L, -1) ? lua_tonumber(L, -1) : 0;
}

void ScriptSystem::start(core::Scene&) {
  state_->host.beginFrame();
  state_->callDriver("start", 0, 0);
  state_->throwKeptErrors();
}

void ScriptSystem::beforeStep(core::Scene& scene, const core::InputFrame& input) {
  State& state = *state_;
  lua_State* L = state.host.state();
  if (!consoleOpenedFrame_) state.host.beginFrame();  // else begun by the console's lines before it
  consoleOpenedFrame_ = false;
  state.host.setGameFrame(scene.world().frame());
  state.beforeStep.push();
  lua_pushnumber(L, input.held);
  lua_pushnumber(L, input.pressed);
  try {
    state.host.call(2, 0);
  } catch (ScriptError& e) {
    state.deferred.insert(state.deferred.begin(), std::move(e));
  }
  state.throwKeptErrors();
}

void ScriptSystem::afterStep(core::Scene&) {
  State& state = *state_;
  state.chargePhysics();
  state.afterStep.push();
  try {
    state.host.call(0, 0);
  } catch (ScriptError& e) {
    state.deferred.insert(state.deferred.begin(), std::move(e));
  }
  state.host.collectIfNeeded();
  state.throwKeptErrors();
}

// Never throws (the game loop calls it outside any frame): an error is reported with the next
// frame's, and the picture shows nothing the scripts drew.
void ScriptSystem::draw(const core::Scene&, core::DrawList& out) const {
  State& state = *state_;
  state.context.draw = &out;
  state.context.drawOverflowReported = false;
  lua::StackGuard guard(state.host.state());
  // A budget of its own: drawing runs at the display's rate, and never in a replay, so it must not
  // spend the budget of the frame the simulation runs next (the console's lines may have begun it).
  const LuaHost::Budget frame = state.host.budget();
  state.host.beginFrame();
  struct Restore {
    LuaHost& host;
    const LuaHost::Budget& frame;
    ~Restore() { host.restoreBudget(frame); }
  } restore{state.host, frame};
  try {
    state.callDriver("draw", 0, 0);
    if (state.host.hasErrors()) {
      for (ScriptError& e : state.host.takeErrors()) state.deferred.push_back(std::move(e));
      out.clear();
    }
  } catch (const ScriptError& e) {
    state.deferred.push_back(e);
    out.clear();
  } catch (const std::exception& e) {  // std::bad_alloc, say
    state.deferred.emplace_back(std::string("draw: ") + e.what(), "");
    out.clear();
  }
  state.context.draw = nullptr;
}

// Never throws either: on an error, the last status that worked (the error is reported with the
// next frame's).
GameStatus ScriptSystem::status() const {
  State& state = *state_;
  try {
    GameStatus s = readStatus();
    if (state.host.hasErrors())
      for (ScriptError& e : state.host.takeErrors()) state.deferred.push_back(std::move(e));
    state.lastStatus = s;
  } catch (const ScriptError& e) {
    state.deferred.push_back(e);
  } catch (const std::exception& e) {
    state.deferred.emplace_back(std::string("status: ") + e.what(), "");
  }
  return state.lastStatus;
}

std::optional<std::string> ScriptSystem::takeError() {
  try {
    state_->throwKeptErrors();
  } catch (const ScriptError& e) {
    return e.report();
  }
  return std::nullopt;
}

GameStatus ScriptSystem::readStatus() const {
  lua_State* L = state_->host.state();
  lua::StackGuard guard(L);
  state_->callDriver("status", 0, 1);
  GameStatus s;
  if (!lua_istable(L, -1)) return s;
  auto number = [&](const char* key) {
    lua_getfield(L, -1, key);
    const double v = lua_tonumber(L, -1);
    lua_pop(L, 1);
    return v;
  };
  lua_getfield(L, -1, "won");
  s.won = lua_toboolean(L, -1) != 0;
  lua_pop(L, 1);
  s.wonFrame = static_cast<uint64_t>(number("wonFrame"));
  s.deaths = static_cast<int>(number("deaths"));
  s.time = static_cast<uint64_t>(number("time"));
  s.face = static_cast<physics::MapPartId>(number("face"));
  s.x = static_cast<int32_t>(number("x"));
  s.y = static_cast<int32_t>(number("y"));
  s.vx = number("vx"), s.vy = number("vy");
  lua_getfield(L, -1, "grounded");
  s.grounded = lua_toboolean(L, -1) != 0;
  lua_pop(L, 1);
  lua_getfield(L, -1, "checkpointFace");
  s.hasCheckpoint = lua_isnumber(L, -1) != 0;
  lua_pop(L, 1);
  if (s.hasCheckpoint) {
    s.checkpointFace = static_cast<physics::MapPartId>(number("checkpointFace"));
    s.checkpointX = static_cast<int32_t>(number("checkpointX"));
    s.checkpointY = static_cast<int32_t>(number("checkpointY"));
  }
  lua_getfield(L, -1, "message");
  if (lua_isstring(L, -1)) s.message = lua_tostring(L, -1);
  lua_pop(L, 1);
  lua_getfield(L, -1, "openTags");
  if (lua_istable(L, -1)) {
    const size_t n = std::min<size_t>(lua_objlen(L, -1), 4096);
    for (size_t i = 1; i <= n; ++i) {
      lua_rawgeti(L, -1, static_cast<int>(i));
      if (lua_isnumber(L, -1)) s.openTags.push_back(static_cast<uint32_t>(lua_tonumber(L, -1)));
      lua_pop(L, 1);
    }
  }
  return s;
}

std::string ScriptSystem::evaluate(const std::string& code, const std::string& chunkName) {
  lua_State* L = state_->host.state();
  lua::StackGuard guard(L);
  state_->host.loadString(code, chunkName, Trust::Trusted);
  state_->callDriver("game", 0, 1);
  state_->host.call(1, 1);
  if (lua_isnil(L, -1)) return "";
  if (lua_type(L, -1) == LUA_TBOOLEAN) return lua_toboolean(L, -1) ? "true" : "false";
  lua_getglobal(L, "tostring");
  lua_insert(L, -2);
  state_->host.call(1, 1);
  size_t n = 0;
  const char* text = lua_tolstring(L, -1, &n);
  return std::string(text ? text : "", n);
}

ScriptSystem::ConsoleAnswer ScriptSystem::console(const std::string& code) {
  lua_State* L = state_->host.state();
  lua::StackGuard guard(L);
  ConsoleAnswer answer;
  int sandbox = kNoSandbox, globals = kNoSandbox;
  try {
    // Lines typed before a frame share that frame's budget with its scripts: however many are
    // typed between two frames (or while the game is paused), they get one budget in all.
    if (!consoleOpenedFrame_) state_->host.beginFrame();
    consoleOpenedFrame_ = true;
    // In the level script's globals when it is sandboxed (its own globals are the level's state a
    // modder pokes at), else in a sandbox's fresh ones.
    state_->callDriver("levelSandbox", 0, 1);
    globals = lua_isnumber(L, -1) ? static_cast<int>(lua_tointeger(L, -1)) : kNoSandbox;
    lua_pop(L, 1);
    if (globals == kNoSandbox) {
      if (state_->consoleGlobals == kNoSandbox) {
        state_->consoleGlobals = state_->host.loadString("", "=console", Trust::Sandboxed);
        lua_pop(L, 1);
      }
      globals = state_->consoleGlobals;
    }
    auto compile = [&](const std::string& text) {
      return state_->host.loadStringInGlobalsOf(text, "=console", globals);
    };
    try {  // an expression shows its value; a statement runs as written
      sandbox = compile("local game = ... return " + code);
    } catch (const ScriptError&) {
      sandbox = compile("local game = ... " + code);
    }
    state_->callDriver("levelView", 0, 1);
    if (!state_->host.callSandboxed(sandbox, 1, 1)) {
      answer.text = "not run: the sandboxes' budget is spent";
    } else {
      answer.ok = true;
      if (!lua_isnil(L, -1)) {  // else a statement, or nothing to show
        // The answer is made inside the line's budget: its __tostring is the line's code.
        lua_getfield(L, LUA_REGISTRYINDEX, "platon.tostring");
        lua_insert(L, -2);
        if (state_->host.callSandboxed(sandbox, 1, 1))
          answer.text = lua_isstring(L, -1) ? lua_tostring(L, -1) : "";
        else
          answer.ok = false, answer.text = "not shown: the sandboxes' budget is spent";
      }
    }
  } catch (const ScriptError& e) {
    answer.ok = false;
    answer.text = e.what();
  }
  // The line leaves no sandbox behind: what it made in the world (bodies, platforms) is its globals'
  // owner's from now on, charged to it each frame (a released sandbox is charged nothing, and its
  // place goes to the next sandbox made).
  if (sandbox != kNoSandbox) {
    ScriptContext& context = state_->context;
    for (auto& [key, maker] : context.madeBy)
      if (maker == sandbox) maker = globals;
    for (auto& [number, maker] : context.platforms)
      if (maker == sandbox) maker = globals;
    state_->host.releaseSandbox(sandbox);
  }
  return answer;
}

std::string ScriptSystem::definitions(bool sandboxed, std::vector<std::string>& problems) {
  lua_State* L = state_->host.state();
  lua::StackGuard guard(L);
  state_->host.loadString(embedded_lua::definitions, "=platon/definitions", Trust::Trusted);
  if (sandboxed)
    state_->host.pushSandboxApi();
  else
    state_->host.pushApi();
  state_->callDriver("game", 0, 1);
  lua_getfield(L, -1, "levelApi");
  lua_remove(L, -2);
  state_->host.loadString(embedded_lua::api_signatures, "=platon/api_signatures", Trust::Trusted);
  state_->host.call(0, 1);
  lua_pushboolean(L, sandboxed);
  state_->callDriver("definitionsData", 0, 1);
  lua_createtable(L, static_cast<int>(state_->scene->actions().size()), 0);  // what each action does
  for (size_t i = 0; i < state_->scene->actions().size(); ++i) {
    const std::string& does = state_->scene->actions()[i].does;
    lua_pushlstring(L, does.data(), does.size());
    lua_rawseti(L, -2, static_cast<int>(i + 1));
  }
  state_->host.call(6, 2);
  for (int i = 1;; ++i) {
    lua_rawgeti(L, -1, i);
    if (!lua_isstring(L, -1)) break;
    problems.emplace_back(lua_tostring(L, -1));
    lua_pop(L, 1);
  }
  lua_pop(L, 2);
  size_t n = 0;
  const char* text = lua_tolstring(L, -1, &n);
  return {text ? text : "", n};
}

void ScriptSystem::sourceFiles(std::vector<std::string>& out) const {
  out.insert(out.end(), state_->files.begin(), state_->files.end());
}

void ScriptSystem::carryOver(core::Scene&, core::System& previous) {
  auto* old = dynamic_cast<ScriptSystem*>(&previous);
  if (!old) return;
  lua_State* from = old->state_->host.state();
  lua_State* to = state_->host.state();
  lua::StackGuard guardFrom(from), guardTo(to);
  // The old version's save() may itself be what the edit fixes: if it fails, the new version
  // starts from the level start rather than refusing the fix.
  old->state_->host.beginFrame();
  try {
    old->state_->callDriver("save", 0, 1);
  } catch (const ScriptError&) {
    old->state_->host.takeErrors();
    return;
  }
  old->state_->host.takeErrors();  // a level's or mod's failing save(): that part starts afresh
  PlainCopy job{from, lua_gettop(from)};
  lua_pushcfunction(to, copyPlainProtected);
  lua_pushlightuserdata(to, &job);
  try {
    state_->host.call(1, 1);
  } catch (const ScriptError& e) {
    // Too much (or too deep) to carry over: the reload is refused and the old version goes on.
    // Restarting the level loads the new version afresh, with nothing carried.
    throw ScriptError(std::string("reload refused, the old version goes on: the level's ") + e.what() +
                          "; restart the level to start the new version without it",
                      "");
  }
  state_->host.beginFrame();
  state_->callDriver("restore", 1, 0);
  state_->throwKeptErrors();
}

size_t ScriptSystem::luaMemoryBytes() const { return state_->host.memoryUsed(); }

std::unique_ptr<core::System> makeScriptSystem(core::Scene& scene) {
  return std::make_unique<ScriptSystem>(scene, core::dataRoot());
}

}  // namespace platon::script
