#include "platon/stage/stage_error.h"

namespace platon::stage {

std::string describe(const SourcePosition& where) {
  std::string out = where.file;
  if (where.line > 0) out += (out.empty() ? "line " : ":") + std::to_string(where.line);
  if (where.line > 0 && where.column > 0) out += ":" + std::to_string(where.column);
  return out.empty() ? out : out + ": ";
}

StageError::StageError(SourcePosition where, std::string reason)
    : std::runtime_error(describe(where) + reason), where_(std::move(where)), reason_(std::move(reason)) {}

}  // namespace platon::stage
