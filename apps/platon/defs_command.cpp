// `platon defs DIR`: writes the Lua language server's definitions (---@meta) of the scripting
// API, from the engine's live binding tables (ScriptSystem::definitions), in two sets: DIR/trusted
// for the engine's own scripts, DIR/sandbox for level scripts and mods; each with a .luarc.json
// that, copied into a folder of such scripts, points the server at them. Fails, naming them, when a binding has no
// definition or a definition no binding.
#include "defs_command.h"

#include <cstdio>
#include <filesystem>
#include <unistd.h>

#include "commands.h"
#include "engine_registry.h"
#include "platon/core/error.h"
#include "platon/core/live_scene.h"
#include "platon/files/write_file.h"
#include "platon/script/script_system.h"

namespace platon::app {
namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::string& text) {
  files::saveWholeOrThrow(path.string(), text, "the definitions");
}

// The server's settings for the folder of scripts `workspace`: LuaJIT, these definitions (by a
// path from that folder: no machine's own path goes into a file that travels), and for
// sandboxed scripts the libraries a sandbox does not have turned off (docs/scripting.md, "Sandbox").
std::string luarc(const fs::path& definitions, const fs::path& workspace, bool sandboxed) {
  const std::string builtins = sandboxed ? "\"io\": \"disable\", \"debug\": \"disable\", \"package\": \"disable\", "
                                           "\"ffi\": \"disable\", \"jit\": \"disable\""
                                         : "";
  const fs::path from =
      fs::absolute(definitions).lexically_normal().lexically_relative(fs::absolute(workspace).lexically_normal());
  return "{\n  \"runtime.version\": \"LuaJIT\",\n  \"workspace.library\": [\"" +
         (from.empty() ? std::string(".") : from.generic_string()) + "\"],\n  \"runtime.builtin\": {" + builtins +
         "}\n}\n";
}

}  // namespace

int defsCommand(int argc, char** argv) {
  fs::path out, level;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--for" && i + 1 < argc)
      level = argv[++i];
    else if (out.empty() && !a.empty() && a[0] != '-')
      out = a;
    else
      return usageError("defs");
  }
  if (out.empty()) return usageError("defs");
  try {
    // A scene with the game's scripts, for the live tables (a level's `game` is made by them).
    const fs::path scene = fs::temp_directory_path() / ("platon_defs_" + std::to_string(::getpid()));
    writeFile(scene / "scene.lua", "return { systems = { 'scripting' }, scripts = { preset = 'game' } }\n");
    std::vector<std::string> problems;
    std::string trusted, sandboxed;
    {
      const core::SystemRegistry registry = engineRegistry(Presentation::Headless);
      core::LiveScene live((scene / "scene.lua").string(), registry, false);
      auto& scripts = dynamic_cast<script::ScriptSystem&>(*live.scene().findSystem("scripting"));
      trusted = scripts.definitions(false, problems);
      sandboxed = scripts.definitions(true, problems);
    }
    fs::remove_all(scene);
    for (const std::string& p : problems) std::fprintf(stderr, "%s\n", p.c_str());
    if (!problems.empty()) return 1;
    writeFile(out / "trusted" / "platon.lua", trusted);
    writeFile(out / "trusted" / ".luarc.json", luarc(out / "trusted", out / "trusted", false));
    writeFile(out / "sandbox" / "platon.lua", sandboxed);
    writeFile(out / "sandbox" / ".luarc.json", luarc(out / "sandbox", out / "sandbox", true));
    if (!level.empty()) {  // the level's folder, pointed at the sandbox's definitions from where it is
      writeFile(level / ".luarc.json", luarc(out / "sandbox", level, true));
      std::printf("%s: the settings for a level's scripts\n", (level / ".luarc.json").string().c_str());
    }
    std::printf("%s: definitions for trusted scripts (trusted/) and level scripts and mods (sandbox/)\n",
                out.string().c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", core::errorReport(e).c_str());
    return 1;
  }
}

}  // namespace platon::app
