// Level designer commands: `platon check level...` and `platon net SOLID|level -o net.svg`.
#pragma once
#include <string>
#include <vector>

namespace platon::app {

int checkCommand(int argc, char** argv);
int netCommand(int argc, char** argv);

// What `platon check` reports as errors for a level given in any of its forms ("file:line:column:
// why"); empty when it has none.
std::vector<std::string> levelErrors(const std::string& level);

}  // namespace platon::app
