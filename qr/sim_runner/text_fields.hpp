// The two readings every text input of the simulator needs (scenario files, the truth channel's
// commands, command-line values): a line cut into words, and a word that is a whole finite number.
#pragma once

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace qrsim {

// The words of `line`, split at any white space.
inline std::vector<std::string> words_of(std::string_view line) {
  std::vector<std::string> words;
  size_t i = 0;
  const auto space = [&line](size_t at) { return std::isspace(static_cast<unsigned char>(line[at])) != 0; };
  while (i < line.size()) {
    while (i < line.size() && space(i)) ++i;
    const size_t start = i;
    while (i < line.size() && !space(i)) ++i;
    if (i > start) words.emplace_back(line.substr(start, i - start));
  }
  return words;
}

// True when all of `text` is one finite number (no trailing characters, no inf or nan).
inline bool parse_real(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(out);
}

}  // namespace qrsim
