-- luacheck (Debian's lua-check) over the project's Lua, run by ctest (Lint.LuaScriptsLevelsAndSounds):
--   luacheck scripts levels sounds tests/scenarios   (scenarios run trusted: LuaJIT's globals)
-- The engine's own scripts (scripts/, trusted) see LuaJIT's globals and `platon`; a level's
-- scripts, mods and sound banks run in the sandbox and see only its globals, which are these
-- (engine/script/lua/sandbox_prelude.lua: newSandbox). A test keeps this list equal to what a
-- sandboxed script finds in _G (Lint.TheSandboxGlobalsAreTheLintsGlobals).
std = "luajit"
read_globals = { "platon" }
max_line_length = 120
unused_args = false  -- callbacks have the engine's signatures, used or not

stds.sandbox = {
  read_globals = {
    "_G", "_VERSION", "assert", "bit", "collectgarbage", "coroutine", "error", "getmetatable", "ipairs", "math",
    "next", "os", "pairs", "pcall", "platon", "print", "rawequal", "rawget", "select", "setmetatable", "string",
    "table", "tonumber", "tostring", "type", "unpack", "xpcall",
  },
}
files["levels"] = { std = "sandbox" }
files["sounds"] = { std = "sandbox" }
