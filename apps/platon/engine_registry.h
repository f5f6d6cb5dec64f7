// The systems the platon program offers scenes: scripting (linked in) and, when the program shows
// a window, rendering (a plugin, loaded only when a scene names it).
#pragma once
#include "platon/core/system.h"

namespace platon::app {

enum class Presentation { Headless, Window };

core::SystemRegistry engineRegistry(Presentation presentation);

}  // namespace platon::app
