// QR -> PC telemetry, in small groups rather than one big record: every frame must stay within 9
// payload bytes for the check byte to catch every 2-bit error (crc8.hpp), and small groups let the
// QR send what changes fast (attitude, rates) more often than what changes slowly. docs/protocol.md
// gives the recommended schedule and its share of the link.
#pragma once

#include <stdint.h>

#include <common/message_table.hpp>
#include <common/mode.hpp>
#include <common/units.hpp>

namespace wire {

// TelemetryAttitude::flags bits
inline constexpr uint8_t kFlagCalibrated = 0x01;
inline constexpr uint8_t kFlagLogging = 0x02;
inline constexpr uint8_t kFlagBatteryWarning = 0x04;
inline constexpr uint8_t kFlagLogFull = 0x08;
// The QR believes it is flying (its landed detector, docs/signal-chain.md), not resting on the ground.
inline constexpr uint8_t kFlagFlying = 0x10;

struct TelemetryAttitude {
  static constexpr MessageType kType = MessageType::telemetry_attitude;
  uint8_t tick = 0;  // +1 per attitude frame sent (wraps), so the PC can count lost telemetry
  Mode mode = Mode::safe;
  uint8_t flags = 0;  // kFlag* bits; other bits are 0 today and ignored by readers
  int16_t phi = 0;    // roll angle, 1e-4 rad
  int16_t theta = 0;  // pitch angle, 1e-4 rad
  int16_t psi = 0;    // yaw angle, 1e-4 rad

  constexpr bool operator==(const TelemetryAttitude&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.tick);
    v(m.mode);
    v(m.flags);
    v(m.phi);
    v(m.theta);
    v(m.psi);
  }
  constexpr bool valid() const { return valid_mode(mode); }
};

struct TelemetryRates {
  static constexpr MessageType kType = MessageType::telemetry_rates;
  int16_t p = 0;  // roll rate, 1e-3 rad/s, saturated
  int16_t q = 0;  // pitch rate, 1e-3 rad/s, saturated
  int16_t r = 0;  // yaw rate, 1e-3 rad/s, saturated

  constexpr bool operator==(const TelemetryRates&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.p);
    v(m.q);
    v(m.r);
  }
  constexpr bool valid() const { return true; }
};

constexpr bool engines_ok(const uint16_t (&engine)[4]) {
  for (uint16_t e : engine) {
    if (e > kEngineMax) return false;
  }
  return true;
}

struct TelemetryEngines {
  static constexpr MessageType kType = MessageType::telemetry_engines;
  uint16_t engine[4] = {0, 0, 0, 0};  // 0..1000; 0 front, 1 right, 2 back, 3 left

  constexpr bool operator==(const TelemetryEngines&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.engine);
  }
  constexpr bool valid() const { return engines_ok(engine); }
};

// What the controllers are steering to, after stick scaling and trim.
struct TelemetrySetpoints {
  static constexpr MessageType kType = MessageType::telemetry_setpoints;
  uint16_t lift = 0;     // 0..1000
  int16_t roll = 0;      // roll angle set-point, 1e-4 rad
  int16_t pitch = 0;     // pitch angle set-point, 1e-4 rad
  int16_t yaw_rate = 0;  // yaw rate set-point, 1e-3 rad/s

  constexpr bool operator==(const TelemetrySetpoints&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.lift);
    v(m.roll);
    v(m.pitch);
    v(m.yaw_rate);
  }
  constexpr bool valid() const { return lift <= kLiftMax; }
};

struct TelemetrySystem {
  static constexpr MessageType kType = MessageType::telemetry_system;
  uint16_t battery_mv = 0;
  uint16_t cpu_load = 0;         // share of the control period spent in tasks, per mille (0..1000)
  uint16_t loop_time_us = 0;     // longest task-set time since the last report, saturated
  uint16_t deadline_misses = 0;  // since start, wraps

  constexpr bool operator==(const TelemetrySystem&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.battery_mv);
    v(m.cpu_load);
    v(m.loop_time_us);
    v(m.deadline_misses);
  }
  constexpr bool valid() const { return cpu_load <= kPermilleMax; }
};

// The QR's receive counters (FrameParser::counters), each modulo 2^16, and its serial receiver's
// overruns (bytes the board had no room for, lost before the parser saw them), saturated at 255
// so that once bytes were lost it never reads 0 again (a payload holds 9 bytes at most): the PC
// compares them with what it sent to show the uplink's health.
struct TelemetryLink {
  static constexpr MessageType kType = MessageType::telemetry_link;
  uint16_t frames_ok = 0;
  uint16_t check_failures = 0;
  uint16_t unknown_types = 0;
  uint16_t bytes_skipped = 0;
  uint8_t rx_overruns = 0;

