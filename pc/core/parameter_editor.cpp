#include <pc/core/parameter_editor.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <pc/core/gain_steps.hpp>
#include <pc/core/param_file.hpp>

namespace qrterm {
namespace {

constexpr const char* kStatusNames[] = {"pending", "read back", "differs", "no report"};

}  // namespace

const char* status_name(ParamStatus status) { return kStatusNames[static_cast<size_t>(status)]; }

std::optional<double> degrees_of(const wire::ParameterSpec& spec, int32_t raw) {
  if (std::string(spec.unit) != "mrad") return std::nullopt;
  constexpr double kDegPerRad = 57.29577951308232;
  return raw / 1000.0 * kDegPerRad;
}

std::string name_and_value(const wire::ParameterSpec& spec, int32_t raw, size_t width) {
  const std::string name = spec.name;
  const std::string value = format_real(spec, raw);
  std::string angle;
  if (const std::optional<double> degrees = degrees_of(spec, raw)) {
    // One decimal where it fits, else whole degrees, else none: the value's column is what must stay.
    char text[32];
    for (const char* format : {"(%.1f deg) ", "(%.0f deg) "}) {
      std::snprintf(text, sizeof text, format, *degrees);
      if (name.size() + 1 + std::string(text).size() + value.size() <= width) {
        angle = text;
        break;
      }
    }
  }
  const std::string right = angle + value;
  if (name.size() + 1 + right.size() > width) return (name + " " + right).substr(0, width);
  return name + std::string(width - name.size() - right.size(), ' ') + right;
}

std::string unit_with_degrees(const wire::ParameterSpec& spec, int32_t raw) {
  const std::optional<double> degrees = degrees_of(spec, raw);
  if (!degrees) return spec.unit;
  char text[48];
  std::snprintf(text, sizeof text, "%s, now %.1f deg", spec.unit, *degrees);
  return text;
}

void ParameterEditor::move(int rows) {
  const long next = static_cast<long>(cursor_) + rows;
  cursor_ = static_cast<size_t>(std::clamp<long>(next, 0, static_cast<long>(wire::kParameterCount) - 1));
}

ParamStatus ParameterEditor::status(const ParameterSync& sync, wire::ParamId id) const {
  if (sync.pending(id)) return ParamStatus::pending;
  const std::optional<int32_t> reported = sync.reported(id);
  if (!reported) return ParamStatus::unknown;
  return *reported == sync.wanted().get(id) ? ParamStatus::read_back : ParamStatus::differs;
}

std::optional<int32_t> ParameterEditor::file_difference(const ParameterSync& sync, wire::ParamId id) const {
  if (!file_exists_) return std::nullopt;
  const int32_t in_file = file_values_.get(id);
  if (in_file == sync.wanted().get(id)) return std::nullopt;
  return in_file;
}

void ParameterEditor::step(ParameterSync& sync, int direction) const {
  const wire::ParameterSpec& spec = selected();
  for (const GainStep& gain : kGainSteps) {
    const bool same_way = (gain.add > 0 || gain.multiply == 2) == (direction > 0);
    if (gain.id == spec.id && same_way) return sync.step(gain);
  }
  const int32_t span = spec.max - spec.min;
  const int32_t amount = std::max<int32_t>(1, span / 100);
  const GainStep generic{Action::none, spec.id, direction > 0 ? amount : -amount, 1};
  sync.step(generic);
}

std::string ParameterEditor::set_typed(ParameterSync& sync, const std::string& text) const {
  const wire::ParameterSpec& spec = selected();
  int64_t raw = 0;
  if (!parse_real(spec, text, raw)) return "\"" + text + "\" is not a number";
  if (raw < spec.min || raw > spec.max) {
    std::string range = format_real(spec, spec.min) + " .. " + format_real(spec, spec.max) + " " + spec.unit;
    if (degrees_of(spec, spec.min)) {
      char degrees[48];
      std::snprintf(degrees, sizeof degrees, " (%.1f .. %.1f deg)", *degrees_of(spec, spec.min),
                    *degrees_of(spec, spec.max));
      range += degrees;
    }
    return std::string(spec.name) + " = " + text + " is outside " + range;
  }
  sync.set(spec.id, static_cast<int32_t>(raw));
  return "";
}

void ParameterEditor::reset_default(ParameterSync& sync) const { sync.set(selected().id, selected().default_value); }

size_t ParameterEditor::reset_all_defaults(ParameterSync& sync) const {
  size_t changed = 0;
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    if (sync.wanted().get(spec.id) == spec.default_value) continue;
    sync.set(spec.id, spec.default_value);
    ++changed;
  }
  return changed;
}

void ParameterEditor::file_written(const std::string& path, wire::ParamId id, int32_t raw) {
  if (path != file_name_) return;
  // A file written where there was none holds the defaults and this value (write_param_to_file).
  if (!file_exists_) file_values_ = wire::ParameterValues{};
  file_exists_ = true;
  (void)file_values_.set(static_cast<uint8_t>(id), raw);
}

std::string ParameterEditor::save(const ParameterSync& sync, const std::string& path) {
  if (path.empty()) return "no file name";
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << format_param_file(sync.wanted());
    out.flush();
    if (!out) return "cannot write " + temporary;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) return "cannot write " + path;
  file_values_ = sync.wanted();
  file_name_ = path;
  file_exists_ = true;
  return "";
}

std::string ParameterEditor::load(ParameterSync& sync, const std::string& path) {
  std::ifstream in(path);
  if (!in) return "cannot read " + path;
  std::ostringstream text;
  text << in.rdbuf();
  const ParamFileContents contents = parse_param_file(text.str());
  if (!contents.errors.empty()) {
    const LineError& first = contents.errors.front();
    return path + ":" + std::to_string(first.line) + ": " + first.message +
           (contents.errors.size() > 1 ? " (and " + std::to_string(contents.errors.size() - 1) + " more)" : "");
  }
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    const int32_t value = contents.values.get(spec.id);
    if (value != sync.wanted().get(spec.id)) sync.set(spec.id, value);
  }
  file_values_ = contents.values;
  file_name_ = path;
  file_exists_ = true;
  return "";
}

}  // namespace qrterm
