// Every tunable of the QR, in one table both ends share: id on the wire, name, fixed-point format,
// range and default. The wire carries the raw integer; the real value is raw / 2^frac_bits in the
// unit named. The QR range-checks every param_set against this table and refuses (nack bad_value)
// what is outside; the console uses the same table to show, step and save the values.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/nack_reason.hpp>

namespace wire {

// The rows, once: identifier, wire id, Q format (frac bits), min, max, default (raw), unit, meaning.
// The identifier is both the ParamId enumerator and the parameter's name (console, parameter files,
// qrsim --param, docs), so the two cannot disagree; a name ends in its unit where it has one (_ms, _hz, _mv,
// _mrad, _rad_s); gains and engine levels carry theirs in the unit column.
// Gains are in the units their controllers use: "engine units" are the 0..1000 engine scale;
// "thrust units" are the mixer's per-engine thrust, 1000 = one engine at full speed
// (qr/core/chain/engine_mixer.hpp), in which the controllers' moments are expressed.
// The attitude estimator is a complementary filter (qr/core/chain/attitude_estimator.hpp): each
// sample the angle moves 1/C1 of its error toward the accelerometer angle, and the gyro bias
// moves by the error x fs / C2; sqrt(C2) / (2 C1) is the damping, so C2 = 4 C1^2 is critical.
// docs/parameters.md is generated from these rows (qrparams --markdown).
#define WIRE_PARAMETER_ROWS(ROW) \
  ROW(yaw_p, 1, 4, 0, 16000, 4800, "thrust units per rad/s", "yaw rate controller gain") \
  ROW(roll_pitch_p1, 2, 8, 0, 5120, 1408, "1/s", "roll/pitch angle loop: rate set-point per rad of angle error") \
  ROW(roll_pitch_p2, 3, 4, 0, 16000, 3520, "thrust units per rad/s", "roll/pitch rate loop gain") \
  ROW(attitude_c1, 4, 0, 1, 65535, 8000, "samples", \
      "attitude estimator (complementary filter): accelerometer angle correction divisor; the angle follows " \
      "the accelerometer with a time constant of C1 samples") \
  ROW(attitude_c2, 5, 0, 1, 1073741824, 256000000, "samples^2", \
      "attitude estimator (complementary filter): gyro bias correction divisor; bias += angle error x fs / C2, " \
      "C2 = 4 C1^2 is critically damped") \
  ROW(filter_cutoff_hz, 6, 0, 1, 250, 20, "Hz", "sensor low-pass cut-off") \
  ROW(telemetry_rate_hz, 7, 0, 1, 100, 50, "Hz", "fast telemetry group rate") \
  ROW(link_timeout_ms, 8, 0, 50, 2000, 250, "ms", "no valid frame for this long in flight: panic") \
  ROW(battery_warning_mv, 9, 0, 9000, 12600, 11100, "mV", "below this: warning") \
  ROW(battery_panic_mv, 10, 0, 9000, 12600, 10500, "mV", "below this in flight: panic") \
  ROW(tilt_limit_mrad, 11, 0, 87, 1396, 785, "mrad", "tilt beyond this in yaw/full control: panic (785 = 45 deg)") \
  ROW(max_yaw_rate_rad_s, 12, 10, 0, 8192, 2048, "rad/s", "yaw rate set-point at full stick") \
  ROW(panic_level, 13, 0, 0, 100, 90, "% of the flying lift", \
      "a panic that cannot land (manual, no calibration, tilt): the engines hold at this share of the lift " \
      "that was flying (the mean engine command of the last quarter second) before ramping down") \
  ROW(panic_hold_ms, 14, 0, 0, 10000, 2000, "ms", "panic: time at the panic level before ramping down") \
  ROW(panic_ramp_ms, 15, 0, 0, 10000, 1000, "ms", "panic: ramp from panic level to zero") \
  ROW(idle_level, 16, 0, 0, 500, 180, "engine units", "lowest engine value while lift > 0 in flight") \
  ROW(log_divider, 17, 0, 1, 1000, 10, "control periods", "write a log line every this many periods") \
  ROW(roll_pitch_i, 18, 4, 0, 16000, 1280, "thrust units per rad", "roll/pitch rate loop integral gain") \
  ROW(roll_pitch_d, 19, 8, 0, 5120, 2048, "thrust units per rad/s^2", \
      "roll/pitch rate loop derivative gain (on the measured rate)") \
  ROW(tilt_time_ms, 20, 0, 0, 2000, 500, "ms", \
      "tilt beyond tilt_limit_mrad for this long in yaw/full control: panic (an upset that recovers sooner " \
      "flies on)") \
  ROW(yaw_i, 21, 4, 0, 16000, 4800, "thrust units per rad", \
      "yaw rate loop integral gain: holds the yaw rate at its set-point against the rotors' drag") \
  ROW(max_tilt_mrad, 22, 0, 87, 698, 524, "mrad", "roll/pitch angle set-point at full stick (524 = 30 deg)") \
  ROW(battery_sag_mv, 23, 0, 0, 3000, 1100, "mV", \
      "the battery's sag with all four engines at full command (internal resistance x that current); the " \
      "battery rules judge the voltage plus this x the engines' load, sum of (e/1000)^3 / 4: an estimate of the " \
      "resting voltage; 0: the voltage as measured") \
  ROW(accel_lag_ms, 24, 0, 0, 30000, 2750, "ms", \
      "attitude estimator: time constant with which the accelerometer's angle follows a change of tilt in " \
      "free flight (the rotors' drag: mass / (drag coefficient x sum of rotor speeds)); 0: at once, the plain " \
      "complementary filter") \
  ROW(takeoff_mg, 25, 0, 1000, 4000, 1100, "mg", \
      "landed detector: from lift 0 the vehicle counts as on the ground (attitude and yaw integrals held empty) " \
      "until the accelerometer reads more than this along the thrust for 50 ms (the vehicle climbing off)") \
  ROW(drag_moment, 26, 0, 0, 1000, 150, "thrust units per rad", \
      "roll/pitch feed-forward against the rotors' drag moment (drag at the hubs, above the centre of mass, " \
      "tilts a moving vehicle back): moment per rad of the accelerometer angle the estimator's drag model " \
      "expects; mass x g x hub height in thrust units; 0: none") \
  ROW(panic_descent_mm_s, 27, 0, 100, 2000, 500, "mm/s", \
      "a panic that lands (yaw, full control or height hold, calibrated): descends level at this vertical " \
      "speed on the height estimate until it touches down; a landing that has not touched down in twice " \
      "the time the height estimate asks for (plus 2 m) becomes the hold-and-ramp") \
  ROW(pilot, 28, 0, 0, 1, 0, "0 PC link, 1 radio", \
      "who flies: the PC link's control frames or the radio receiver's (CRSF) channels; changed in safe only " \
      "(nack not_from_this_mode elsewhere; the value in force is accepted anywhere). With the radio, its arm " \
      "switch arms (docs/safety.md rule 17) and the PC keeps telemetry, logs, parameters and the abort key") \
  ROW(rc_roll_channel, 29, 0, 1, 16, 1, "channel", "radio: the channel of the roll stick (1..16, as radios count)") \
  ROW(rc_pitch_channel, 30, 0, 1, 16, 2, "channel", "radio: the channel of the pitch stick") \
  ROW(rc_lift_channel, 31, 0, 1, 16, 3, "channel", "radio: the channel of the lift (throttle) stick") \
  ROW(rc_yaw_channel, 32, 0, 1, 16, 4, "channel", "radio: the channel of the yaw stick") \
  ROW(rc_arm_channel, 33, 0, 1, 16, 5, "channel", \
      "radio: the channel of the arm switch (high: on; moved to on in safe with the lift low and the sticks " \
      "neutral arms, moved to off in flight is an emergency stop)") \
  ROW(rc_mode_channel, 34, 0, 1, 16, 6, "channel", \
      "radio: the channel of the mode switch, read when arming: low manual, centre yaw control, high full " \
      "control") \
  ROW(motor_poles, 35, 0, 2, 36, 14, "magnet poles", \
      "the engines' motors: RPM = the ESC's eRPM (bidirectional DShot) / (poles / 2)") \
  ROW(gyro_scale_x_ppm, 36, 0, -100000, 100000, 0, "ppm", \
      "the gyro's x axis reads this many parts per million more than its nominal 65.5 LSB per deg/s " \
      "(10000: 1 % high; the MPU-6050 allows +-3 %); the firmware divides it out. A calibration with " \
      "gyro_turns measures it") \
  ROW(gyro_scale_y_ppm, 37, 0, -100000, 100000, 0, "ppm", "the same for the gyro's y axis") \
  ROW(gyro_scale_z_ppm, 38, 0, -100000, 100000, 0, "ppm", "the same for the gyro's z axis") \
  ROW(gyro_turns, 39, 0, 0, 10, 0, "turns", \
      "the next calibration, after its half second at rest, waits while the vehicle is turned this many " \
      "whole turns about one body axis and set down still, and sets that axis' gyro_scale_*_ppm from the " \
      "rate it summed (docs/signal-chain.md); back to 0 when it ends, found or not. 0: a calibration at rest") \
  ROW(imu_orientation, 40, 0, 0, 7, 0, "mounting", \
      "how the IMU's board sits in the frame: 0 as drawn; 1, 2, 3 turned 90, 180, 270 deg clockwise seen from " \
      "above; 4..7 the same, then upside down (common/drivers/imu_mounting.hpp); the orientation check finds it; " \
      "changed in safe only, then calibrate again")

enum class ParamId : uint8_t {
#define WIRE_PARAMETER_ENUMERATOR(name, id, frac_bits, min, max, default_value, unit, meaning) name = id,
  WIRE_PARAMETER_ROWS(WIRE_PARAMETER_ENUMERATOR)
#undef WIRE_PARAMETER_ENUMERATOR
};

// The parameters the QR writes itself: a calibration with gyro_turns measures a gyro scale and
// ends the turns (qr/core/chain/gyro_turns.hpp). The console takes what the QR reports of these
// as its own value, so a measurement is saved with the others and sent back at the next connect,
// and the turns are not asked for again.
constexpr bool written_by_qr(ParamId id) {
  return id == ParamId::gyro_scale_x_ppm || id == ParamId::gyro_scale_y_ppm || id == ParamId::gyro_scale_z_ppm ||
         id == ParamId::gyro_turns;
}

struct ParameterSpec {
  ParamId id;
  const char* name;       // the enumerator's identifier, spelled the same
  uint8_t frac_bits;      // Q format: value = raw / 2^frac_bits
  int32_t min;            // raw, inclusive
  int32_t max;            // raw, inclusive
  int32_t default_value;  // raw
  const char* unit;
  const char* meaning;
};

inline constexpr ParameterSpec kParameterTable[] = {
#define WIRE_PARAMETER_SPEC(name, id, frac_bits, min, max, default_value, unit, meaning) \
  {ParamId::name, #name, frac_bits, min, max, default_value, unit, meaning},
    WIRE_PARAMETER_ROWS(WIRE_PARAMETER_SPEC)
#undef WIRE_PARAMETER_SPEC
};

inline constexpr size_t kParameterCount = sizeof(kParameterTable) / sizeof(kParameterTable[0]);

// The numbers of each row without its texts: what the QR reads at run time (range checks,
// defaults, reports). Its image has no room for names, units and meanings it never sends, and the
// linker keeps only the arrays code reads.
struct ParameterLimits {
  ParamId id;
  int32_t min;            // raw, inclusive
  int32_t max;            // raw, inclusive
  int32_t default_value;  // raw
};

inline constexpr ParameterLimits kParameterLimits[] = {
#define WIRE_PARAMETER_LIMITS(name, id, frac_bits, min, max, default_value, unit, meaning) \
  {ParamId::name, min, max, default_value},
    WIRE_PARAMETER_ROWS(WIRE_PARAMETER_LIMITS)
#undef WIRE_PARAMETER_LIMITS
};
static_assert(sizeof(kParameterLimits) / sizeof(kParameterLimits[0]) == kParameterCount);

// Ids run 1..kParameterCount in row order (find_parameter finds a row by subtraction).
constexpr bool ids_follow_rows() {
  for (size_t row = 0; row < kParameterCount; ++row) {
    if (static_cast<size_t>(kParameterTable[row].id) != row + 1) return false;
  }
  return true;
}
static_assert(ids_follow_rows(), "parameter ids must run 1, 2, 3, ... in table order");

// The row for a wire id, or nullptr.
const ParameterSpec* find_parameter(uint8_t id);

constexpr bool in_range(const ParameterSpec& spec, int32_t raw) { return raw >= spec.min && raw <= spec.max; }
constexpr bool in_range(const ParameterLimits& limits, int32_t raw) { return raw >= limits.min && raw <= limits.max; }

// Current values of every parameter, starting at the defaults. The QR owns the real one; the
// console keeps a copy updated from param_report.
class ParameterValues {
 public:
  ParameterValues();

  int32_t get(ParamId id) const;

  // Sets a value if the id exists and the value is in range; otherwise changes nothing and says why.
  NackReason set(uint8_t id, int32_t raw);

 private:
  int32_t values_[kParameterCount];
};

}  // namespace wire
