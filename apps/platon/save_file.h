// Saving a player's file (progress, settings) so that a crash or a power cut mid-save leaves the
// old file or the new one, never half of either: written whole to a new file, flushed to the disk,
// renamed over the old; its folders made first.
#pragma once
#include <string>

#include "platon/core/display.h"
#include "platon/files/write_file.h"

namespace platon::app {

using files::makeFolders;  // platon/files/write_file.h
using files::saveWhole;

// The player's own folder for the game, by the XDG base directories: $XDG_DATA_HOME/platon
// (kind "data", else ~/.local/share/platon) or $XDG_CONFIG_HOME/platon ("config", else
// ~/.config/platon). A relative XDG variable is ignored, as the specification says.
std::string userFolder(const std::string& kind);

// F12 in the game and in `platon play`: the frame on screen as a PNG in the data folder's
// screenshots/ (made when missing), named by the local time. Returns what to tell the player.
std::string saveScreenshot(core::Display& display);

}  // namespace platon::app