  constexpr bool operator==(const TelemetryLink&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.frames_ok);
    v(m.check_failures);
    v(m.unknown_types);
    v(m.bytes_skipped);
    v(m.rx_overruns);
  }
  constexpr bool valid() const { return true; }
};

// One scheduler task's cost so far, in the board's cycle counter (instructions on the devboard),
// and how many of its runs went over its budget (the task table's), each saturated at 65535.
// The scheduler also keeps the minimum; the wire leaves it out (it never says what to fix). The QR cycles through its tasks, one per telemetry period; the console
// keeps the table and prints it on request.
struct TelemetryTask {
  static constexpr MessageType kType = MessageType::telemetry_task;
  uint8_t task = 0;  // the QR's task number (common/task_names.hpp)
  uint16_t mean = 0;
  uint16_t max = 0;
  uint16_t overruns = 0;

  constexpr bool operator==(const TelemetryTask&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.task);
    v(m.mean);
    v(m.max);
    v(m.overruns);
  }
  constexpr bool valid() const { return mean <= max; }
};

// TelemetryHeight::flags bits
inline constexpr uint8_t kHeightValid = 0x01;  // the estimate has its barometer reference

// The height estimate (the barometer and the accelerometer fused), up, from the height at the
// last calibration: what height hold holds and a landing descends on; and the hover lift the QR
// has learnt in flight.
struct TelemetryHeight {
  static constexpr MessageType kType = MessageType::telemetry_height;
  int32_t height_mm = 0;    // mm, up
  int16_t climb_mm_s = 0;   // vertical speed, mm/s, up, saturated
  uint8_t flags = 0;        // kHeightValid; without it the two figures are 0 and mean nothing
  uint16_t hover_lift = 0;  // the lift that carries the vehicle, 0..1000 (0: no flight has taught it yet)

  constexpr bool operator==(const TelemetryHeight&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.height_mm);
    v(m.climb_mm_s);
    v(m.flags);
    v(m.hover_lift);
  }
  constexpr bool valid() const { return (flags & ~kHeightValid) == 0 && hover_lift <= kLiftMax; }
};

// TelemetryRadio::flags bits
inline constexpr uint8_t kRadioPilot = 0x01;      // the radio flies (parameter pilot)
inline constexpr uint8_t kRadioLinkUp = 0x02;     // a valid RC frame within the link timeout
inline constexpr uint8_t kRadioArmSwitch = 0x04;  // the arm switch is on (in the last RC frame)
inline constexpr uint8_t kRadioFlags = kRadioPilot | kRadioLinkUp | kRadioArmSwitch;

// The radio receiver's link as its CRSF link statistics say (common/drivers/crsf.hpp), and who
// flies. A telemetry turn of its own once a radio has been heard or while it is the pilot.
struct TelemetryRadio {
  static constexpr MessageType kType = MessageType::telemetry_radio;
  uint8_t flags = 0;          // kRadio* bits
  uint8_t uplink_rssi = 0;    // -dBm, the active antenna's
  uint8_t uplink_lq = 0;      // link quality, %
  int8_t uplink_snr = 0;      // dB
  uint8_t rf_mode = 0;        // the receiver's packet rate index
  uint8_t tx_power = 0;       // the transmitter's power index (crsf.hpp)
  uint8_t downlink_rssi = 0;  // -dBm
  uint8_t downlink_lq = 0;    // %
  int8_t downlink_snr = 0;    // dB

  constexpr bool operator==(const TelemetryRadio&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.flags);
    v(m.uplink_rssi);
    v(m.uplink_lq);
    v(m.uplink_snr);
    v(m.rf_mode);
    v(m.tx_power);
    v(m.downlink_rssi);
    v(m.downlink_lq);
    v(m.downlink_snr);
  }
  constexpr bool valid() const { return (flags & ~kRadioFlags) == 0 && uplink_lq <= 100 && downlink_lq <= 100; }
};

// The engines' speeds as bidirectional DShot ESCs report them (common/drivers/erpm.hpp), RPM,
// saturated; a telemetry turn of its own when the board reads them.
struct TelemetryRpm {
  static constexpr MessageType kType = MessageType::telemetry_rpm;
  uint16_t rpm[4] = {0, 0, 0, 0};  // 0 front, 1 right, 2 back, 3 left

  constexpr bool operator==(const TelemetryRpm&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.rpm);
  }
  constexpr bool valid() const { return true; }
};

}  // namespace wire
