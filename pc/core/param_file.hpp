// The parameter file: the values the console sends the QR at connect and saves at exit, as
// "name = value" lines with the names of the shared parameter table (common/parameter_table.hpp)
// and values in the table's real units (yaw_p = 100, roll_pitch_p1 = 4.25), so a person can edit it. The
// wire carries raw integers; a value converts to the nearest raw step (1/2^frac of the unit).
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include <common/parameter_table.hpp>
#include <pc/core/settings_text.hpp>

namespace qrterm {

struct ParamFileContents {
  wire::ParameterValues values;       // defaults where the file is silent
  std::vector<wire::ParamId> listed;  // the parameters the file named, in file order
  std::vector<LineError> errors;      // any error means: do not use `values`
};

ParamFileContents parse_param_file(const std::string& text);

// Every parameter, with its unit, range and meaning in a comment above it.
std::string format_param_file(const wire::ParameterValues& values);

// raw / 2^frac as exact decimal text: 1088 with frac 8 -> "4.25". Every raw value of the table is
// a finite binary fraction, so the text is exact and reads back to the same raw value.
std::string format_real(const wire::ParameterSpec& spec, int32_t raw);


// One parameter set in the parameter file at `path`, the others as the file has them (the
// defaults where it is silent or missing), written through a temporary file: what went wrong, or
// empty. A result kept the moment it is found (the orientation check's imu_orientation), not only
// at exit.
std::string write_param_to_file(const std::string& path, wire::ParamId id, int32_t raw);

// Decimal text in the parameter's unit -> raw, rounded to the nearest step. False when the text
// is not a number.
bool parse_real(const wire::ParameterSpec& spec, const std::string& text, int64_t& raw);

}  // namespace qrterm
