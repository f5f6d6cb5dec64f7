#pragma once

namespace platon::app {

// `platon game`: the title screen, the level select and the campaign in a window.
int gameCommand(int argc, char** argv);

}  // namespace platon::app
