// The player's own folders for the game and the screenshots saved there.
#pragma once
#include <string>

#include "platon/core/display.h"

namespace platon::session {

// The player's own folder for the game, by the XDG base directories: $XDG_DATA_HOME/platon
// (kind "data", else ~/.local/share/platon) or $XDG_CONFIG_HOME/platon ("config", else
// ~/.config/platon). A relative XDG variable is ignored, as the specification says.
std::string userFolder(const std::string& kind);

// F12 in every window: the frame on screen as a PNG in the data folder's screenshots/ (made when
// missing), named by the local time. Returns what to tell the player.
std::string saveScreenshot(core::Display& display);

}  // namespace platon::session
