// Every tunable of the QR, in one table both ends share: id on the wire, name, fixed-point format,
// range and default. The wire carries the raw integer; the real value is raw / 2^frac_bits in the
// unit named. The QR range-checks every param_set against this table and refuses (nack bad_value)
// what is outside; the console uses the same table to show, step and save the values.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/nack_reason.hpp>

namespace wire {

enum class ParamId : uint8_t {
  yaw_p = 1,
  roll_pitch_p1 = 2,
  roll_pitch_p2 = 3,
  attitude_c1 = 4,
  attitude_c2 = 5,
  filter_cutoff_hz = 6,
  telemetry_rate_hz = 7,
  link_timeout_ms = 8,
  battery_warning_mv = 9,
  battery_panic_mv = 10,
  tilt_limit_mrad = 11,
  max_yaw_rate_rad_s = 12,
  panic_level = 13,
  panic_hold_ms = 14,
  panic_ramp_ms = 15,
  idle_level = 16,
  log_divider = 17,
  roll_pitch_i = 18,
  roll_pitch_d = 19,
};

struct ParameterSpec {
  ParamId id;
  const char* name;
  uint8_t frac_bits;  // Q format: value = raw / 2^frac_bits
  int32_t min;        // raw, inclusive
  int32_t max;        // raw, inclusive
  int32_t default_value;  // raw
  const char* unit;
  const char* meaning;
};

// Gains are in the units their controllers use: "engine units" are the 0..1000 engine scale;
// "thrust units" are the mixer's per-engine thrust, 1000 = one engine at full speed
// (qr/core/chain/engine_mixer.hpp), in which the controllers' moments are expressed.
inline constexpr ParameterSpec kParameterTable[] = {
    {ParamId::yaw_p, "yaw_p", 4, 0, 16000, 4800, "thrust units per rad/s", "yaw rate controller gain"},
    {ParamId::roll_pitch_p1, "p1", 8, 0, 5120, 1408, "1/s", "roll/pitch angle loop: rate set-point per rad of angle error"},
    {ParamId::roll_pitch_p2, "p2", 4, 0, 16000, 2560, "thrust units per rad/s", "roll/pitch rate loop gain"},
    {ParamId::attitude_c1, "c1", 0, 1, 65535, 8000, "samples", "attitude filter: angle correction divisor"},
    {ParamId::attitude_c2, "c2", 0, 1, 1073741824, 256000000, "samples", "attitude filter: gyro bias correction divisor"},
    {ParamId::filter_cutoff_hz, "filter_cutoff", 0, 1, 250, 20, "Hz", "sensor low-pass cut-off"},
    {ParamId::telemetry_rate_hz, "telemetry_rate", 0, 1, 100, 50, "Hz", "fast telemetry group rate"},
    {ParamId::link_timeout_ms, "link_timeout", 0, 50, 2000, 250, "ms", "no valid frame for this long in flight: panic"},
    {ParamId::battery_warning_mv, "battery_warning", 0, 9000, 12600, 11100, "mV", "below this: warning"},
    {ParamId::battery_panic_mv, "battery_panic", 0, 9000, 12600, 10500, "mV", "below this in flight: panic"},
    {ParamId::tilt_limit_mrad, "tilt_limit", 0, 87, 1396, 785, "mrad", "tilt beyond this in yaw/full control: panic (785 = 45 deg)"},
    {ParamId::max_yaw_rate_rad_s, "max_yaw_rate", 10, 0, 8192, 2048, "rad/s", "yaw rate set-point at full stick"},
    {ParamId::panic_level, "panic_level", 0, 0, 1000, 350, "engine units", "engines hold at most this while panicking"},
    {ParamId::panic_hold_ms, "panic_hold", 0, 0, 10000, 2000, "ms", "panic: time at the panic level before ramping down"},
    {ParamId::panic_ramp_ms, "panic_ramp", 0, 0, 10000, 1000, "ms", "panic: ramp from panic level to zero"},
    {ParamId::idle_level, "idle_level", 0, 0, 500, 180, "engine units", "lowest engine value while lift > 0 in flight"},
    {ParamId::log_divider, "log_divider", 0, 1, 1000, 10, "control periods", "write a log line every this many periods"},
    {ParamId::roll_pitch_i, "roll_pitch_i", 4, 0, 16000, 1280, "thrust units per rad", "roll/pitch rate loop integral gain"},
    {ParamId::roll_pitch_d, "roll_pitch_d", 8, 0, 5120, 1280, "thrust units per rad/s^2", "roll/pitch rate loop derivative gain (on the measured rate)"},
};

inline constexpr size_t kParameterCount = sizeof(kParameterTable) / sizeof(kParameterTable[0]);

// The row for a wire id, or nullptr.
const ParameterSpec* find_parameter(uint8_t id);

constexpr bool in_range(const ParameterSpec& spec, int32_t raw) { return raw >= spec.min && raw <= spec.max; }

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
