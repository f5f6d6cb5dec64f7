// Saving a player's file (progress, settings) so that a crash or a power cut mid-save leaves the
// old file or the new one, never half of either: written whole to a new file, flushed to the disk,
// renamed over the old; its folders made first.
#pragma once
#include <string>

namespace platon::app {

// "" when saved, else why not: "<path>: cannot write <what>" (what: "the progress file").
std::string saveWhole(const std::string& path, const std::string& text, const std::string& what);

}  // namespace platon::app
