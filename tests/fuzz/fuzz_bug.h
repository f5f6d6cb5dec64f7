// What a fuzz target does when an input breaks its invariant: prints the reason and the whole
// input (NUL bytes shown, the fuzzer puts them in), then aborts so libFuzzer keeps the input.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <string>

[[noreturn]] inline void bug(const std::string& what, const std::string& text) {
  std::string shown;
  for (const char c : text) shown += c == '\0' ? std::string("\\0") : std::string(1, c);
  std::fprintf(stderr, "BUG: %s\n--- input ---\n%s\n-------------\n", what.c_str(), shown.c_str());
  std::abort();
}
