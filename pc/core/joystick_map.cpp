#include <pc/core/joystick_map.hpp>

#include <algorithm>
#include <charconv>

namespace qrterm {
namespace {

constexpr int32_t kAxisMax = 32767;  // the driver's full deflection
constexpr int32_t kPermille = 1000;

int32_t oriented(const AxisBinding& binding, int32_t raw) {
  const int32_t value = std::clamp(raw, -kAxisMax, kAxisMax);
  return binding.invert ? -value : value;
}

// Removes `band` per mille at the bottom of a 0..1000 scale and stretches the rest back to
// 0..1000, so the output starts from zero at the edge of the band instead of jumping.
int32_t past_deadband(int32_t permille, int32_t band) {
  if (permille <= band) return 0;
  return (permille - band) * kPermille / (kPermille - band);
}

bool parse_int(const std::string& text, int64_t& value) {
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  return error == std::errc{} && stop == end;
}

bool parse_bool(const std::string& text, bool& value) {
  if (text == "yes" || text == "true" || text == "1") return value = true, true;
  if (text == "no" || text == "false" || text == "0") return value = false, true;
  return false;
}

enum class Field : uint8_t { axis, invert, button, deadband };

struct MapEntry {
  const char* name;
  Field field;
  AxisBinding JoystickMap::*binding;  // for axis and invert
};

// Pairs (axis, invert) in the order lift, roll, pitch, yaw, then the rest: the duplicate-axis check
// below finds an input's axis entry at 2 * its index.
constexpr MapEntry kEntries[] = {
    {"lift_axis", Field::axis, &JoystickMap::lift},   {"lift_invert", Field::invert, &JoystickMap::lift},
    {"roll_axis", Field::axis, &JoystickMap::roll},   {"roll_invert", Field::invert, &JoystickMap::roll},
    {"pitch_axis", Field::axis, &JoystickMap::pitch}, {"pitch_invert", Field::invert, &JoystickMap::pitch},
    {"yaw_axis", Field::axis, &JoystickMap::yaw},     {"yaw_invert", Field::invert, &JoystickMap::yaw},
    {"abort_button", Field::button, nullptr},         {"deadband", Field::deadband, nullptr},
};

constexpr int64_t kMaxAxis = 63;  // the Linux joystick API numbers axes and buttons in a byte; no stick has more
constexpr int64_t kMaxDeadband = 500;

}  // namespace

int32_t JoystickMap::stick(const AxisBinding& binding, int32_t raw) const {
  const int32_t value = oriented(binding, raw);
  const int32_t magnitude = past_deadband((value < 0 ? -value : value) * kPermille / kAxisMax, deadband_permille);
  return value < 0 ? -magnitude : magnitude;
}

int32_t JoystickMap::lift_of(int32_t raw) const {
  const int32_t permille = (oriented(lift, raw) + kAxisMax) * kPermille / (2 * kAxisMax);
  return past_deadband(permille, deadband_permille);
}

JoystickMapFile parse_joystick_map(const std::string& text) {
  JoystickMapFile out;
  SettingsText settings = read_settings(text);
  size_t axis_line[4] = {0, 0, 0, 0};  // where lift, roll, pitch, yaw were set; 0: default
  out.errors = std::move(settings.errors);
  for (const Setting& setting : settings.settings) {
    const MapEntry* entry = nullptr;
    for (const MapEntry& candidate : kEntries) {
      if (setting.name == candidate.name) entry = &candidate;
    }
    if (entry == nullptr) {
      std::string names;
      for (const MapEntry& e : kEntries) names += std::string(names.empty() ? "" : ", ") + e.name;
      out.errors.push_back({setting.line, "unknown setting \"" + setting.name + "\" (known: " + names + ")"});
      continue;
    }
    int64_t number = 0;
    bool flag = false;
    switch (entry->field) {
      case Field::invert:
        if (!parse_bool(setting.value, flag)) {
          out.errors.push_back({setting.line, setting.name + ": expected yes or no, found \"" + setting.value + "\""});
        } else {
          (out.map.*entry->binding).invert = flag;
        }
        break;
      case Field::axis:
      case Field::button:
        if (!parse_int(setting.value, number) || number < 0 || number > kMaxAxis) {
          out.errors.push_back({setting.line, setting.name + ": expected a number 0.." + std::to_string(kMaxAxis) +
                                                  ", found \"" + setting.value + "\""});
        } else if (entry->field == Field::axis) {
          (out.map.*entry->binding).axis = static_cast<uint8_t>(number);
          axis_line[static_cast<size_t>(entry - kEntries) / 2] = setting.line;
        } else {
          out.map.abort_button = static_cast<uint8_t>(number);
        }
        break;
      case Field::deadband:
        if (!parse_int(setting.value, number) || number < 0 || number > kMaxDeadband) {
          out.errors.push_back({setting.line, "deadband: expected per mille 0.." + std::to_string(kMaxDeadband) +
                                                  ", found \"" + setting.value + "\""});
        } else {
          out.map.deadband_permille = static_cast<int32_t>(number);
        }
        break;
    }
  }
  const AxisBinding JoystickMap::*axes[] = {&JoystickMap::lift, &JoystickMap::roll, &JoystickMap::pitch,
                                            &JoystickMap::yaw};
  for (size_t i = 0; i < 4; ++i) {
    for (size_t j = i + 1; j < 4; ++j) {
      if ((out.map.*axes[i]).axis == (out.map.*axes[j]).axis) {
        out.errors.push_back({std::max(axis_line[i], axis_line[j]), std::string(kEntries[2 * i].name) + " and " +
                                                                        kEntries[2 * j].name + " are both axis " +
                                                                        std::to_string((out.map.*axes[i]).axis)});
      }
    }
  }
  std::stable_sort(out.errors.begin(), out.errors.end(),
                   [](const LineError& a, const LineError& b) { return a.line < b.line; });
  return out;
}

std::string format_joystick_map(const JoystickMap& map) {
  std::string text =
      "# qrterm joystick map: axis numbers as the Linux joystick driver counts them (jstest shows them).\n";
  for (const MapEntry& entry : kEntries) {
    std::string value;
    switch (entry.field) {
      case Field::axis: value = std::to_string((map.*entry.binding).axis); break;
      case Field::invert: value = (map.*entry.binding).invert ? "yes" : "no"; break;
      case Field::button: value = std::to_string(map.abort_button); break;
      case Field::deadband: value = std::to_string(map.deadband_permille); break;
    }
    text += std::string(entry.name) + " = " + value + "\n";
  }
  return text;
}

}  // namespace qrterm
