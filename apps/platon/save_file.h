// Saving a player's file (progress, settings) so that a crash or a power cut mid-save leaves the
// old file or the new one, never half of either: written whole to a new file, flushed to the disk,
// renamed over the old; its folders made first.
#pragma once
#include <string>

#include "platon/files/write_file.h"
#include "platon/session/user_folder.h"

namespace platon::app {

using files::makeFolders;  // platon/files/write_file.h
using files::saveWhole;
using session::saveScreenshot;  // platon/session/user_folder.h
using session::userFolder;

}  // namespace platon::app
