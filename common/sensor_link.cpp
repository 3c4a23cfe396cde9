#include <common/sensor_link.hpp>

#include <common/crc8.hpp>

namespace simlink {

uint8_t check(const uint8_t* type_and_payload, size_t length) { return wire::crc8(type_and_payload, length); }

void LinkWriter::operator()(uint8_t v) { out_[size_++] = v; }
void LinkWriter::operator()(uint16_t v) {
  (*this)(static_cast<uint8_t>(v));
  (*this)(static_cast<uint8_t>(v >> 8));
}
void LinkWriter::operator()(uint32_t v) {
  (*this)(static_cast<uint16_t>(v));
  (*this)(static_cast<uint16_t>(v >> 16));
}

void LinkReader::operator()(uint8_t& v) { v = *in_++; }
void LinkReader::operator()(uint16_t& v) {
  uint8_t low = 0, high = 0;
  (*this)(low);
  (*this)(high);
  v = static_cast<uint16_t>(low | (high << 8));
}
void LinkReader::operator()(uint32_t& v) {
  uint16_t low = 0, high = 0;
  (*this)(low);
  (*this)(high);
  v = low | (static_cast<uint32_t>(high) << 16);
}

void frame_around(LinkFrameBytes& frame, LinkType type, size_t length) {
  frame.bytes[0] = kStart;
  frame.bytes[1] = static_cast<uint8_t>(type);
  frame.bytes[2 + length] = check(frame.bytes + 1, length + 1);
  frame.size = static_cast<uint8_t>(length + kLinkOverhead);
}

// Every pass either waits for more bytes, drops at least one, or hands out a frame and drops its
// bytes, so the buffer never holds more than one frame's worth.
bool LinkParser::advance(LinkFrame& frame) {
  for (;;) {
    if (length_ == 0) return false;
    if (buffer_[0] != kStart) {
      drop(1);
      ++skipped_;
      continue;
    }
    if (length_ < 2) return false;
    const size_t n = payload_length(listener_, buffer_[1]);
    if (n == 0) {
      drop(1);
      ++skipped_;
      continue;
    }
    if (length_ < n + kLinkOverhead) return false;
    if (check(buffer_ + 1, n + 1) != buffer_[n + 2]) {
      drop(1);
      ++skipped_;
      continue;
    }
    for (size_t i = 0; i < n; ++i) payload_[i] = buffer_[2 + i];
    frame = LinkFrame{buffer_[1], static_cast<uint8_t>(n), payload_};
    drop(n + kLinkOverhead);
    ++frames_;
    return true;
  }
}

void LinkParser::drop(size_t count) {
  for (size_t i = count; i < length_; ++i) buffer_[i - count] = buffer_[i];
  length_ -= count;
}

}  // namespace simlink
