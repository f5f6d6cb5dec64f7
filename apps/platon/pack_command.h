// `platon pack LEVEL --replay run.replay [-o out.platon]` and `platon install PACKAGE`: levels
// that travel (docs/packages.md).
#pragma once
#include <string>

namespace platon::app {

int packCommand(int argc, char** argv);
int installCommand(int argc, char** argv);

// The player's own levels: $XDG_DATA_HOME/platon/levels (the title screen lists them).
std::string userLevelsFolder();

}  // namespace platon::app
