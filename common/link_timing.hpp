// Timing rules of the link, shared by both ends. Time always comes in from the caller, in ms, as a
// wrapping uint32 counter; nothing here reads a clock.
#pragma once

#include <stdint.h>

namespace wire {

inline constexpr uint32_t kControlPeriodMs = 20;    // PC sends Control at 50 Hz
inline constexpr uint32_t kResendIntervalMs = 100;  // an unacknowledged request is sent again after this
inline constexpr uint8_t kMaxSends = 10;            // first send plus 9 resends, then give up
inline constexpr uint32_t kGiveUpAfterMs = kResendIntervalMs * kMaxSends;  // 1 s after the first send

// How long the QR remembers the last sequence number of each request type. Longer than a request
// is ever re-sent, so every resend is recognised; short enough that a console restarted with the
// same sequence numbers is not mistaken for a resend for long.
inline constexpr uint32_t kDedupWindowMs = 2 * kGiveUpAfterMs;

// The serial line: 115200 baud, 8N1, ten bit times a byte; a byte is through when its stop bit
// is, 86 806 ns after its start bit (rounded to the ns; 0.0005 % off, nothing over any flight).
// The simulator's line and the devboard's paced transmitter both count in this.
inline constexpr uint32_t kLineBaud = 115200;
inline constexpr uint32_t kLineByteTimeNs = static_cast<uint32_t>((10ull * 1000000000ull + kLineBaud / 2) / kLineBaud);

// `now` is at or after `then`, for wrapping millisecond counters less than 2^31 ms apart.
constexpr bool reached(uint32_t now, uint32_t then) { return now - then < 0x80000000u; }

}  // namespace wire
