// The one way a file is saved (progress, settings, a level from the editor): written whole to a
// new file beside it, flushed to the disk, renamed over the old, so that a crash or a power cut
// mid-save leaves the old file or the new one, never half of either; its folders made first.
#pragma once
#include <string>

namespace platon::files {

// "" when saved, else why not: "<path>: cannot write <what>" (what: "the progress file").
std::string saveWhole(const std::string& path, const std::string& text, const std::string& what);
// mkdir -p: each folder of `path` that is missing (what cannot be made shows when the file is written).
void makeFolders(const std::string& path);

}  // namespace platon::files
