// Helpers shared by the wire tests: hex text <-> bytes, and running bytes through a parser.
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include <common/frame.hpp>
#include <common/frame_parser.hpp>

namespace wire_test {

inline std::vector<uint8_t> bytes_of(const wire::FrameBytes& frame) {
  return std::vector<uint8_t>(frame.bytes, frame.bytes + frame.size);
}

// "4D 11 F4" -> {0x4D, 0x11, 0xF4}. Anything that is not a pair of hex digits is an error.
std::vector<uint8_t> from_hex(const std::string& text, bool* ok = nullptr);
std::string to_hex(const std::vector<uint8_t>& bytes);

inline std::vector<wire::Frame> parse_all(wire::FrameParser& parser, const std::vector<uint8_t>& bytes) {
  std::vector<wire::Frame> frames;
  for (uint8_t b : bytes) parser.push(b, [&](const wire::Frame& f) { frames.push_back(f); });
  return frames;
}

inline std::vector<wire::Frame> parse_all(const std::vector<uint8_t>& bytes, wire::Listen listen = wire::Listen::both) {
  wire::FrameParser parser(listen);
  return parse_all(parser, bytes);
}

// The frame a parser would deliver for these encoded bytes (which must be a whole valid frame).
wire::Frame frame_of(const wire::FrameBytes& bytes);

}  // namespace wire_test
