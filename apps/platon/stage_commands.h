// Level designer commands: `platon check level...` and `platon net SOLID|level -o net.svg`.
#pragma once

namespace platon::app {

int checkCommand(int argc, char** argv);
int netCommand(int argc, char** argv);

}  // namespace platon::app
