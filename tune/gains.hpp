// The gains the design chooses, in the parameters' own units (common/parameter_table.hpp), and
// how they become the parameter table's raw integers: rounded to the row's Q format and clamped
// to its range, which is what the firmware flies. A value is written as `qrsim --param NAME=VALUE`
// and the parameter files take it: in the unit, exactly raw / 2^frac (qr/host/parameter_text.hpp
// reads it back to the same raw).
#pragma once

#include <stdint.h>

#include <array>
#include <string>

#include <common/parameter_table.hpp>

namespace tune {

struct RollPitchGains {
  double p1 = 0;  // 1/s: rate set-point per rad of angle error (roll_pitch_p1)
  double p2 = 0;  // thrust units per rad/s (roll_pitch_p2)
  double i = 0;   // thrust units per rad (roll_pitch_i)
  double d = 0;   // thrust units per rad/s^2 (roll_pitch_d)
};

struct YawGains {
  double p = 0;  // thrust units per rad/s (yaw_p)
  double i = 0;  // thrust units per rad (yaw_i)
};

struct RawParameter {
  wire::ParamId id{};
  int32_t raw = 0;
  bool clamped = false;  // the gain was outside the parameter's range

  const char* name() const;
  double value() const;      // raw / 2^frac, in the parameter's unit
  std::string text() const;  // that value, exactly, as --param takes it
};

std::array<RawParameter, 4> raw_parameters(const RollPitchGains& gains);  // p1, p2, i, d
std::array<RawParameter, 2> raw_parameters(const YawGains& gains);        // p, i

// The gains the firmware would fly: rounded to their formats and clamped to their ranges.
RollPitchGains flown(const RollPitchGains& gains);
YawGains flown(const YawGains& gains);

// The parameter table's defaults.
RollPitchGains default_roll_pitch_gains();
YawGains default_yaw_gains();
// The gains a parameter table flies.
RollPitchGains roll_pitch_gains(const wire::ParameterValues& table);
YawGains yaw_gains(const wire::ParameterValues& table);

// A parameter's range in its unit (for the design's search).
struct GainRange {
  double min, max;
};
GainRange range_of(wire::ParamId id);

}  // namespace tune
