// `platon edit LEVEL [--new SOLID|mesh-file]`: the level editor in a window (docs/editing.md).
#pragma once

namespace platon::app {

int editCommand(int argc, char** argv);  // argv[0] is "edit"

}  // namespace platon::app
