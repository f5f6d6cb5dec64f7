#include "save_file.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace platon::app {
namespace {

// mkdir -p, for the data and config folders.
void makeFolders(const std::string& path) {
  for (size_t i = 1; i <= path.size(); ++i)
    if (i == path.size() || path[i] == '/') mkdir(path.substr(0, i).c_str(), 0755);
}

}  // namespace

std::string saveWhole(const std::string& path, const std::string& text, const std::string& what) {
  const size_t slash = path.find_last_of('/');
  if (slash != std::string::npos) makeFolders(path.substr(0, slash));
  const std::string temporary = path + ".new";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  bool written = fd >= 0;
  for (size_t done = 0; written && done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n <= 0)
      written = false;
    else
      done += static_cast<size_t>(n);
  }
  written = written && ::fsync(fd) == 0;
  if (fd >= 0) ::close(fd);
  if (!written) {
    if (fd >= 0) std::remove(temporary.c_str());
    return temporary + ": cannot write " + what;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) return path + ": cannot replace " + what;
  return "";
}

std::string userFolder(const std::string& kind) {
  const bool config = kind == "config";
  const char* xdg = std::getenv(config ? "XDG_CONFIG_HOME" : "XDG_DATA_HOME");
  if (xdg && xdg[0] == '/') return std::string(xdg) + "/platon";
  const char* home = std::getenv("HOME");
  return std::string(home && home[0] ? home : ".") + (config ? "/.config/platon" : "/.local/share/platon");
}

std::string saveScreenshot(core::Display& display) {
  const std::string folder = userFolder("data") + "/screenshots";
  makeFolders(folder);
  const std::time_t now = std::time(nullptr);
  char name[64];
  std::strftime(name, sizeof name, "platon-%Y%m%d-%H%M%S", std::localtime(&now));
  std::string path = folder + "/" + name + ".png";
  for (int n = 2; access(path.c_str(), F_OK) == 0; ++n)  // several in one second
    path = folder + "/" + name + "-" + std::to_string(n) + ".png";
  try {
    display.saveScreenshot(path);
    return "screenshot: " + path;
  } catch (const std::exception& e) {
    return e.what();
  }
}

}  // namespace platon::app
