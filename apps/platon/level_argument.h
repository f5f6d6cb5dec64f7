// What every command that takes a level accepts, read one way: the level's folder
// (levels/cube_intro), its scene.lua, its .level file, or a folder name under levels/
// (cube_intro), here or in the program's own data.
#pragma once
#include <string>

namespace platon::app {

struct LevelArgument {
  std::string scene;      // the scene.lua ("" when a .level file has none beside it)
  std::string levelFile;  // the .level file the scene names, or the one given ("" when none)
};

// Throws std::runtime_error naming what it looked for when the argument is none of these, and the
// manifest's own error (file:line:column) when the scene's manifest is broken.
LevelArgument levelArgument(const std::string& argument);

}  // namespace platon::app
