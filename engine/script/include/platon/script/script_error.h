// A Lua error as C++ sees it: the message (which starts with the script's file:line when Lua knows
// it) and the traceback of the Lua stack at the point of the error.
#pragma once
#include <stdexcept>
#include <string>

namespace platon::script {

class ScriptError : public std::runtime_error {
 public:
  ScriptError(const std::string& message, std::string traceback)
      : std::runtime_error(message), traceback_(std::move(traceback)) {}
  // "stack traceback:\n\t[C]: ..." as Lua prints it; empty when the error came from outside Lua.
  const std::string& traceback() const { return traceback_; }
  // The message and the traceback, as shown on screen or printed by a failing scenario.
  std::string report() const { return traceback_.empty() ? what() : std::string(what()) + "\n" + traceback_; }

 private:
  std::string traceback_;
};

}  // namespace platon::script
