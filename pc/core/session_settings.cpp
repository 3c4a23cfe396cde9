#include <pc/core/session_settings.hpp>

#include <algorithm>

#include <pc/core/param_file.hpp>

namespace qrterm {
namespace {

// A saved value and the session it cannot work in, with what to do; one row per trap.
struct Trap {
  wire::ParamId id;
  bool (*traps)(int32_t value, const SessionKind& session);
  const char* why_and_fix;  // after "name = value "
};

constexpr Trap kTraps[] = {
    {wire::ParamId::pilot, [](int32_t v, const SessionKind& s) { return v == 1 && s.simulator && !s.simulator_radio; },
     "(the radio flies) but this simulator has no radio: no key arms the QR. Set pilot 0 on the parameter "
     "screen (Tab Tab, select pilot, =), or start with a radio (scripts/run --radio)"},
    {wire::ParamId::gyro_turns, [](int32_t v, const SessionKind&) { return v > 0; },
     "from the parameter file: the next calibration (3) waits for that many whole turns by hand "
     "(the gyro's scale, docs/console.md). For a calibration at rest set gyro_turns 0 on the parameter "
     "screen"},
};

}  // namespace

bool simulator_has_radio(const std::vector<std::string>& simulator_arguments) {
  return std::find(simulator_arguments.begin(), simulator_arguments.end(), "--rc") != simulator_arguments.end();
}

bool simulator_flies_devboard(const std::vector<std::string>& simulator_arguments) {
  return std::find(simulator_arguments.begin(), simulator_arguments.end(), "--devboard") != simulator_arguments.end();
}

std::vector<std::string> settings_that_trap(const wire::ParameterValues& saved, const SessionKind& session) {
  std::vector<std::string> lines;
  for (const Trap& trap : kTraps) {
    const int32_t value = saved.get(trap.id);
    if (!trap.traps(value, session)) continue;
    const wire::ParameterSpec* spec = wire::find_parameter(static_cast<uint8_t>(trap.id));
    lines.push_back(std::string(spec->name) + " = " + format_real(*spec, value) + " " + trap.why_and_fix);
  }
  return lines;
}

std::vector<std::string> undo_lines(const wire::ParameterValues& before, const wire::ParameterValues& after) {
  std::vector<std::string> lines;
  for (const wire::ParameterSpec& spec : wire::kParameterTable) {
    const int32_t was = before.get(spec.id), is = after.get(spec.id);
    if (was == is) continue;
    std::string change = std::string(spec.name) + " " + format_real(spec, was) + " -> " + format_real(spec, is);
    change.resize(std::max<size_t>(change.size() + 2, 36), ' ');
    lines.push_back(change + "undo: " + spec.name + " = " + format_real(spec, was));
  }
  return lines;
}

}  // namespace qrterm
