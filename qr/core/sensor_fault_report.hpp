// The sensors' faults told to the console as debug text: which sensor, the kind of its last fault
// and how many it has counted, e.g. "imu fault: address NACK (12 since power-up)". The drivers
// count every bad answer (common/drivers/mpu6050.hpp, ms5611.hpp); the flight reads only their
// verdict (board.hpp SensorHealth, docs/safety.md rule 20), so without this line a pilot would see
// a refusal or a panic and not why.
//
// Rate-limited: a line per sensor at most once per kSensorReportPeriodUs, and only when its count
// has grown since the last line. A NACK burst of 50 ms counts 50 faults and makes one line; a bus
// stuck for ever makes one a second, 40-odd bytes of the line's 1 150 a second.
//
// Start-up's faults are start-up's: the MPU answers nothing for its first 100 ms, so its driver
// counts an address NACK on every boot before it streams. The faults a sensor counted before it
// first became healthy are not reported if it becomes healthy within kSensorStartupGraceUs of the
// first tick; one that is not healthy by then (a wrong identity, a PROM that fails its CRC) has
// them reported, since they are why.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/drivers/mpu6050.hpp>
#include <common/drivers/ms5611.hpp>
#include <qr/core/board.hpp>

namespace qr {

inline constexpr uint32_t kSensorReportPeriodUs = 1000000;
// The MPU streams from about 0.28 s (its 100 ms start-up, reset wait, 30 ms of settling and 41 ms
// of self-test); the MS5611 measures from a few ms. A second is both with room.
inline constexpr uint32_t kSensorStartupGraceUs = 1000000;

// One sensor's side of the report, as a row: its name and its fault kinds' names.
struct SensorReportRow {
  const char* prefix;  // "imu fault: "
  const char* const* kind_names;
  uint8_t kinds;
};

inline constexpr SensorReportRow kSensorReportRows[] = {
    {"imu fault: ", drivers::kMpu6050FaultNames, static_cast<uint8_t>(drivers::kMpu6050FaultKinds)},
    {"barometer fault: ", drivers::kMs5611FaultNames, static_cast<uint8_t>(drivers::Ms5611Fault::count_)},
};
inline constexpr uint8_t kReportedSensors = sizeof(kSensorReportRows) / sizeof(kSensorReportRows[0]);
static_assert(kReportedSensors == 2, "a row per sensor of SensorHealth");

// A line is at most the prefix, a kind's name, " (", 10 digits, " since power-up)\n".
inline constexpr size_t kSensorReportChars = 80;

class SensorFaultReport {
 public:
  // Once a tick with the sample's health; true when a line is due, written into `line` (with its
  // newline, NUL-terminated). At most one line a call: the other sensor's waits a tick.
  bool due(const SensorHealth& h, uint32_t now_us, char (&line)[kSensorReportChars]) {
    if (!started_) {
      started_ = true;
      start_us_ = now_us;
    }
    const bool in_grace = now_us - start_us_ < kSensorStartupGraceUs;
    const bool healthy[kReportedSensors] = {h.imu, h.barometer};
    const uint32_t counts[kReportedSensors] = {h.imu_faults, h.barometer_faults};
    const uint8_t kinds[kReportedSensors] = {h.imu_fault, h.barometer_fault};
    for (uint8_t i = 0; i < kReportedSensors; ++i) {
      Sensor& s = sensors_[i];
      if (healthy[i] && !s.was_healthy) {
        s.was_healthy = true;
        if (in_grace) s.reported = counts[i];  // start-up's faults, over in time
      }
      if (in_grace && !s.was_healthy) continue;  // still starting: wait for its verdict
      if (counts[i] == s.reported) continue;
      if (s.said && now_us - s.said_at_us < kSensorReportPeriodUs) continue;
      s.reported = counts[i];
      s.said = true;
      s.said_at_us = now_us;
      compose(kSensorReportRows[i], kinds[i], counts[i], line);
      return true;
    }
    return false;
  }

 private:
  struct Sensor {
    bool was_healthy = false;
    bool said = false;
    uint32_t said_at_us = 0;
    uint32_t reported = 0;  // the count the last line told (or start-up's)
  };

  static void compose(const SensorReportRow& row, uint8_t kind, uint32_t count, char (&line)[kSensorReportChars]) {
    size_t n = 0;
    const auto put = [&line, &n](const char* text) {
      while (*text != '\0' && n + 1 < kSensorReportChars) line[n++] = *text++;
    };
    put(row.prefix);
    put(kind < row.kinds ? row.kind_names[kind] : "unknown");
    put(" (");
    char digits[11];
    size_t d = 0;
    do {
      digits[d++] = static_cast<char>('0' + count % 10u);
      count /= 10u;
    } while (count > 0 && d < sizeof digits);
    while (d > 0 && n + 1 < kSensorReportChars) line[n++] = digits[--d];
    put(" since power-up)\n");
    line[n] = '\0';
  }

  bool started_ = false;
  uint32_t start_us_ = 0;
  Sensor sensors_[kReportedSensors];
};

}  // namespace qr
