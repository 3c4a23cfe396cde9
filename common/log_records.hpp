// Log lines and how they cross the wire. A log line is larger than one frame may carry (9 payload
// bytes, crc8.hpp), so it travels as a few parts: each part names the line number and the part
// index and carries 6 bytes of the line's flat little-endian record. The PC puts the parts of a
// line back together; a line missing any part is asked for again by number (LogDownload).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/message_table.hpp>
#include <common/mode.hpp>
#include <common/payload_codec.hpp>
#include <common/units.hpp>

namespace wire {

inline constexpr uint8_t kLogPartDataBytes = 6;

// One sample of the raw and filtered sensors, written at the sensor log rate.
struct SensorLogRecord {
  static constexpr MessageType kPartType = MessageType::sensor_log_part;
  static constexpr uint8_t kParts = 5;
  uint16_t line = 0;                      // carried in every part, not in the flat record
  uint32_t time_us = 0;                   // QR clock, wraps after 71 minutes
  int16_t gyro[3] = {0, 0, 0};            // raw counts x, y, z
  int16_t accel[3] = {0, 0, 0};           // raw counts x, y, z
  int16_t gyro_filtered[3] = {0, 0, 0};   // same counts, after the low-pass filter
  int16_t accel_filtered[3] = {0, 0, 0};  // same counts, after the low-pass filter
  uint16_t battery_mv = 0;

  constexpr bool operator==(const SensorLogRecord&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.time_us);
    v(m.gyro);
    v(m.accel);
    v(m.gyro_filtered);
    v(m.accel_filtered);
    v(m.battery_mv);
  }
  constexpr bool valid() const { return true; }
};

// One control period's state, written at the telemetry log rate.
struct TelemetryLogRecord {
  static constexpr MessageType kPartType = MessageType::telemetry_log_part;
  static constexpr uint8_t kParts = 7;
  uint16_t line = 0;
  uint32_t time_us = 0;
  Mode mode = Mode::safe;
  uint8_t flags = 0;  // as TelemetryAttitude::flags
  uint16_t lift = 0;  // set-points as in TelemetrySetpoints
  int16_t roll = 0;
  int16_t pitch = 0;
  int16_t yaw_rate = 0;
  int16_t phi = 0;  // estimates as in TelemetryAttitude / TelemetryRates
  int16_t theta = 0;
  int16_t psi = 0;
  int16_t p = 0;
  int16_t q = 0;
  int16_t r = 0;
  uint16_t engine[4] = {0, 0, 0, 0};
  uint16_t loop_time_us = 0;
  uint16_t battery_mv = 0;
  uint16_t cpu_load = 0;
  uint16_t deadline_misses = 0;

  constexpr bool operator==(const TelemetryLogRecord&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.time_us);
    v(m.mode);
    v(m.flags);
    v(m.lift);
    v(m.roll);
    v(m.pitch);
    v(m.yaw_rate);
    v(m.phi);
    v(m.theta);
    v(m.psi);
    v(m.p);
    v(m.q);
    v(m.r);
    v(m.engine);
    v(m.loop_time_us);
    v(m.battery_mv);
    v(m.cpu_load);
    v(m.deadline_misses);
  }
  constexpr bool valid() const {
    bool engines_in_range = true;
    for (uint16_t e : engine) engines_in_range = engines_in_range && e <= kEngineMax;
    return valid_mode(mode) && lift <= kLiftMax && engines_in_range && cpu_load <= kPermilleMax;
  }
};

// LogStatus::flags bits
inline constexpr uint8_t kLogStatusSensorOn = 0x01;
inline constexpr uint8_t kLogStatusTelemetryOn = 0x02;
inline constexpr uint8_t kLogStatusFull = 0x04;  // a log filled up and stopped keeping lines

// The QR's logs as they stand: sent in the telemetry rotation and after every log request, so the
// console knows how many lines a download must bring (lines lost at the end are noticed too).
struct LogStatus {
  static constexpr MessageType kType = MessageType::log_status;
  uint8_t flags = 0;          // kLogStatus* bits
  uint16_t sensor_lines = 0;  // lines 0..sensor_lines-1 exist
  uint16_t telemetry_lines = 0;
  uint16_t capacity_lines = 0;  // lines each log can hold

