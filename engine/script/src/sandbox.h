// The sandbox's environment factory, written in Lua and run once per state as trusted code.
#pragma once
#include <string_view>

namespace platon::script {

// A chunk that takes the C print function and returns newSandbox(name, api) -> environment table.
std::string_view sandboxPrelude();

}  // namespace platon::script
