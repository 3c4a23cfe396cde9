// The frame: 'M' (0x4D) · type · payload (fixed length for the type) · [guard] · check.
// The check is CRC-8/DVB-S2 over everything between the start byte and itself; the start byte is
// not covered (a damaged start byte loses the frame, it cannot make a wrong one). The guard, on
// the commanding requests only (MessageSpec::guarded), is CRC-24/OPENPGP over type and payload,
// three bytes, least significant first: random bytes pass the check 1 time in 256, and a guarded
// frame's check and guard together 1 time in 2^32 (docs/protocol.md, sections 2 and 10).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/message_table.hpp>

namespace wire {

inline constexpr uint8_t kStartByte = 0x4D;   // 'M'
inline constexpr uint8_t kFrameOverhead = 3;  // start, type, check
inline constexpr uint8_t kGuardBytes = 3;     // the commanding requests' CRC-24

// The longest payload for which the check still catches every 2-bit error: type + payload +
// check must stay within 93 bits, the period of the polynomial's non-(x+1) factor (crc8.hpp).
inline constexpr uint8_t kMaxPayloadBytes = 9;
inline constexpr uint8_t kMaxFrameBytes = kMaxPayloadBytes + kFrameOverhead;

// Bytes on the line for a message of this spec, start byte to check byte.
constexpr uint8_t frame_length(const MessageSpec& spec) {
  return static_cast<uint8_t>(spec.payload_length + kFrameOverhead + (spec.guarded ? kGuardBytes : 0));
}

// Every frame fits the longest, and the check still sees every 2-bit error in it (at most 88 bits
// from the type byte to the check, crc8.hpp).
constexpr bool frames_fit() {
  for (const MessageSpec& spec : kMessageTable) {
    if (spec.payload_length > kMaxPayloadBytes || frame_length(spec) > kMaxFrameBytes) return false;
  }
  return true;
}
static_assert(frames_fit(), "a frame longer than kMaxFrameBytes");

// A received frame: its check (and guard) have been verified and its type is in the table. The
// payload is the message's alone, without the guard.
struct Frame {
  MessageType type = MessageType::control;
  uint8_t length = 0;
  uint8_t payload[kMaxPayloadBytes] = {};  // bytes past `length` are 0

  constexpr bool operator==(const Frame&) const = default;
};

// Bytes ready to go out on the serial line, start byte to check byte. Word-aligned: every frame
// the QR sends starts as a zeroed one, and 13 bytes on a byte boundary were cleared through a
// memcpy call (RV32, 40 instructions), 16 on a word boundary are four stores.
struct alignas(4) FrameBytes {
  uint8_t bytes[kMaxFrameBytes] = {};
  uint8_t size = 0;  // 0: nothing to send (the payload did not fit the table's length)

  constexpr bool operator==(const FrameBytes&) const = default;
};

// Frames `payload` as `type`. The length must be the table's length for the type; otherwise the
// result is empty (size 0) rather than a frame no receiver would read the same way.
FrameBytes make_frame(MessageType type, const uint8_t* payload, size_t length);

}  // namespace wire
