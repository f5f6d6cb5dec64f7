// `platon edit LEVEL [--new SOLID|mesh-file]`: the level editor in a window (docs/editing.md).
#pragma once
#include <string>

#include "level_argument.h"
#include "platon/core/system.h"

namespace platon::app {

int editCommand(int argc, char** argv);  // argv[0] is "edit"

// The editor on `level` until Esc, in `shown`'s window when given (F4 in `platon play`: the same
// window), else in a window of its own; `shotPath`: save its first picture there and return.
// Returns 0, kWindowClosed when the window was closed (the program that opened the editor quits
// too: SDL delivers SIGTERM the same way), or 1 after saying why the level cannot be edited. `newLevel`: made by --new
// just now (a mesh level's face lines, known once the mesh is read, are saved at once).
inline constexpr int kWindowClosed = 3;
int editLevel(const LevelArgument& level, core::SystemRegistry& registry, core::System* shown,
              const std::string& shotPath = "", bool newLevel = false);

}  // namespace platon::app
