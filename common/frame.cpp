#include <common/crc24.hpp>
#include <common/crc8.hpp>
#include <common/frame.hpp>

namespace wire {

FrameBytes make_frame(MessageType type, const uint8_t* payload, size_t length) {
  FrameBytes frame;
  const MessageSpec* spec = find_message(type_byte(type));
  if (spec == nullptr || spec->payload_length != length) return frame;

  frame.bytes[0] = kStartByte;
  frame.bytes[1] = type_byte(type);
  for (size_t i = 0; i < length; ++i) frame.bytes[2 + i] = payload[i];
  size_t end = 2 + length;
  if (spec->guarded) {
    const uint32_t guard = crc24(&frame.bytes[1], 1 + length);
    for (int i = 0; i < kGuardBytes; ++i) frame.bytes[end++] = static_cast<uint8_t>(guard >> (8 * i));
  }
  frame.bytes[end] = crc8(&frame.bytes[1], end - 1);
  frame.size = frame_length(*spec);
  return frame;
}

}  // namespace wire
