#include <common/crc24.hpp>
#include <common/crc8.hpp>
#include <common/frame.hpp>

namespace wire {

FrameBytes make_frame(MessageType type, const uint8_t* payload, size_t length) {
  FrameBytes frame;
  const MessageSpec* spec = find_message(type_byte(type));
  if (spec == nullptr || spec->payload_length != length) return frame;

  // The check byte is the CRC-8 of everything from the type byte on, taken as each byte is written
  // (one pass: every frame the QR sends, telemetry most of all, is made here).
  frame.bytes[0] = kStartByte;
  frame.bytes[1] = type_byte(type);
  uint8_t check = crc8_update(0, frame.bytes[1]);
  for (size_t i = 0; i < length; ++i) {
    frame.bytes[2 + i] = payload[i];
    check = crc8_update(check, payload[i]);
  }
  size_t end = 2 + length;
  if (spec->guarded) {
    const uint32_t guard = crc24(&frame.bytes[1], 1 + length);
    for (int i = 0; i < kGuardBytes; ++i) {
      frame.bytes[end] = static_cast<uint8_t>(guard >> (8 * i));
      check = crc8_update(check, frame.bytes[end++]);
    }
  }
  frame.bytes[end] = check;
  frame.size = frame_length(*spec);
  return frame;
}

}  // namespace wire
