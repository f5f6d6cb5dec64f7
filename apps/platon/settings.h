// The player's settings, saved in $XDG_CONFIG_HOME/platon/settings.txt (~/.config/platon/ by
// default) as "name value" lines. A damaged file never stops the game: each line it cannot read
// keeps that setting's default, and problems() says which and why, at file:line.
#pragma once
#include <string>
#include <vector>

#include "platon/core/display.h"

namespace platon::app {

struct Settings {
  int musicVolume = 60;     // percent
  int effectsVolume = 90;   // percent
  bool screenShake = true;  // the view shakes on a death and the goal
  bool fullscreen = false;
  bool vsync = true;
  int gameSpeed = 100;  // percent, 50..100: the assist mode (pacing only; recorded in replays)
  int multisamples =
      -1;  // samples a pixel: -1 auto (4; none on a software rasterizer), 0, 2, 4, 8 (from the next frame)
  // keys_jump Space, pad_jump a, b ...: SDL's names, commas between, by action name (an action a
  // mod adds too: keys_dash); an action with none keeps its defaults (core/actions.h).
  core::BindingChoices keys;

  // $XDG_CONFIG_HOME/platon/settings.txt, or ~/.config/platon/settings.txt.
  static std::string defaultPath();
  // Reads `path` (no file: the defaults, no problem).
  static Settings load(const std::string& path, std::vector<std::string>& problems);
  // The file's text, which load() reads back to the same settings.
  std::string text() const;
  // "" when saved, else why not (the game goes on with them unsaved).
  std::string save(const std::string& path) const;
};

}  // namespace platon::app
