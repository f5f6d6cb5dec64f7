// The names a package may hold: each part of a path plain (letters, digits, '.', '-', '_', not
// starting with '.'), at most 8 parts and 200 bytes, '/' between them.
#pragma once
#include <string>

namespace platon::package {

// Why `path` cannot be a file's path in a package, or "" when it can.
std::string pathProblem(const std::string& path);

}  // namespace platon::package
