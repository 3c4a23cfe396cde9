// The safety state machine: which mode the QR is in, which requests it refuses and why, what
// sends it to panic, and the last word on engine outputs. Rules are rows of tables, not ifs
// scattered through the flight code; each rule has a test named after it (tests/qr/safety_test).
#pragma once

#include <stdint.h>

#include <qr/core/board.hpp>
#include <common/mode.hpp>
#include <common/nack_reason.hpp>

namespace qr {

// Pilot's set-points as they come off the link: lift 0..1000, roll/pitch/yaw -1000..1000,
// centred at 0.
struct ControlInput {
  uint16_t lift = 0;
  int16_t roll = 0;
  int16_t pitch = 0;
  int16_t yaw = 0;

  bool neutral() const { return lift == 0 && roll == 0 && pitch == 0 && yaw == 0; }
};

using wire::Mode;
using wire::NackReason;  // the machine's refusals are the first reasons on the wire's list

constexpr uint8_t index(Mode m) { return static_cast<uint8_t>(m); }
inline constexpr uint8_t kModeCount = wire::kModeCount;

enum class PanicCause : uint8_t { none = 0, requested, link_lost, battery_low, tilt };

struct SafetyLimits {
  uint32_t link_timeout_us = 250000;
  uint16_t battery_panic_mv = 10500;
  uint16_t battery_warn_mv = 11100;
  uint32_t battery_trip_us = 100000;  // a dip shorter than this (a load spike) is not a panic
  int32_t tilt_limit_mrad = 785;      // 45 degrees
  uint16_t panic_level = 350;         // engines hold at most this while panicking
  uint32_t panic_hold_us = 2000000;
  uint32_t panic_ramp_us = 1000000;
  uint16_t idle = 180;                // no engine below this while lift > 0 in flight
};

// What the machine looks at, assembled once per tick.
struct Situation {
  uint32_t now_us = 0;
  ControlInput controls;
  EngineCommand engines;    // what the engines get now
  bool calibrated = false;
  uint16_t battery_mv = 0;
  uint32_t last_frame_us = 0;
  int32_t tilt_mrad = 0;    // max(|roll|, |pitch|) from the attitude estimator
};

class SafetyMachine {
 public:
  explicit SafetyMachine(const SafetyLimits& limits) : limits_(limits) {}

  Mode mode() const { return mode_; }
  bool stopped() const { return stopped_; }
  PanicCause panic_cause() const { return panic_cause_; }
  bool battery_warning() const { return battery_warning_; }
  SafetyLimits& limits() { return limits_; }
  const SafetyLimits& limits() const { return limits_; }

  // A pilot's mode request. Safe and panic are always obeyed (a flight mode reaches safe
  // through panic); anything else is checked against the guard table.
  NackReason request(uint8_t mode, const Situation& s);
  // Exit: to safe (through panic if flying), then stopped.
  void request_exit(const Situation& s);
  void calibration_finished();

  // Every tick: watchdogs (link, battery, tilt), the panic timeline and a pending exit.
  void supervise(const Situation& s);

  // The last word on engine values: zero unless flying or panicking, the panic profile in
  // panic, and while flying with lift an idle floor so no engine stalls.
  EngineCommand limit_engines(const EngineCommand& wanted, const Situation& s) const;

 private:
  void enter_panic(PanicCause cause, const Situation& s);

  SafetyLimits limits_;
  Mode mode_ = Mode::safe;
  bool exit_pending_ = false;
  bool stopped_ = false;
  bool battery_warning_ = false;
  bool battery_low_ = false;
  uint32_t battery_low_since_us_ = 0;
  PanicCause panic_cause_ = PanicCause::none;
  uint32_t panic_start_us_ = 0;
  EngineCommand panic_from_;
};

}  // namespace qr
