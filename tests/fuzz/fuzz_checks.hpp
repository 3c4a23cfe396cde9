// What the fuzz targets check beyond the sanitizers, written once: a failed property traps (the
// fuzzer saves the input), and an error's line number must be a line of the text.
#pragma once

#include <stddef.h>

#include <string>

namespace fuzz {

inline void require(bool condition) {
  if (!condition) __builtin_trap();
}

inline size_t line_count(const std::string& text) {
  size_t lines = 1;
  for (char c : text) lines += c == '\n' ? 1 : 0;
  return lines;
}

}  // namespace fuzz
