// Where the engine's own files are, found from where the program is: no path of the machine that
// built it is compiled in, so an installed tree moves anywhere and needs no source tree.
//
// The layout is the installed one (GNUInstallDirs): bin/platon, the plugins in lib/platon/, the
// engine's scripts, the campaign's levels and the shipped scenarios and replays in share/platon/.
// The build tree mirrors it: build/lib/platon/ holds the plugins, and build/share/platon/ links to
// the sources' scripts/ and levels/, so a program in any folder one level below the build's top
// (build/apps/platon, build/tests/...) finds them the same way.
#pragma once
#include <optional>
#include <string>

namespace platon::core {

// The folder of the running program (from /proc/self/exe).
std::string programFolder();

// The folder that holds the engine's scripts/ and levels/: $PLATON_ROOT when set (a modder's copy
// of the engine's scripts), else <programFolder()>/../share/platon. Throws std::runtime_error naming
// where it looked when that folder has no scripts/scene.lua.
std::string dataRoot();

// One of the engine's own files (sounds/bank.lua): under dataRoot() when it is there, else in the
// program's own data folder, so a modder's PLATON_ROOT needs to copy only what it changes.
std::string engineFile(const std::string& relative);

// Where plugins are looked for after $PLATON_PLUGIN_PATH: <programFolder()>/../lib/platon.
// (That folder does not depend on $PLATON_ROOT: the plugins belong to the program.)
std::string pluginFolder();

// A path a person or a file names (a scene, a campaign, a scenario's scene): as given when it exists
// from the current folder or is absolute, else the same path under dataRoot() when it exists there
// (so "levels/cube_intro/scene.lua" names the shipped level from any folder), else as given (its
// reader then says it is missing).
std::string resolveDataPath(const std::string& path);

// A scene path a replay or scenario (`namingFile`) names: from that file's own folder when the
// scene is there (a level shared with its replays), else as resolveDataPath finds it.
std::string resolveNamedPath(const std::string& path, const std::string& namingFile);

// The path a replay or scenario written here should name a scene by, so that it can be shared:
// relative and without "..", from the game's data folder when the scene is in it (an installed
// campaign level: "levels/cube_intro/scene.lua"), else from the current folder. Nothing when it is
// in neither (a replay names no absolute path: a stranger's could name any file).
std::optional<std::string> portableScenePath(const std::string& path);

}  // namespace platon::core
