// The frame: 'M' (0x4D) · type · payload (fixed length for the type) · check.
// The check is CRC-8/DVB-S2 over type and payload; the start byte is not covered (a damaged start
// byte loses the frame, it cannot make a wrong one).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/message_table.hpp>

namespace wire {

inline constexpr uint8_t kStartByte = 0x4D;   // 'M'
inline constexpr uint8_t kFrameOverhead = 3;  // start, type, check

// The longest payload for which the check still catches every 2-bit error: type + payload +
// check must stay within 93 bits, the period of the polynomial's non-(x+1) factor (crc8.hpp).
inline constexpr uint8_t kMaxPayloadBytes = 9;
inline constexpr uint8_t kMaxFrameBytes = kMaxPayloadBytes + kFrameOverhead;

// A received frame: its check has been verified and its type is in the table.
struct Frame {
  MessageType type = MessageType::control;
  uint8_t length = 0;
  uint8_t payload[kMaxPayloadBytes] = {};  // bytes past `length` are 0

  constexpr bool operator==(const Frame&) const = default;
};

// Bytes ready to go out on the serial line, start byte to check byte.
struct FrameBytes {
  uint8_t bytes[kMaxFrameBytes] = {};
  uint8_t size = 0;  // 0: nothing to send (the payload did not fit the table's length)

  constexpr bool operator==(const FrameBytes&) const = default;
};

// Frames `payload` as `type`. The length must be the table's length for the type; otherwise the
// result is empty (size 0) rather than a frame no receiver would read the same way.
FrameBytes make_frame(MessageType type, const uint8_t* payload, size_t length);

}  // namespace wire
