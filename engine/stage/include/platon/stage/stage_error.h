// The one error the stage module throws: a bad level file, mesh or solid. Carries where the
// problem is (file:line:column for text, a triangle or vertex for a mesh) and why, so a level
// designer can go straight to it.
#pragma once
#include <stdexcept>
#include <string>

namespace platon::stage {

struct SourcePosition {
  std::string file;  // may be empty (text given without a name)
  int line = 0;      // 1-based; 0: the whole file
  int column = 0;    // 1-based; 0: the whole line
};

class StageError : public std::runtime_error {
 public:
  StageError(SourcePosition where, std::string reason);
  const SourcePosition& where() const { return where_; }
  const std::string& reason() const { return reason_; }

 private:
  SourcePosition where_;
  std::string reason_;
};

// "file:line:column: " with the parts that are known.
std::string describe(const SourcePosition& where);

}  // namespace platon::stage
