// The systems the platon program offers scenes: scripting (linked in), meshes (a plugin, loaded
// only for a level drawn on a mesh), rendering when the program draws (a plugin, loaded only when a
// scene names it) and audio when a person plays (a plugin, likewise).
#pragma once
#include <string>
#include <vector>

#include "platon/core/system.h"

namespace platon::app {

// Headless: no picture, no sound (runs, scenarios, checks). Picture: drawn, silent (platon shot).
// Window: drawn and heard (the game, platon play).
enum class Presentation { Headless, Picture, Window };

core::SystemRegistry engineRegistry(Presentation presentation);

// Where plugins are looked for (after $PLATON_PLUGIN_PATH): the program's plugin folder, found from
// the program's own (core::pluginFolder()).
std::vector<std::string> pluginFolders();

}  // namespace platon::app
