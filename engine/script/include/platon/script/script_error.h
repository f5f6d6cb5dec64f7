// A Lua error as C++ sees it: the message (which starts with the script's file:line when Lua knows
// it) and the traceback of the Lua stack at the point of the error.
#pragma once
#include <string>

#include "platon/core/error.h"

namespace platon::script {

class ScriptError : public core::DetailedError {
 public:
  ScriptError(const std::string& message, std::string traceback) : core::DetailedError(message, std::move(traceback)) {}
  // "stack traceback:\n\t[C]: ..." as Lua prints it; empty when the error came from outside Lua.
  const std::string& traceback() const { return details(); }
};

}  // namespace platon::script
