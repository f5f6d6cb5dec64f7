// An error with more to say than one line: the message (starting with file:line where known) and
// details such as a Lua traceback. Systems throw it; the core shows report() without knowing
// which system it came from.
#pragma once
#include <stdexcept>
#include <string>

namespace platon::core {

class DetailedError : public std::runtime_error {
 public:
  DetailedError(const std::string& message, std::string details)
      : std::runtime_error(message), details_(std::move(details)) {}
  const std::string& details() const { return details_; }
  // The message and the details, as shown on screen or printed by a failing run.
  std::string report() const { return details_.empty() ? what() : std::string(what()) + "\n" + details_; }

 private:
  std::string details_;
};

// report() for a DetailedError, what() for any other exception.
inline std::string errorReport(const std::exception& e) {
  if (const auto* d = dynamic_cast<const DetailedError*>(&e)) return d->report();
  return e.what();
}

}  // namespace platon::core
