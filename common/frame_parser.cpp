#include <common/crc24.hpp>
#include <common/crc8.hpp>
#include <common/frame_parser.hpp>

namespace wire {

// Looks at the kept bytes as the start of a frame. Returns true when they begin with a whole,
// valid frame (copied to frame_ and removed); false when more bytes are needed.
bool FrameParser::advance() {
  while (length_ > 0) {
    if (buffer_[0] != kStartByte) {
      uint8_t next_start = 1;
      while (next_start < length_ && buffer_[next_start] != kStartByte) ++next_start;
      discard(next_start, true);
      continue;
    }
    if (length_ < 2) return false;

    const MessageSpec* spec = find_message(buffer_[1]);
    if (spec == nullptr || !listens_to(listen_, spec->direction)) {
      ++counters_.unknown_types;
      discard(1, true);  // the 'M' was not a start; the type byte may be one
      continue;
    }

    const uint8_t length = frame_length(*spec);
    if (length_ < length) return false;

    const uint8_t check_at = static_cast<uint8_t>(length - 1);
    if (crc8(&buffer_[1], check_at - 1u) != buffer_[check_at] || !guard_holds(*spec)) {
      ++counters_.check_failures;
      discard(1, true);  // a real frame may start anywhere after this false 'M'
      continue;
    }

    frame_.type = spec->type;
    frame_.length = spec->payload_length;
    for (uint8_t i = 0; i < kMaxPayloadBytes; ++i) frame_.payload[i] = i < spec->payload_length ? buffer_[2 + i] : 0;
    ++counters_.frames_ok;
    discard(length, false);
    return true;
  }
  return false;
}

// The kept frame's guard, when its type has one, is the CRC-24 of its type and payload.
bool FrameParser::guard_holds(const MessageSpec& spec) const {
  if (!spec.guarded) return true;
  const uint8_t* guard = &buffer_[2 + spec.payload_length];
  const uint32_t sent = guard[0] | static_cast<uint32_t>(guard[1]) << 8 | static_cast<uint32_t>(guard[2]) << 16;
  return crc24(&buffer_[1], 1u + spec.payload_length) == sent;
}

void FrameParser::discard(uint8_t count, bool skipped) {
  if (skipped) counters_.bytes_skipped += count;
  for (uint8_t i = count; i < length_; ++i) buffer_[i - count] = buffer_[i];
  length_ = static_cast<uint8_t>(length_ - count);
}

}  // namespace wire