  constexpr bool operator==(const LogStatus&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.flags);
    v(m.sensor_lines);
    v(m.telemetry_lines);
    v(m.capacity_lines);
  }
  constexpr bool valid() const {
    return (flags & ~(kLogStatusSensorOn | kLogStatusTelemetryOn | kLogStatusFull)) == 0 &&
           sensor_lines <= capacity_lines && telemetry_lines <= capacity_lines;
  }
};

template <class Record>
concept LogRecord = requires {
  Record::kPartType;
  Record::kParts;
}
&&wire_size<Record>() == size_t{Record::kParts} * kLogPartDataBytes;

template <LogRecord Record>
struct LogPart {
  static constexpr MessageType kType = Record::kPartType;
  uint16_t line = 0;
  uint8_t part = 0;                      // 0..Record::kParts-1
  uint8_t data[kLogPartDataBytes] = {};  // bytes [6*part, 6*part+6) of the flat record

  constexpr bool operator==(const LogPart&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.line);
    v(m.part);
    v(m.data);
  }
  constexpr bool valid() const { return part < Record::kParts; }
};

using SensorLogPart = LogPart<SensorLogRecord>;
using TelemetryLogPart = LogPart<TelemetryLogRecord>;

// Part `part` of a line, ready to encode(). The QR sends parts 0..kParts-1 of each line in turn.
// A part number past the end gives a part with no data, which every receiver refuses.
template <LogRecord Record>
constexpr LogPart<Record> make_log_part(const Record& record, uint8_t part) {
  LogPart<Record> out;
  out.line = record.line;
  out.part = part;
  if (part >= Record::kParts) return out;
  uint8_t flat[size_t{Record::kParts} * kLogPartDataBytes] = {};
  write_fields(record, flat, sizeof flat);
  const size_t from = static_cast<size_t>(part) * kLogPartDataBytes;
  for (size_t i = 0; i < kLogPartDataBytes; ++i) out.data[i] = flat[from + i];
  return out;
}

// Collects the parts of one line at a time. Parts of a line may come in any order and more than
// once; a part of another line abandons the line being collected (it is counted, and the PC asks
// for it again).
template <LogRecord Record>
class LogLineAssembler {
 public:
  enum class Result : uint8_t { incomplete, complete, rejected };

  // Adds a decoded part; on `complete` the whole line is in `out`. `rejected` means the parts
  // were all there but did not form a valid record (a field out of range).
  constexpr Result add(const LogPart<Record>& part, Record& out) {
    if (part.part >= Record::kParts) return Result::rejected;
    if (!collecting_ || part.line != line_) {
      if (collecting_) ++abandoned_lines_;
      collecting_ = true;
      line_ = part.line;
      received_ = 0;
    }
    for (size_t i = 0; i < kLogPartDataBytes; ++i) flat_[size_t{part.part} * kLogPartDataBytes + i] = part.data[i];
    received_ = static_cast<uint8_t>(received_ | (1u << part.part));
    if (received_ != kAllParts) return Result::incomplete;

    collecting_ = false;
    Record record;
    if (!read_fields(flat_, sizeof flat_, record)) return Result::rejected;
    record.line = line_;
    out = record;
    return Result::complete;
  }

  // Lines given up because a part of another line came before they were complete.
  constexpr uint32_t abandoned_lines() const { return abandoned_lines_; }

 private:
  static_assert(Record::kParts <= 8, "the received-parts mask is one byte");
  static constexpr uint8_t kAllParts = static_cast<uint8_t>((1u << Record::kParts) - 1u);

  uint8_t flat_[size_t{Record::kParts} * kLogPartDataBytes] = {};
  uint16_t line_ = 0;
  uint8_t received_ = 0;
  bool collecting_ = false;
  uint32_t abandoned_lines_ = 0;
};

}  // namespace wire
