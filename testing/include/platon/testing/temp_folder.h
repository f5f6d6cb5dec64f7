// A folder of a test's own under the system's temporary directory, removed when the test ends;
// files are written into it on demand. The process id keeps parallel test processes apart.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace platon::testing {

class TempFolder {
 public:
  explicit TempFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("platon_" + name + "_" + std::to_string(getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() { std::filesystem::remove_all(path_); }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  // Writes `text` to `file` (folders created) and returns its full path.
  std::string write(const std::string& file, const std::string& text) const {
    const std::filesystem::path p = path_ / file;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary | std::ios::trunc) << text;
    return p.string();
  }
  std::string path(const std::string& file = "") const { return (path_ / file).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace platon::testing
