// Which of a set of files were saved since the last look, from Linux inotify.
//
// Editors save in different ways: in place (a close after writing), or by writing a new file and
// renaming it over the old one (vim, most IDEs), which replaces the inode a per-file watch would
// follow. So the watcher watches each file's folder and picks the events by name.
//
// This uses the C library's inotify calls directly rather than libinotifytools: that library keeps
// its state in process globals (one watcher per process), waits in whole seconds, and is GPL-2.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace platon::core {

class FileWatcher {
 public:
  // Throws std::runtime_error when inotify is not available.
  FileWatcher();
  ~FileWatcher();
  FileWatcher(const FileWatcher&) = delete;
  FileWatcher& operator=(const FileWatcher&) = delete;

  // Makes `files` the watched set. A folder watched before and still wanted keeps its watch, so a
  // save that is already queued, or that lands while the set changes, is still reported by the
  // next changes(); only folders no longer wanted are dropped. A file that does not exist yet is
  // watched for its creation. A folder that does not exist (or cannot be watched) is an error:
  // every other file is watched all the same, then std::runtime_error names the folders left out.
  // Returns the files that were not watched before this call (they may have been saved before
  // their watch began: the caller can compare their times).
  std::vector<std::string> watch(const std::vector<std::string>& files);
  // The watched files (as given to watch()) saved since the last call, each once; waits up to
  // `timeoutMilliseconds` for the first one (0: just look).
  std::vector<std::string> changes(int timeoutMilliseconds = 0);

 private:
  int fd_ = -1;
  std::map<int, std::string> folders_;        // watch descriptor -> folder
  std::map<std::string, std::string> files_;  // folder + '/' + name -> the path as given
};

}  // namespace platon::core
