// A parameter as people write it: its name in docs/parameters.md and a value in its unit, to the
// raw value the wire carries. Shared by the host programs' --param (qrsim, qrreplay) and the
// scenario files.
#pragma once

#include <stdint.h>

#include <string>

#include <common/parameter_table.hpp>

namespace qr::host {

// Returns an empty string on success, otherwise what is wrong (an unknown name, a bad number, a
// value out of the parameter's range).
std::string parameter_from_text(const std::string& name, const std::string& value, wire::ParamId& id, int32_t& raw);

}  // namespace qr::host
