// `platon defs DIR`: the Lua language server's definitions of the scripting API.
#pragma once

namespace platon::app {

int defsCommand(int argc, char** argv);

}  // namespace platon::app
