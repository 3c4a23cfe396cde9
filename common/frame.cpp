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
  frame.bytes[2 + length] = crc8(&frame.bytes[1], 1 + length);
  frame.size = static_cast<uint8_t>(length + kFrameOverhead);
  return frame;
}

}  // namespace wire
