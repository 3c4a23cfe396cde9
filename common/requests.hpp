// PC -> QR messages. Control is periodic and never acknowledged (the next one is worth more than
// a resend); the rest are requests, acknowledged by type and sequence number. Every request's
// first field is `seq`, stamped by the resend queue when the request is submitted.
#pragma once

#include <stdint.h>

#include <common/message_table.hpp>
#include <common/mode.hpp>
#include <common/units.hpp>

namespace wire {

// The pilot's sticks, 50 times a second. Also the heartbeat: the QR declares the link lost when
// no valid frame arrives for the link timeout.
struct Control {
  static constexpr MessageType kType = MessageType::control;
  uint16_t lift = 0;  // 0..1000
  int16_t roll = 0;   // -1000..1000, positive: right side down
  int16_t pitch = 0;  // -1000..1000, positive: nose up
  int16_t yaw = 0;    // -1000..1000, positive: nose right

  constexpr bool operator==(const Control&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.lift);
    v(m.roll);
    v(m.pitch);
    v(m.yaw);
  }
  static constexpr bool stick_ok(int16_t s) { return s >= -kStickMax && s <= kStickMax; }
  constexpr bool valid() const { return lift <= kLiftMax && stick_ok(roll) && stick_ok(pitch) && stick_ok(yaw); }
};

struct ModeChange {
  static constexpr MessageType kType = MessageType::mode_change;
  uint8_t seq = 0;
  Mode mode = Mode::safe;

  constexpr bool operator==(const ModeChange&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.seq);
    v(m.mode);
  }
  // Every mode byte decodes: a number with no mode (6..255) is a well-formed request the QR's
  // safety machine refuses with nack unknown_mode (bad_value would call the frame malformed).
  constexpr bool valid() const { return true; }
};

// Sets one parameter of the shared table (parameter_table.hpp) to a raw value in its Q format.
struct ParamSet {
  static constexpr MessageType kType = MessageType::param_set;
  uint8_t seq = 0;
  uint8_t id = 0;
  int32_t value = 0;

  constexpr bool operator==(const ParamSet&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.seq);
    v(m.id);
    v(m.value);
  }
  constexpr bool valid() const { return true; }  // id and range are the table's business: nack
};

inline constexpr uint8_t kAllParameters = 0xFF;

// Asks for param_report(s): one parameter, or every one when id is kAllParameters.
struct ParamGet {
  static constexpr MessageType kType = MessageType::param_get;
  uint8_t seq = 0;
  uint8_t id = kAllParameters;

  constexpr bool operator==(const ParamGet&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.seq);
    v(m.id);
  }
  constexpr bool valid() const { return true; }
};

enum class LogKind : uint8_t { sensor = 0, telemetry = 1 };

inline constexpr uint8_t kLogSensor = 0x01;     // LogStart::logs bit
inline constexpr uint8_t kLogTelemetry = 0x02;  // LogStart::logs bit

struct LogStart {
  static constexpr MessageType kType = MessageType::log_start;
  uint8_t seq = 0;
  uint8_t logs = kLogSensor | kLogTelemetry;

  constexpr bool operator==(const LogStart&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.seq);
    v(m.logs);
  }
  constexpr bool valid() const { return logs != 0 && (logs & ~(kLogSensor | kLogTelemetry)) == 0; }
};

struct LogStop {
  static constexpr MessageType kType = MessageType::log_stop;
  uint8_t seq = 0;

  constexpr bool operator==(const LogStop&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.seq);
  }
  constexpr bool valid() const { return true; }
};

// Asks the QR to send lines [first_line, first_line + count) of one log; count 0 means "to the
// end". Lines lost on the way are asked for again with a narrower range.
struct LogDownload {
  static constexpr MessageType kType = MessageType::log_download;
  uint8_t seq = 0;
  LogKind log = LogKind::sensor;
  uint16_t first_line = 0;
  uint16_t count = 0;

  constexpr bool operator==(const LogDownload&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.seq);
    v(m.log);
    v(m.first_line);
    v(m.count);
  }
  constexpr bool valid() const { return log == LogKind::sensor || log == LogKind::telemetry; }
};

// Asks the QR to send again the parts a download lost, while the download goes on: bit k of
// `parts` (byte k / 8, bit k % 8) is part k % P of line first_line + k / P, P the log's parts per
// line (5 sensor, 7 telemetry). The QR sends them before the next parts of the stream, so a lost
// part costs one part, not a line and not a wait for the stream's end (docs/protocol.md section 8).
inline constexpr size_t kLogResendMaskBytes = 5;

struct LogResend {
  static constexpr MessageType kType = MessageType::log_resend;
  uint8_t seq = 0;
  LogKind log = LogKind::sensor;
  uint16_t first_line = 0;
  uint8_t parts[kLogResendMaskBytes] = {};

  constexpr bool operator==(const LogResend&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.seq);
    v(m.log);
    v(m.first_line);
    v(m.parts);
  }
  constexpr bool valid() const { return log == LogKind::sensor || log == LogKind::telemetry; }
  constexpr bool wants(size_t bit) const { return (parts[bit / 8] >> (bit % 8) & 1u) != 0; }
  constexpr void want(size_t bit) { parts[bit / 8] = static_cast<uint8_t>(parts[bit / 8] | (1u << (bit % 8))); }
};

// The motor test (docs/safety.md rule 22): one engine (0 front, 1 right, 2 back, 3 left) at
// `level` engine units for 2 s, on the bench with the propellers off, so that an engine on the
// wrong output or turning the wrong way is found there. The level is at most 20 % of full: enough
// to see a motor turn, too little to lift the vehicle with its propellers on.
inline constexpr uint16_t kMotorTestMaxLevel = 200;

struct MotorTest {
  static constexpr MessageType kType = MessageType::motor_test;
  uint8_t seq = 0;
  uint8_t engine = 0;
  uint16_t level = 0;

  constexpr bool operator==(const MotorTest&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.seq);
    v(m.engine);
    v(m.level);
  }
  constexpr bool valid() const { return engine < 4 && level <= kMotorTestMaxLevel; }
};

// A DShot ESC's spin direction, set and saved in the ESC (DShot "spin direction 1" or "2", then
// "save settings"): the bench's cure for a motor the motor test found turning the wrong way, on
// boards whose ESCs take DShot commands, in safe with every engine stopped (docs/safety.md rule 18).
struct EscDirection {
  static constexpr MessageType kType = MessageType::esc_direction;
  uint8_t seq = 0;
  uint8_t engine = 0;     // 0 front, 1 right, 2 back, 3 left
  uint8_t direction = 1;  // 1: spin direction 1 (the ESC's normal), 2: spin direction 2 (reversed)

  constexpr bool operator==(const EscDirection&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.seq);
    v(m.engine);
    v(m.direction);
  }
  constexpr bool valid() const { return engine < 4 && (direction == 1 || direction == 2); }
};

// The console is closing: the QR goes to safe (through panic if flying) and stops.
struct Exit {
  static constexpr MessageType kType = MessageType::exit;
  uint8_t seq = 0;

  constexpr bool operator==(const Exit&) const = default;

  template <class Self, class Visit>
  static constexpr void fields(Self& m, Visit& v) {
    v(m.seq);
  }
  constexpr bool valid() const { return true; }
};

}  // namespace wire
