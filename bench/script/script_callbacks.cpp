// One contact callback: the game's hazard rule in Lua (through LuaRules, as the engine calls it),
// the same rule in C++, and a bare lua_pcall of an empty Lua function, the least any call into Lua
// costs. Goal (issue 9): the Lua callback <= 2x the bare lua_pcall.
//   build/bench/script_callbacks [calls] [runs]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "lua_host.h"
#include "lua_rules.h"
#include "spread.h"

using namespace platon;

namespace {

class HazardRule final : public physics::Rules {  // scripts/rules/game.lua's contact(), in C++
 public:
  physics::EntityId player;
  bool killed = false;
  void contact(const physics::Contact& c, physics::ContactResponse&) override {
    if (c.line.tag == 1 && c.entity == player) killed = true;
  }
};

template <class F>
double nanosecondsPerCall(uint64_t calls, F&& f) {
  const auto start = std::chrono::steady_clock::now();
  for (uint64_t i = 0; i < calls; ++i) f(i);
  return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
         static_cast<double>(calls);
}

}  // namespace

int main(int argc, char** argv) {
  const uint64_t calls = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 7;
  script::LuaHost host;
  lua_State* L = host.state();
  // scripts/rules/game.lua's hazard rule, alone.
  const std::string hazardRule =
      "local player, killed = 7, false\n"
      "return { contact = function(entity, tag, kind, part, line, nx, ny, other)\n"
      "  if tag == 1 and entity == player then killed = true end\n"
      "end }";
  host.loadString(hazardRule + ", function() end\n", "=bench", script::Trust::Trusted);
  host.call(0, 2);
  script::LuaRules luaRules(host, -2, script::LuaRules::Call::Classic);
  script::LuaRules ffiRules(host, -2, script::LuaRules::Call::Ffi);
  const int empty = luaL_ref(L, LUA_REGISTRYINDEX);
  lua_pop(L, 1);
  // The same rule in a mod: sandboxed, its functions interpreted (the JIT is off for them).
  const int mod = host.loadString(hazardRule + "\n", "=mod", script::Trust::Sandboxed);
  host.beginFrame();
  host.callSandboxed(mod, 0, 1);
  // As the engine calls a mod's rules: under the frame's budget (beginFrame below, as every frame).
  script::LuaRules modClassic(host, -1, script::LuaRules::Call::Classic, mod);
  lua_pop(L, 1);
  HazardRule hazard;
  hazard.player = {7, 0};
  physics::Rules* volatile opaque = &hazard;  // called as the world calls it: virtually, not inlined
  physics::Rules& cppRules = *opaque;

  physics::Contact contact{};
  contact.entity = {3, 1};
  contact.line = {0, 12, 0, physics::LineKind::Solid, {}};
  contact.normal = {0, 65536};
  physics::ContactResponse response;

  std::vector<double> lua, ffi, cpp, bare, handled, ratio, ffiRatio, ffiHandledRatio, sandboxClassic;
  for (int r = 0; r < runs; ++r) {
    lua.push_back(nanosecondsPerCall(calls, [&](uint64_t i) {
      contact.line.tag = static_cast<uint32_t>(i & 1);
      luaRules.contact(contact, response);
    }));
    ffi.push_back(nanosecondsPerCall(calls, [&](uint64_t i) {
      contact.line.tag = static_cast<uint32_t>(i & 1);
      ffiRules.contact(contact, response);
    }));
    host.beginFrame();  // a run is less than one frame's budget of sandboxed time
    sandboxClassic.push_back(nanosecondsPerCall(calls, [&](uint64_t i) {
      contact.line.tag = static_cast<uint32_t>(i & 1);
      modClassic.contact(contact, response);
    }));
    cpp.push_back(nanosecondsPerCall(calls, [&](uint64_t i) {
      contact.line.tag = static_cast<uint32_t>(i & 1);
      cppRules.contact(contact, response);
    }));
    bare.push_back(nanosecondsPerCall(calls, [&](uint64_t) {
      lua_rawgeti(L, LUA_REGISTRYINDEX, empty);
      lua_pcall(L, 0, 0, 0);
    }));
    // The pcall an engine that reports tracebacks must make: with a message handler (the host's,
    // in the state's first slot) and the callback's one result read and popped.
    handled.push_back(nanosecondsPerCall(calls, [&](uint64_t) {
      lua_rawgeti(L, LUA_REGISTRYINDEX, empty);
      lua_pcall(L, 0, 1, 1);
      if (lua_type(L, -1) != LUA_TNIL) std::abort();
      lua_settop(L, -2);
    }));
    ratio.push_back(lua.back() / bare.back());
    ffiRatio.push_back(ffi.back() / bare.back());
    ffiHandledRatio.push_back(ffi.back() / handled.back());
  }
  std::printf("one contact callback, %llu calls a run, %d interleaved runs; median (min-max) ns per call\n",
              static_cast<unsigned long long>(calls), runs);
  std::printf("  Lua rule, classic (8 arguments pushed, traceback handler, budget)   : %s\n",
              bench::Spread::of(lua).show("%.1f").c_str());
  std::printf("  Lua rule, FFI (struct written, JIT-compiled trampoline; the engine's): %s\n",
              bench::Spread::of(ffi).show("%.1f").c_str());
  std::printf("  sandboxed rule (a mod's: JIT off, so the classic path)            : %s\n",
              bench::Spread::of(sandboxClassic).show("%.1f").c_str());
  std::printf("  C++ rule (virtual call)                                             : %s\n",
              bench::Spread::of(cpp).show("%.1f").c_str());
  std::printf("  bare lua_pcall of an empty function                                 : %s\n",
              bench::Spread::of(bare).show("%.1f").c_str());
  std::printf("  classic Lua rule / bare lua_pcall: %s\n", bench::Spread::of(ratio).show("%.2f").c_str());
  std::printf("  FFI Lua rule / bare lua_pcall    : %s (goal <= 2: %s)\n",
              bench::Spread::of(ffiRatio).show("%.2f").c_str(),
              bench::runsMet(ffiRatio.size(), [&](size_t i) { return ffiRatio[i] <= 2.0; }).c_str());
  std::printf("  lua_pcall with a traceback handler and one result                  : %s\n",
              bench::Spread::of(handled).show("%.1f").c_str());
  std::printf("  FFI Lua rule / that lua_pcall    : %s (<= 2: %s)\n",
              bench::Spread::of(ffiHandledRatio).show("%.2f").c_str(),
              bench::runsMet(ffiHandledRatio.size(), [&](size_t i) { return ffiHandledRatio[i] <= 2.0; }).c_str());
  return 0;
}
