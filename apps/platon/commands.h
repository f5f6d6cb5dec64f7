// The program's commands, in one table: each one's name, what it is for in a line, and its usage
// (printed to stdout by `platon COMMAND --help`, to stderr with exit status 2 on a bad argument).
// `platon --help` lists them all from the same table.
#pragma once
#include <span>
#include <string_view>

namespace platon::app {

struct Command {
  const char* name;
  const char* summary;                // one line
  const char* usage;                  // "usage: platon NAME ..." and what each option means
  int (*run)(int argc, char** argv);  // argv[0] is the command's name
};

std::span<const Command> commands();
const Command* findCommand(std::string_view name);
// The command's usage on stderr; returns 2 (a usage error's exit status).
int usageError(std::string_view name);
// Every command with its summary, then how to ask one for its options.
void printCommands(bool toStdout);

}  // namespace platon::app
