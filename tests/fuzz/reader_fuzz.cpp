// libFuzzer target: the readers of the files players share and modders write, other than levels:
// the data reader of scene manifests and scenarios (a Lua table literal, read as data: no Lua
// runs) and the replay reader. Any text is either refused with an error that starts with the
// file's name and a line ("f.lua:3:7: ..."), or read. What the data reader reads, LuaJIT reads to
// the same value (same types, the same bits of every number, the same bytes of every string, the
// same keys); a replay read writes back to text that reads to the same replay. Anything else
// (another exception, a crash, a sanitizer report) is a bug.
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "fuzz_bug.h"
#include "platon/core/lua_data.h"
#include "platon/core/replay.h"
#include "platon/testing/lua_reference.h"

using namespace platon;

namespace {

// "file:line:" with a line of at least 1.
bool placed(const std::string& message, const std::string& file) {
  if (message.rfind(file + ":", 0) != 0) return false;
  const size_t digits = message.find_first_not_of("0123456789", file.size() + 1);
  return digits != std::string::npos && digits > file.size() + 1 && message[digits] == ':' &&
         message.compare(file.size() + 1, 2, "0:") != 0;
}

// The reference: LuaJIT, with no library opened (a literal needs none).
lua_State* reference() {
  static lua_State* L = luaL_newstate();
  return L;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const core::DataValue v = core::readLuaData(text, "f.lua");
    // Only text the reader took for a literal runs: it computes nothing.
    lua_State* L = reference();
    lua_settop(L, 0);
    if (luaL_loadbuffer(L, text.data(), text.size(), "=f.lua") != 0 || lua_pcall(L, 0, 1, 0) != 0)
      bug(std::string("the data reader reads what LuaJIT refuses: ") + lua_tostring(L, -1), text);
    std::string why;
    if (!testing::sameAsLua(L, 1, v, why)) bug("the data reader and LuaJIT differ: " + why, text);
    lua_settop(L, 0);
    lua_gc(L, LUA_GCCOLLECT, 0);
  } catch (const core::DataError& e) {
    if (!placed(e.what(), "f.lua")) bug(std::string("a data refusal without its place: ") + e.what(), text);
  }
  core::Replay replay;
  try {
    replay = core::parseReplay(text, "f.replay");
  } catch (const std::runtime_error& e) {
    if (!placed(e.what(), "f.replay")) bug(std::string("a replay refusal without its place: ") + e.what(), text);
    return 0;
  }
  const std::string written = core::formatReplay(replay);
  core::Replay again;
  try {
    again = core::parseReplay(written, "again.replay");
  } catch (const std::runtime_error& e) {
    bug(std::string("a replay read does not read back: ") + e.what(), text);
  }
  if (again.scene != replay.scene || again.held != replay.held || again.hashEvery != replay.hashEvery ||
      again.sceneFiles != replay.sceneFiles || again.hashes.size() != replay.hashes.size())
    bug("a replay read back differs", text);
  return 0;
}
