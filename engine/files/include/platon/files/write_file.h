// The one way a file is saved (progress, settings, a level from the editor, a kept test, a replay, a
// report, a picture): written whole to a new file beside it, flushed to the disk, renamed over the
// old, so that a crash or a power cut mid-save leaves the old file or the new one, never half of
// either; its folders made first.
//
// A save never writes through a link, whoever planted it: the new file is made with O_CREAT |
// O_EXCL | O_NOFOLLOW under a name of its own (a link or a file already of that name makes it pick
// another), and the file it replaces must be a regular file or absent: a link, a folder or a FIFO
// of the saved name is refused, so a downloaded level folder cannot point a save outside itself.
#pragma once
#include <string>

namespace platon::files {

// "" when saved, else why not: "<path>: cannot write <what>: <reason>" (what: "the progress file").
std::string saveWhole(const std::string& path, const std::string& text, const std::string& what);
// The same, throwing std::runtime_error with that message.
void saveWholeOrThrow(const std::string& path, const std::string& text, const std::string& what);
// mkdir -p: each folder of `path` that is missing (what cannot be made shows when the file is written).
void makeFolders(const std::string& path);

}  // namespace platon::files
