// The parameter table's formats, as the chain reads them: a gain arrives as the raw integer of
// its row's Q format (common/parameter_table.hpp), and the chain uses that very format, so a
// gain enters the flight build without any conversion or rounding.
#pragma once

#include <stddef.h>

#include <common/parameter_table.hpp>

namespace qr::chain {

// Ids are 1..kParameterCount in table order (tests/common/parameter_table_test.cpp checks it).
constexpr const wire::ParameterSpec& parameter_spec(wire::ParamId id) {
  return wire::kParameterTable[static_cast<size_t>(id) - 1];
}
constexpr int parameter_frac_bits(wire::ParamId id) { return parameter_spec(id).frac_bits; }

inline constexpr int kYawPFrac = parameter_frac_bits(wire::ParamId::yaw_p);                     // Q<4>
inline constexpr int kYawIFrac = parameter_frac_bits(wire::ParamId::yaw_i);                     // Q<4>
inline constexpr int kP1Frac = parameter_frac_bits(wire::ParamId::roll_pitch_p1);               // Q<8>
inline constexpr int kP2Frac = parameter_frac_bits(wire::ParamId::roll_pitch_p2);               // Q<4>
inline constexpr int kRollPitchIFrac = parameter_frac_bits(wire::ParamId::roll_pitch_i);        // Q<4>
inline constexpr int kRollPitchDFrac = parameter_frac_bits(wire::ParamId::roll_pitch_d);        // Q<8>
inline constexpr int kMaxYawRateFrac = parameter_frac_bits(wire::ParamId::max_yaw_rate_rad_s);  // Q<10>

}  // namespace qr::chain
