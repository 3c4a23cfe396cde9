#include <pc/core/param_file.hpp>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string_view>

namespace qrterm {
namespace {

const wire::ParameterSpec* find_by_name(const std::string& name) {
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    if (name == spec.name) return &spec;
  }
  return nullptr;
}

std::string known_names() {
  std::string names;
  for (const wire::ParameterSpec& spec : wire::kParameterTable)
    names += std::string(names.empty() ? "" : ", ") + spec.name;
  return names;
}

uint8_t id_byte(wire::ParamId id) { return static_cast<uint8_t>(id); }

// Names parameter files used before the names took their units and their enumerators' spelling:
// a file saved then is refused with the new name in the message rather than read by a second name.
struct FormerName {
  const char* name;
  wire::ParamId now;
};
constexpr FormerName kFormerNames[] = {
    {"p1", wire::ParamId::roll_pitch_p1},
    {"p2", wire::ParamId::roll_pitch_p2},
    {"c1", wire::ParamId::attitude_c1},
    {"c2", wire::ParamId::attitude_c2},
    {"filter_cutoff", wire::ParamId::filter_cutoff_hz},
    {"telemetry_rate", wire::ParamId::telemetry_rate_hz},
    {"link_timeout", wire::ParamId::link_timeout_ms},
    {"battery_warning", wire::ParamId::battery_warning_mv},
    {"battery_panic", wire::ParamId::battery_panic_mv},
    {"tilt_limit", wire::ParamId::tilt_limit_mrad},
    {"max_yaw_rate", wire::ParamId::max_yaw_rate_rad_s},
    {"panic_hold", wire::ParamId::panic_hold_ms},
    {"panic_ramp", wire::ParamId::panic_ramp_ms},
};

std::string unknown_name_error(const std::string& name) {
  for (const FormerName& former : kFormerNames) {
    if (name == former.name) {
      return "\"" + name + "\" is now called " + wire::find_parameter(id_byte(former.now))->name;
    }
  }
  return "unknown parameter \"" + name + "\" (known: " + known_names() + ")";
}

}  // namespace

std::string format_real(const wire::ParameterSpec& spec, int32_t raw) {
  const int64_t value = raw;
  const int64_t magnitude = value < 0 ? -value : value;
  const int64_t one = int64_t{1} << spec.frac_bits;
  std::string text = (value < 0 ? "-" : "") + std::to_string(magnitude / one);
  int64_t fraction = magnitude % one;
  if (fraction == 0) return text;
  // fraction / 2^f == fraction * 5^f / 10^f: exactly f decimal digits.
  for (uint8_t i = 0; i < spec.frac_bits; ++i) fraction *= 5;
  std::string digits = std::to_string(fraction);
  digits.insert(0, spec.frac_bits - digits.size(), '0');
  digits.erase(digits.find_last_not_of('0') + 1);
  return text + "." + digits;
}

bool parse_real(const wire::ParameterSpec& spec, const std::string& text, int64_t& raw) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value, std::chars_format::fixed);
  if (error != std::errc{} || stop != end || !std::isfinite(value)) return false;
  const double scaled = std::ldexp(value, spec.frac_bits);
  // Far outside every range: kept far outside (so it is reported as out of range) while keeping
  // llround within what it can return.
  constexpr double kFar = 9e15;
  raw = std::llround(std::clamp(scaled, -kFar, kFar));
  return true;
}

ParamFileContents parse_param_file(const std::string& text) {
  ParamFileContents out;
  SettingsText settings = read_settings(text);
  out.errors = std::move(settings.errors);
  for (const Setting& setting : settings.settings) {
    const wire::ParameterSpec* spec = find_by_name(setting.name);
    if (spec == nullptr) {
      out.errors.push_back({setting.line, unknown_name_error(setting.name)});
      continue;
    }
    bool repeated = false;
    for (wire::ParamId id : out.listed) repeated = repeated || id == spec->id;
    if (repeated) {
      out.errors.push_back({setting.line, std::string(spec->name) + " is set twice"});
      continue;
    }
    int64_t raw = 0;
    if (!parse_real(*spec, setting.value, raw)) {
      out.errors.push_back({setting.line, std::string(spec->name) + ": \"" + setting.value + "\" is not a number"});
      continue;
    }
    if (raw < spec->min || raw > spec->max) {
      out.errors.push_back({setting.line, std::string(spec->name) + " = " + setting.value + " is outside " +
                                              format_real(*spec, spec->min) + " .. " + format_real(*spec, spec->max) +
                                              " " + spec->unit});
      continue;
    }
    out.values.set(id_byte(spec->id), static_cast<int32_t>(raw));
    out.listed.push_back(spec->id);
  }
  // Errors in line order, whichever pass found them.
  std::stable_sort(out.errors.begin(), out.errors.end(),
                   [](const LineError& a, const LineError& b) { return a.line < b.line; });
  return out;
}

std::string format_param_file(const wire::ParameterValues& values) {
  std::string text =
      "# qrterm parameters: sent to the QR at connect, written back at exit.\n"
      "# name = value, in the unit given; docs/parameters.md has the table.\n";
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    text += "\n# " + std::string(spec.meaning) + " [" + spec.unit + "], " + format_real(spec, spec.min) + " .. " +
            format_real(spec, spec.max) + ", default " + format_real(spec, spec.default_value) + "\n";
    text += std::string(spec.name) + " = " + format_real(spec, values.get(spec.id)) + "\n";
  }
  return text;
}

std::string write_param_to_file(const std::string& path, wire::ParamId id, int32_t raw) {
  std::string text;
  wire::ParameterValues values;
  if (read_file(path, text)) {
    const ParamFileContents contents = parse_param_file(text);
    if (!contents.errors.empty()) {
      const LineError& first = contents.errors.front();
      return path + ":" + std::to_string(first.line) + ": " + first.message;
    }
    values = contents.values;
  } else if (errno != ENOENT) {
    return "cannot read " + path + ": " + std::strerror(errno);
  }
  if (values.set(id_byte(id), raw) != wire::NackReason::none) return "the value is out of range";
  return write_file_atomically(path, format_param_file(values));
}

}  // namespace qrterm
