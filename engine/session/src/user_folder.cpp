#include "platon/session/user_folder.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <unistd.h>

#include "platon/files/write_file.h"

namespace platon::session {

std::string userFolder(const std::string& kind) {
  const bool config = kind == "config";
  const char* xdg = std::getenv(config ? "XDG_CONFIG_HOME" : "XDG_DATA_HOME");
  if (xdg && xdg[0] == '/') return std::string(xdg) + "/platon";
  const char* home = std::getenv("HOME");
  return std::string(home && home[0] ? home : ".") + (config ? "/.config/platon" : "/.local/share/platon");
}

std::string saveScreenshot(core::Display& display) {
  const std::string folder = userFolder("data") + "/screenshots";
  files::makeFolders(folder);
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

}  // namespace platon::session
