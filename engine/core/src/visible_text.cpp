#include "platon/core/visible_text.h"

#include <cstdint>
#include <cstdio>

namespace platon::core {
namespace {

// The length of the valid UTF-8 character at text[i], or 0.
size_t utf8Length(std::string_view text, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = byte(i);
  size_t length = 0;
  uint32_t code = 0;
  if (b < 0x80) return 1;
  if (b >= 0xC2 && b <= 0xDF)
    length = 2, code = b & 0x1F;
  else if (b >= 0xE0 && b <= 0xEF)
    length = 3, code = b & 0x0F;
  else if (b >= 0xF0 && b <= 0xF4)
    length = 4, code = b & 0x07;
  else
    return 0;
  if (i + length > text.size()) return 0;
  for (size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = code << 6 | (byte(i + k) & 0x3F);
  }
  const bool overlong = (length == 3 && code < 0x800) || (length == 4 && code < 0x10000);
  if (overlong || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return length;
}

}  // namespace

std::string visibleText(std::string_view text, bool keepLineBreaks) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const unsigned char b = static_cast<unsigned char>(text[i]);
    const size_t length = utf8Length(text, i);
    const bool control = b < 0x20 && b != '\t' && !(keepLineBreaks && b == '\n');
    if (length == 0 || control || b == 0x7F) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", b);
      out += escaped;
      ++i;
    } else {
      out.append(text, i, length);
      i += length;
    }
  }
  return out;
}

}  // namespace platon::core
