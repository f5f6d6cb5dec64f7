#include "platon/script/script_system.h"

#include <algorithm>
#include <cstdlib>

#include "lua_rules.h"
#include "script_context.h"

namespace platon::script {

struct ScriptSystem::State {
  core::Scene* scene = nullptr;
  std::string root;
  LuaHost host;
  ScriptContext context;
  lua::Ref driver;  // the table scripts/scene.lua returned
  std::unique_ptr<LuaRules> rules;
  std::vector<std::string> files;  // every script file loaded: hot reload watches them
  bool ffi = std::getenv("PLATON_NO_FFI") == nullptr;  // the FFI fast paths (off: for the benches)

  State(core::Scene& s, std::string r, LuaLimits limits) : scene(&s), root(std::move(r)), host(limits) {
    context.scene = &s;
    context.host = &host;
  }

  lua::Ref beforeStep, afterStep;  // driver.beforeStep and driver.afterStep: called every frame

  // Pushes driver[name] and calls it with nargs arguments already pushed after it.
  void callDriver(const char* name, int nargs, int nresults) {
    lua_State* L = host.state();
    driver.push();
    lua_getfield(L, -1, name);
    lua_remove(L, -2);
    if (nargs > 0) lua_insert(L, -(nargs + 1));
    host.call(nargs, nresults);
  }
};

namespace {

ScriptSystem::State& stateOf(lua_State* L) {
  return *static_cast<ScriptSystem::State*>(lua_touserdata(L, lua_upvalueindex(1)));
}

// engine.load(path, trusted, ...) -> the chunk's results. Trusted only for paths under scripts/.
int engineLoad(lua_State* L) {
  ScriptSystem::State& state = stateOf(L);
  const std::string path(lua::checkString(L, 1));
  const bool trusted = lua::checkBoolean(L, 2);
  const int nargs = lua_gettop(L) - 2;
  const std::string file = trusted ? state.root + "/" + path : path;
  state.files.push_back(file);
  state.host.loadFile(file, trusted ? Trust::Trusted : Trust::Sandboxed);
  lua_insert(L, 3);
  state.host.call(nargs, 1);
  return 1;
}

// engine.setRules(rules, sandboxed): rules is a table of callbacks or nil (the C++ defaults);
// sandboxed says its functions run with the JIT off.
int engineSetRules(lua_State* L) {
  ScriptSystem::State& state = stateOf(L);
  const bool sandboxed = lua_toboolean(L, 2) != 0;
  state.scene->world().setRules(nullptr);
  state.rules.reset();
  if (!lua_isnil(L, 1)) {
    const LuaRules::Call how = state.ffi && !sandboxed ? LuaRules::Call::Ffi : LuaRules::Call::Classic;
    state.rules = std::make_unique<LuaRules>(state.host, 1, how);
    state.scene->world().setRules(state.rules.get());
  }
  return 0;
}

int engineNewSandbox(lua_State* L) {
  ScriptSystem::State& state = stateOf(L);
  state.host.newSandbox(lua::checkString(L, 1));
  return 1;
}

constexpr luaL_Reg kEngine[] = {
    {"call", lua::callThrough},
    {"load", lua::bound<engineLoad>},
    {"setRules", lua::bound<engineSetRules>},
    {"newSandbox", lua::bound<engineNewSandbox>},
    {nullptr, nullptr},
};

// Copies plain data from one Lua state to another: nil, booleans, numbers, strings, and tables of
// them keyed by strings or numbers. Functions, userdata, coroutines and anything nested deeper
// than kMaxDepth (a cycle, say) are left out. Runs inside a protected call of the destination, so
// running out of its memory is an error there, not a panic.
constexpr int kMaxDepth = 24;

struct PlainCopy {
  lua_State* from;
  int index;
};

void copyPlain(lua_State* from, int index, lua_State* to, int depth) {
  if (!lua_checkstack(to, 3) || !lua_checkstack(from, 3)) luaL_error(to, "data too deeply nested to carry over");
  switch (lua_type(from, index)) {
    case LUA_TBOOLEAN: return lua_pushboolean(to, lua_toboolean(from, index));
    case LUA_TNUMBER: return lua_pushnumber(to, lua_tonumber(from, index));
    case LUA_TSTRING: {
      size_t n = 0;
      const char* text = lua_tolstring(from, index, &n);
      return lua_pushlstring(to, text, n);
    }
    case LUA_TTABLE:
      if (depth < kMaxDepth) break;
      [[fallthrough]];
    default: return lua_pushnil(to);
  }
  const int source = index < 0 ? lua_gettop(from) + index + 1 : index;
  lua_newtable(to);
  for (lua_pushnil(from); lua_next(from, source); lua_pop(from, 1)) {
    const int keyType = lua_type(from, -2);
    if (keyType != LUA_TSTRING && keyType != LUA_TNUMBER) continue;
    copyPlain(from, -2, to, depth + 1);
    copyPlain(from, lua_gettop(from), to, depth + 1);
    if (lua_isnil(to, -1)) lua_pop(to, 2);
    else lua_rawset(to, -3);
  }
}

int copyPlainProtected(lua_State* to) {
  const auto* job = static_cast<const PlainCopy*>(lua_touserdata(to, 1));
  lua_pop(to, 1);
  copyPlain(job->from, job->index, to, 0);
  return 1;
}

}  // namespace

ScriptSystem::ScriptSystem(core::Scene& scene, std::string root) {
  const core::SceneManifest& m = scene.manifest();
  LuaLimits limits;
  limits.memoryBytes = m.memoryMegabytes << 20;
  limits.callNanoseconds = static_cast<int64_t>(m.callMilliseconds * 1e6);
  state_ = std::make_unique<State>(scene, std::move(root), limits);
  registerWorldApi(state_->host, state_->context);
  if (state_->ffi) registerWorldFfi(state_->host, state_->context);
  registerDrawApi(state_->host, state_->context);
}

ScriptSystem::~ScriptSystem() {
  if (state_ && state_->rules) state_->scene->world().setRules(nullptr);
}

void ScriptSystem::build(core::Scene& scene) {
  lua_State* L = state_->host.state();
  const core::SceneManifest& m = scene.manifest();
  // The trusted `platon` global: the API table itself (sandboxes get read-only views of it).
  state_->host.pushApi();
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
  lua_newtable(L);
  for (size_t i = 0; i < m.mods.size(); ++i) {
    lua_pushlstring(L, m.mods[i].data(), m.mods[i].size());
    lua_rawseti(L, -2, static_cast<int>(i + 1));
  }
  lua_setfield(L, -2, "mods");
  lua_pushnumber(L, m.seed);
  lua_setfield(L, -2, "seed");
  state_->host.call(2, 1);
  state_->driver = lua::Ref(L, -1);
  lua_getfield(L, -1, "beforeStep");
  state_->beforeStep = lua::Ref(L, -1);
  lua_getfield(L, -2, "afterStep");
  state_->afterStep = lua::Ref(L, -1);
  lua_pop(L, 3);
  state_->callDriver("build", 0, 0);
}

void ScriptSystem::start(core::Scene&) { state_->callDriver("start", 0, 0); }

void ScriptSystem::beforeStep(core::Scene&, const core::InputFrame& input) {
  lua_State* L = state_->host.state();
  state_->beforeStep.push();
  lua_pushnumber(L, input.held);
  lua_pushnumber(L, input.pressed);
  state_->host.call(2, 0);
}

void ScriptSystem::afterStep(core::Scene&) {
  state_->afterStep.push();
  state_->host.call(0, 0);
}

void ScriptSystem::draw(const core::Scene&, core::DrawList& out) const {
  state_->context.draw = &out;
  try {
    state_->callDriver("draw", 0, 0);
  } catch (...) {
    state_->context.draw = nullptr;
    throw;
  }
  state_->context.draw = nullptr;
}

GameStatus ScriptSystem::status() const {
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
  try {
    old->state_->callDriver("save", 0, 1);
  } catch (const ScriptError&) {
    return;
  }
  PlainCopy job{from, lua_gettop(from)};
  lua_pushcfunction(to, copyPlainProtected);
  lua_pushlightuserdata(to, &job);
  state_->host.call(1, 1);
  state_->callDriver("restore", 1, 0);
}

size_t ScriptSystem::luaMemoryBytes() const { return state_->host.memoryUsed(); }

std::string engineRoot() {
  if (const char* root = std::getenv("PLATON_ROOT"); root && *root) return root;
  return PLATON_SOURCE_ROOT;
}

std::unique_ptr<core::System> makeScriptSystem(core::Scene& scene) {
  return std::make_unique<ScriptSystem>(scene, engineRoot());
}

}  // namespace platon::script
