#include <pc/core/param_file.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
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
  for (const wire::ParameterSpec& spec : wire::kParameterTable) names += std::string(names.empty() ? "" : ", ") + spec.name;
  return names;
}

uint8_t id_byte(wire::ParamId id) { return static_cast<uint8_t>(id); }

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
      out.errors.push_back({setting.line, "unknown parameter \"" + setting.name + "\" (known: " + known_names() + ")"});
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
  std::stable_sort(out.errors.begin(), out.errors.end(), [](const LineError& a, const LineError& b) { return a.line < b.line; });
  return out;
}

std::string format_param_file(const wire::ParameterValues& values) {
  std::string text =
      "# qrterm parameters: sent to the QR at connect, written back at exit.\n"
      "# name = value, in the unit given; docs/protocol.md section 9 has the table.\n";
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    text += "\n# " + std::string(spec.meaning) + " [" + spec.unit + "], " + format_real(spec, spec.min) + " .. " +
            format_real(spec, spec.max) + ", default " + format_real(spec, spec.default_value) + "\n";
    text += std::string(spec.name) + " = " + format_real(spec, values.get(spec.id)) + "\n";
  }
  return text;
}

}  // namespace qrterm
