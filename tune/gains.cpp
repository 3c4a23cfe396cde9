#include <tune/gains.hpp>

#include <cmath>
#include <cstdio>

namespace tune {
namespace {

const wire::ParameterSpec& spec_of(wire::ParamId id) { return *wire::find_parameter(static_cast<uint8_t>(id)); }

double value_of(wire::ParamId id, int32_t raw) { return std::ldexp(raw, -spec_of(id).frac_bits); }

// Nearest raw value (halves away from zero), then the range.
RawParameter raw_of(wire::ParamId id, double value) {
  const wire::ParameterSpec& spec = spec_of(id);
  const double scaled = std::round(std::ldexp(value, spec.frac_bits));
  RawParameter p{id, 0, false};
  if (!(scaled >= spec.min)) {  // also NaN
    p.raw = spec.min;
    p.clamped = true;
  } else if (scaled > spec.max) {
    p.raw = spec.max;
    p.clamped = true;
  } else {
    p.raw = static_cast<int32_t>(scaled);
  }
  return p;
}

double default_of(wire::ParamId id) { return value_of(id, spec_of(id).default_value); }

using wire::ParamId;

}  // namespace

const char* RawParameter::name() const { return spec_of(id).name; }

double RawParameter::value() const { return value_of(id, raw); }

// raw / 2^frac has at most frac decimals (2^-frac = 5^frac / 10^frac), and the table's formats
// have at most 8 fraction bits: printed with frac decimals, trailing zeros dropped, it is exact.
std::string RawParameter::text() const {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.*f", static_cast<int>(spec_of(id).frac_bits), value());
  std::string s = buffer;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s;
}

std::array<RawParameter, 4> raw_parameters(const RollPitchGains& g) {
  return {raw_of(ParamId::roll_pitch_p1, g.p1), raw_of(ParamId::roll_pitch_p2, g.p2),
          raw_of(ParamId::roll_pitch_i, g.i), raw_of(ParamId::roll_pitch_d, g.d)};
}

std::array<RawParameter, 2> raw_parameters(const YawGains& g) {
  return {raw_of(ParamId::yaw_p, g.p), raw_of(ParamId::yaw_i, g.i)};
}

RollPitchGains flown(const RollPitchGains& gains) {
  const auto r = raw_parameters(gains);
  return {r[0].value(), r[1].value(), r[2].value(), r[3].value()};
}

YawGains flown(const YawGains& gains) {
  const auto r = raw_parameters(gains);
  return {r[0].value(), r[1].value()};
}

RollPitchGains default_roll_pitch_gains() {
  return {default_of(ParamId::roll_pitch_p1), default_of(ParamId::roll_pitch_p2), default_of(ParamId::roll_pitch_i),
          default_of(ParamId::roll_pitch_d)};
}

YawGains default_yaw_gains() { return {default_of(ParamId::yaw_p), default_of(ParamId::yaw_i)}; }

RollPitchGains roll_pitch_gains(const wire::ParameterValues& table) {
  const auto in = [&](ParamId id) { return value_of(id, table.get(id)); };
  return {in(ParamId::roll_pitch_p1), in(ParamId::roll_pitch_p2), in(ParamId::roll_pitch_i), in(ParamId::roll_pitch_d)};
}

YawGains yaw_gains(const wire::ParameterValues& table) {
  return {value_of(ParamId::yaw_p, table.get(ParamId::yaw_p)), value_of(ParamId::yaw_i, table.get(ParamId::yaw_i))};
}

GainRange range_of(wire::ParamId id) {
  const wire::ParameterSpec& spec = spec_of(id);
  return {value_of(id, spec.min), value_of(id, spec.max)};
}

}  // namespace tune
