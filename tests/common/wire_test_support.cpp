#include "wire_test_support.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>

namespace wire_test {

std::vector<uint8_t> from_hex(const std::string& text, bool* ok) {
  std::vector<uint8_t> out;
  bool good = true;
  size_t i = 0;
  while (i < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[i])) != 0) {
      ++i;
      continue;
    }
    if (i + 1 >= text.size() || std::isxdigit(static_cast<unsigned char>(text[i])) == 0 ||
        std::isxdigit(static_cast<unsigned char>(text[i + 1])) == 0) {
      good = false;
      break;
    }
    out.push_back(static_cast<uint8_t>(std::stoul(text.substr(i, 2), nullptr, 16)));
    i += 2;
  }
  if (ok != nullptr) *ok = good;
  return out;
}

std::string to_hex(const std::vector<uint8_t>& bytes) {
  std::string out;
  char piece[4];
  for (size_t i = 0; i < bytes.size(); ++i) {
    std::snprintf(piece, sizeof piece, "%02X", bytes[i]);
    if (i > 0) out += ' ';
    out += piece;
  }
  return out;
}

wire::Frame frame_of(const wire::FrameBytes& bytes) {
  const std::vector<wire::Frame> frames = parse_all(bytes_of(bytes));
  if (frames.size() != 1) {
    ADD_FAILURE() << "not exactly one frame in " << to_hex(bytes_of(bytes));
    return wire::Frame{};
  }
  return frames.front();
}

}  // namespace wire_test
