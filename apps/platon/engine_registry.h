// The systems the platon program offers scenes: scripting (linked in), meshes (a plugin, loaded
// only for a level drawn on a mesh) and, when the program shows a window, rendering (a plugin,
// loaded only when a scene names it).
#pragma once
#include <string>
#include <vector>

#include "platon/core/system.h"

namespace platon::app {

enum class Presentation { Headless, Window };

core::SystemRegistry engineRegistry(Presentation presentation);

// Where plugins are looked for (after $PLATON_PLUGIN_PATH): the program's plugin folder, found from
// the program's own (core::pluginFolder()).
std::vector<std::string> pluginFolders();

}  // namespace platon::app
