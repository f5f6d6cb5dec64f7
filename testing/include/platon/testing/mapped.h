// Whether a library is mapped into this process (/proc/self/maps): the tests that prove a plugin,
// and what it links, is loaded only when a scene needs it.
#pragma once
#include <fstream>
#include <sstream>
#include <string>

namespace platon::testing {

inline bool mapped(const char* library) {
  std::ifstream maps("/proc/self/maps");
  std::stringstream text;
  text << maps.rdbuf();
  return text.str().find(library) != std::string::npos;
}

}  // namespace platon::testing
