// How much of the QR -> PC line observable streams may take (docs/protocol.md section 13.4). The
// QR refuses a stream request the line cannot carry beside the basic telemetry and the replies
// (nack over_budget); the console runs the same arithmetic to show what a selection costs before
// it asks. Whole bytes per second, rounded against the streams: the rule never promises more
// than the line has.
#pragma once

#include <stdint.h>

#include <common/frame.hpp>

namespace wire {

inline constexpr uint32_t kLineBytesPerS = 11520;  // 115200 baud, 8N1: 10 bits a byte
// One telemetry period (section 7): attitude 12 + rates 9 + the largest slow group 12
// (telemetry_link) + a task figure 10.
inline constexpr uint32_t kTelemetryPeriodBytes = 43;
// Acks, nacks, parameter reports, debug text, log status: under 500 bytes/s in practice (section
// 7); twice that is kept free.
inline constexpr uint32_t kReplyReserveBytesPerS = 1000;

inline constexpr uint8_t kStreamCount = 4;           // streams that may run at once
inline constexpr uint8_t kStreamObservablesMax = 4;  // observables in one stream
inline constexpr uint8_t kSampleValuesPerFrame = 4;  // 16-bit values in one observable_samples frame
inline constexpr uint32_t kSampleFrameBytes = 12;    // 'M', type, 9 payload bytes, check

// A frame carries whole samples: 4 of a one-observable stream, 2 of a two-observable one, 1 of a
// stream of 3 or 4.
constexpr uint8_t samples_per_frame(uint8_t observables) {
  return observables == 0 || observables > kSampleValuesPerFrame
             ? uint8_t{0}
             : static_cast<uint8_t>(kSampleValuesPerFrame / observables);
}

// Bytes per second a stream of `observables` sampled every `divider` control periods sends,
// rounded up. Divider 0 is a stopped stream.
constexpr uint32_t stream_bytes_per_s(uint32_t control_hz, uint16_t divider, uint8_t observables) {
  const uint32_t per_frame = samples_per_frame(observables);
  if (divider == 0 || per_frame == 0) return 0;
  const uint32_t ticks_per_frame = divider * per_frame;
  return (control_hz * kSampleFrameBytes + ticks_per_frame - 1) / ticks_per_frame;
}

// What is left for streams with telemetry periods at `telemetry_hz`.
constexpr uint32_t stream_room_bytes_per_s(uint32_t telemetry_hz) {
  const uint32_t taken = telemetry_hz * kTelemetryPeriodBytes + kReplyReserveBytesPerS;
  return taken >= kLineBytesPerS ? 0 : kLineBytesPerS - taken;
}

// Samples per second (one sample = one observable's value) a stream carries.
constexpr uint32_t stream_samples_per_s(uint32_t control_hz, uint16_t divider, uint8_t observables) {
  return divider == 0 ? 0 : control_hz * observables / divider;
}

}  // namespace wire
