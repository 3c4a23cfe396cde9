// The safety state machine: which mode the QR is in, which requests it refuses and why, what
// sends it to panic, and the last word on engine outputs. Rules are rows of tables, not ifs
// scattered through the flight code; each rule has a test named after it (tests/qr/safety_test.cpp).
#pragma once

#include <stdint.h>

#include <common/parameter_table.hpp>
#include <common/requests.hpp>
#include <qr/core/board.hpp>
#include <qr/core/flight_types.hpp>

namespace qr {

enum class PanicCause : uint8_t {
  none = 0,
  requested,
  link_lost,
  battery_low,
  tilt,
  disarmed,
  imu_lost,
  wrong_sign,
  count
};

// As the debug text says them ("mode: panic (link lost)").
inline constexpr const char* kPanicCauseNames[] = {"",     "requested",      "link lost", "battery low",
                                                   "tilt", "arm switch off", "IMU lost",  "wrong sign"};
static_assert(sizeof(kPanicCauseNames) / sizeof(kPanicCauseNames[0]) == static_cast<uint8_t>(PanicCause::count),
              "one name per panic cause");

// The machine's thresholds: all but the battery trip time are parameters, so they come from the
// parameter table (safety_limits below), never from a second set of defaults here.
struct SafetyLimits {
  uint32_t link_timeout_us;
  uint16_t battery_panic_mv;
  uint16_t battery_warn_mv;
  int32_t tilt_limit_mrad;
  uint32_t tilt_time_us;    // beyond the tilt limit for this long: lost, not upset
  uint16_t panic_hold_pct;  // the cut: engines hold at this share of the lift that was flying
  uint32_t panic_hold_us;
  uint32_t panic_ramp_us;
  uint16_t descent_mm_s;                 // the landing: the descent rate (the chain flies it; the machine times it)
  uint16_t idle;                         // no engine below this while lift > 0 in flight
  uint16_t battery_sag_mv;               // the sag at all engines full (battery_sag_mv parameter)
  uint32_t battery_trip_us = 100000;     // the battery measure below the panic level this long: panic
  uint16_t battery_hysteresis_mv = 100;  // the warning ends only this far above its level
  uint32_t motor_test_us = 2000000;      // a motor test spins its engine this long (rule 22)
  int32_t autotune_tilt_mrad = 140;      // the autotune's excitation ends beyond 8 degrees of tilt (rule 23)
};

// The limits the parameters say (the defaults when `p` is default-constructed).
SafetyLimits safety_limits(const wire::ParameterValues& p);

// What the machine looks at, assembled once per tick.
struct Situation {
  uint32_t now_us = 0;
  ControlInput controls;
  EngineCommand engines;  // what the engines get now
  bool calibrated = false;
  uint16_t battery_mv = 0;
  uint32_t last_frame_us = 0;
  int32_t tilt_mrad = 0;        // max(|roll|, |pitch|) from the attitude estimator
  bool height_valid = false;    // the height estimate has its reference (a calibration with the barometer)
  int32_t height_mm = 0;        // the height estimate
  bool landed = false;          // the chain's landed detector: on the ground (in a landing: touched down)
  Pilot pilot = Pilot::pc;      // who flies; last_frame_us is the time of that link's last valid frame
  Pilot requester = Pilot::pc;  // who asks for the mode: the radio's arm switch or the PC link
  // The sensors' drivers' verdicts (board.hpp SensorHealth; boards without drivers: healthy).
  bool imu_healthy = true;
  bool barometer_healthy = true;
  // The sign check's verdict (chain/sign_check.hpp, rule 21): 0, or the axis (1 roll, 2 pitch,
  // 3 yaw) whose loop the vehicle answers the wrong way.
  uint8_t wrong_sign = 0;
  // The autotune's identification sequence has ended (chain/identification.hpp).
  bool identification_over = true;
};

class SafetyMachine {
 public:
  explicit SafetyMachine(const SafetyLimits& limits = safety_limits(wire::ParameterValues{})) : limits_(limits) {}

  Mode mode() const { return mode_; }
  bool stopped() const { return stopped_; }
  PanicCause panic_cause() const { return panic_cause_; }
  // This panic lands: the chain holds the vehicle level and descends at descent_mm_s until it
  // touches down (Situation::landed), then the engines stop. Otherwise it is the cut: the engines
  // hold at panic_hold_pct of the flying lift, ramp to zero, and the machine goes to safe.
  bool landing() const { return landing_; }
  // The lift that was flying, engine units: the mean engine command over about the last quarter
  // of a second outside panic (so a lift stick dropped just before a panic still counts).
  uint16_t flying_lift() const { return static_cast<uint16_t>(flying_q8_ >> 8); }
  bool battery_warning() const { return battery_warning_; }
  // What the battery rules judge, in mV: the resting voltage (the measured one plus the sag the
  // engines' load causes through the pack's internal resistance, battery_sag_mv) low-passed with a
  // time constant of about a second: a climb's sag is not an empty battery, and what sag the load
  // model misses passes in the mean when it lasts a few hundred ms.
  uint16_t battery_measure_mv() const { return static_cast<uint16_t>(battery_q8_ >> 8); }
  SafetyLimits& limits() { return limits_; }
  const SafetyLimits& limits() const { return limits_; }

