#include "platon/core/input.h"

#include <array>

namespace platon::core {
namespace {
constexpr std::array<std::string_view, kButtonCount> kNames{"left", "right",   "up",    "down",
                                                            "jump", "restart", "pause", "reload"};
}  // namespace

std::string_view buttonName(Button button) { return kNames[static_cast<size_t>(button)]; }

bool buttonFromName(std::string_view name, Button& out) {
  for (size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) {
      out = static_cast<Button>(i);
      return true;
    }
  return false;
}

}  // namespace platon::core
