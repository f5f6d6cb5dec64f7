// What a fuzz target does when an input breaks its invariant: prints the whole input (NUL bytes
// shown, the fuzzer puts them in) and then the reason, last, so the tail of a log that CI shows
// has it; then aborts so libFuzzer keeps the input.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <string>

[[noreturn]] inline void bug(const std::string& what, const std::string& text) {
  std::string shown;
  for (const char c : text) shown += c == '\0' ? std::string("\\0") : std::string(1, c);
  std::fprintf(stderr, "--- input ---\n%s\n-------------\nBUG: %s\n", shown.c_str(), what.c_str());
  std::abort();
}