  // A pilot's mode request. Safe and panic are always obeyed (a flight mode reaches safe
  // through panic); anything else is checked against the guard table.
  NackReason request(uint8_t mode, const Situation& s);
  // The motor test (rule 22): `engine` (0..3) alone at `level` (at most wire::kMotorTestMaxLevel)
  // for motor_test_us, entered from safe through the guards of leaving safe; the radio as the
  // pilot refuses it. It ends by itself in safe; a mode request or another motor test, the lift
  // above zero in a control frame, or the pilot's link silent for the link timeout end it at once.
  NackReason request_motor_test(uint8_t engine, uint16_t level, const Situation& s);
  // Exit: to safe (through panic if flying), then stopped.
  void request_exit(const Situation& s);
  void calibration_finished();

  // The modes entered since the last call, one bit per mode (1 << index(mode)), then cleared.
  // Every transition goes through one place that sets its bit; the owner's one door
  // (Flight::change_modes) gives the chain the mode's sources and runs its entry action.
  uint16_t take_entered() {
    const uint16_t entered = entered_;
    entered_ = 0;
    return entered;
  }

  // The pilot's sticks as each control frame brings them, before the chain uses them: any change
  // of the lift ends height hold at once, back to full control; any change of a stick or the lift
  // ends the autotune so (rule 23).
  // The lift above zero ends a motor test.
  void sticks_moved(const ControlInput& c);

  // The radio's switches as each valid RC frame brings them while the radio is the pilot (rule
  // 16): the arm switch moved to on in safe asks for `wanted` (the mode switch's mode) through the
  // guards every request passes (lift low, sticks neutral, ...); moved to off in a flight mode it
  // is an emergency stop. A switch already on at power-up, when the radio became the pilot or
  // when its link came back after the link timeout arms nothing: it must be seen off first, and
  // one movement to on is one attempt, refused or not. `s.requester` is the radio.
  NackReason radio_switches(bool arm, Mode wanted, const Situation& s);
  // The pilot parameter changed (in safe only): the new pilot's arm switch must be seen off first.
  void pilot_changed() { arm_seen_off_ = false; }
  bool arm_switch() const { return arm_on_; }

  // Every tick: watchdogs (link, battery, tilt), the panic timeline and a pending exit.
  void supervise(const Situation& s);

  // The last word on engine values: zero unless flying or panicking, the panic profile in
  // panic, and while flying with lift an idle floor so no engine stalls; in a motor test its
  // engine at its level, the others zero.
  EngineCommand limit_engines(const EngineCommand& wanted, const Situation& s) const;

 private:
  void enter(Mode to) {
    mode_ = to;
    entered_ = static_cast<uint16_t>(entered_ | (1u << index(to)));
  }
  void enter_panic(PanicCause cause, const Situation& s);
  NackReason refusal(Mode to, const Situation& s) const;

  SafetyLimits limits_;
  Mode mode_ = Mode::safe;
  // A bit per mode: a uint8_t dropped the motor test's (mode 8), whose door then never opened.
  uint16_t entered_ = 0;
  static_assert(kModeCount <= 16, "entered_: one bit per mode");
  bool exit_pending_ = false;
  bool stopped_ = false;
  bool battery_warning_ = false;
  bool battery_low_ = false;
  uint32_t battery_low_since_us_ = 0;
  uint32_t battery_q8_ = 0;  // the battery measure: the voltage's one-second mean, mV x 256 (0: none yet)
  bool tilted_ = false;
  uint32_t tilted_since_us_ = 0;
  PanicCause panic_cause_ = PanicCause::none;
  uint32_t panic_start_us_ = 0;
  bool landing_ = false;
  uint32_t descent_limit_us_ = 0;  // a landing not touched down by then becomes the cut
  uint16_t hold_level_ = 0;        // the cut's level, engine units
  uint32_t flying_q8_ = 0;         // flying_lift() x 256
  ControlInput held_;              // the sticks when height hold or the autotune was entered
  uint8_t test_engine_ = 0;        // the motor test's engine, its level and its start
  uint16_t test_level_ = 0;
  uint32_t test_start_us_ = 0;
  bool arm_seen_off_ = false;  // the radio's arm switch was off in a frame since it last armed
  bool arm_on_ = false;        // the arm switch in the last RC frame
  bool radio_heard_ = false;
  uint32_t radio_heard_us_ = 0;  // the last RC frame's time: a longer silence than the timeout is a loss
};

}  // namespace qr
