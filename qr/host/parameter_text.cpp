#include <qr/host/parameter_text.hpp>

#include <cmath>
#include <cstdlib>

namespace qr::host {

std::string parameter_from_text(const std::string& name, const std::string& value, wire::ParamId& id, int32_t& raw) {
  const wire::ParameterSpec* spec = nullptr;
  for (const wire::ParameterSpec& s : wire::kParameterTable) {
    if (name == s.name) spec = &s;
  }
  if (spec == nullptr) return "unknown parameter '" + name + "' (docs/parameters.md names them)";
  char* end = nullptr;
  const double real = value.empty() ? 0 : std::strtod(value.c_str(), &end);
  if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(real))
    return "bad number '" + value + "' for parameter " + name;
  const double scaled = std::round(std::ldexp(real, spec->frac_bits));
  if (scaled < spec->min || scaled > spec->max) return "parameter " + name + ": " + value + " is out of range";
  id = spec->id;
  raw = static_cast<int32_t>(scaled);
  return "";
}

}  // namespace qr::host
