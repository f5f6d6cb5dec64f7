// platon.sound: what scripts make heard. Sounds are asked for on fixed frames (a tick, a rule, an
// afterStep), so a replay hears the same sounds on the same frames; the scene records them whether
// or not a device plays them (core/sound.h). Names are checked against the scene's bank headless
// too, so a misspelt sound fails in a scenario as it would in the game.
#include <string>

#include "script_context.h"

namespace platon::script {
namespace {

// A number within [low, high] at `index`, or `fallback` when it is absent or nil.
float optionalIn(lua_State* L, int index, double fallback, double low, double high, const char* what) {
  if (lua_isnoneornil(L, index)) return static_cast<float>(fallback);
  const double v = lua::checkNumber(L, index);
  if (v < low || v > high) lua::argError(L, index, what);
  return static_cast<float>(v);
}

// play(name [, volume [, pan]]): the effect `name` of the scene's bank, this frame. Volume 0..1
// (1), pan -1 (left) .. 1 (right) (0). Returns false when the frame already has
// core::Sounds::kMaxPerFrame effects (the sound is dropped), else true.
int play(lua_State* L) {
  ScriptContext& context = contextOf(L);
  const std::string_view name = lua::checkString(L, 1);
  core::Sounds& sounds = context.scene->sounds();
  if (!sounds.bank().hasEffect(name))
    throw lua::ArgError("sound: no effect named '" + std::string(name).substr(0, 64) +
                        "' (the scene's bank has: " + sounds.bank().effectNames() + ")");
  const float volume = optionalIn(L, 2, 1, 0, 1, "a volume 0..1");
  const float pan = optionalIn(L, 3, 0, -1, 1, "a pan -1..1");
  // draw() runs once per displayed frame, not per simulated one: a sound from it would depend on
  // the display's rate and never match a headless run.
  if (context.draw)
    throw lua::ArgError("sound: play from a frame's logic, not from draw (it runs per displayed frame)");
  lua_pushboolean(L, sounds.play(std::string(name), volume, pan));
  return 1;
}

// music(name): the tune of the scene's bank that plays from now on (looping); nil or "" for none.
int music(lua_State* L) {
  core::Sounds& sounds = contextOf(L).scene->sounds();
  if (lua_isnoneornil(L, 1)) {
    sounds.setMusic("");
    return 0;
  }
  const std::string_view name = lua::checkString(L, 1);
  if (!name.empty() && !sounds.bank().hasMusic(name))
    throw lua::ArgError("sound: no tune named '" + std::string(name).substr(0, 64) +
                        "' (the scene's bank has: " + sounds.bank().musicNames() + ")");
  sounds.setMusic(std::string(name));
  return 0;
}

// has(name): whether the scene's bank has an effect (or, with "music" as argument 2, a tune) so named.
int has(lua_State* L) {
  const std::string_view name = lua::checkString(L, 1);
  const core::SoundBank& bank = contextOf(L).scene->sounds().bank();
  bool found = bank.hasEffect(name);
  if (!lua_isnoneornil(L, 2)) {
    if (lua::checkString(L, 2) != "music") lua::argError(L, 2, "nil or \"music\"");
    found = bank.hasMusic(name);
  }
  lua_pushboolean(L, found);
  return 1;
}

// playing(): the tune's name, or nil.
int playing(lua_State* L) {
  const std::string& name = contextOf(L).scene->sounds().music();
  if (name.empty()) return 0;
  lua_pushlstring(L, name.data(), name.size());
  return 1;
}

constexpr luaL_Reg kSound[] = {
    {"play", lua::bound<play>},       {"music", lua::bound<music>}, {"has", lua::bound<has>},
    {"playing", lua::bound<playing>}, {nullptr, nullptr},
};

}  // namespace

void registerSoundApi(LuaHost& host, ScriptContext& context) { addApiTable(host, context, "sound", kSound); }

}  // namespace platon::script
