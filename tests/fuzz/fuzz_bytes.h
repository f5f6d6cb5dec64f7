// A fuzz input read a byte at a time, for targets that build structured inputs from it (an
// archive's entries, a stream of edits): zeros once it runs out.
#pragma once
#include <cstddef>
#include <cstdint>

struct Bytes {
  const uint8_t* data;
  size_t size, at = 0;
  uint8_t next() { return at < size ? data[at++] : 0; }
  bool more() const { return at < size; }
};
