#include "platon/core/system.h"

#include <stdexcept>

namespace platon::core {

void SystemRegistry::add(std::string name, SystemFactory factory) {
  if (has(name)) throw std::invalid_argument("system '" + name + "' is registered twice");
  entries_.push_back({std::move(name), std::move(factory)});
}

bool SystemRegistry::has(std::string_view name) const {
  for (const Entry& e : entries_)
    if (e.name == name) return true;
  return false;
}

std::unique_ptr<System> SystemRegistry::create(std::string_view name, Scene& scene) const {
  for (const Entry& e : entries_)
    if (e.name == name) return e.factory(scene);
  std::string known;
  for (const Entry& e : entries_) known += (known.empty() ? "" : ", ") + e.name;
  throw std::invalid_argument("unknown system '" + std::string(name) + "' (known: " + (known.empty() ? "none" : known) +
                              ")");
}

std::vector<std::string> SystemRegistry::names() const {
  std::vector<std::string> out;
  for (const Entry& e : entries_) out.push_back(e.name);
  return out;
}

}  // namespace platon::core
