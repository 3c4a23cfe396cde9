// A sensor recording as the devboard reads it from memory (docs/devboard.md): a 20-byte header,
// then one record per control period, all little-endian.
//   header: "QRRC" | u16 version (2; 1 is read too) | u16 record bytes (28; 24 in version 1)
//           | u32 record count | u32 rate (Hz) | u32 time of the first record (µs)
//   record: i16 gyro x,y,z | i16 accel x,y,z | u16 battery mV | u16 lift | i16 roll, pitch, yaw
//           | u16 flags (0) | i32 pressure Pa (version 2 only: version 1 has no barometer, 0)
// The sticks are used by test mode (replay) only; flying from the console, they come from the link.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <qr/core/board.hpp>
#include <qr/core/flight_types.hpp>

namespace rv32virt {

inline constexpr uint8_t kRecordingMagic[4] = {'Q', 'R', 'R', 'C'};
inline constexpr uint16_t kRecordingVersion = 2;
inline constexpr size_t kRecordingHeaderBytes = 20;
inline constexpr size_t kRecordBytes = 28;
inline constexpr size_t kRecordBytesVersion1 = 24;  // before the barometer

struct RecordedTick {
  qr::SensorSample sample;
  qr::ControlInput sticks;
};

class Recording {
 public:
  // Reads the header at `bytes`; valid() is false when there is no recording of our format.
  explicit Recording(const uint8_t* bytes);

  bool valid() const { return count_ != 0; }
  uint32_t count() const { return count_; }
  uint32_t rate_hz() const { return rate_hz_; }
  RecordedTick at(uint32_t index) const;
  // Time of record `index`: one control period after the one before (wrapping like the clock).
  uint32_t time_us(uint32_t index) const { return start_us_ + index * (1000000u / rate_hz_); }

 private:
  const uint8_t* records_ = nullptr;
  size_t record_bytes_ = kRecordBytes;
  uint32_t count_ = 0;
  uint32_t rate_hz_ = 0;
  uint32_t start_us_ = 0;
};

}  // namespace rv32virt
