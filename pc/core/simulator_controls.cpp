#include <pc/core/simulator_controls.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <pc/core/mode_names.hpp>
#include <pc/core/radio_pilot.hpp>

namespace qrterm {
namespace {

// A key of the simulator's and what it sends. `command` null: the key makes its own (turn).
struct SimulatorKey {
  Action action;
  const char* without_simulator;  // after "no simulator: "
  const char* command;
  const char* said;
};

constexpr SimulatorKey kSimulatorKeys[] = {
    {Action::sim_push, "n pushes only a QR the console started in qrsim", "push 0.3 0 0 0.1\n",
     "sim: push 0.3 N m about roll for 0.1 s"},
    {Action::sim_reset, "v sets upright only a QR the console started in qrsim", "reset\n",
     "sim: asking to set the QR down upright (engines must be off)"},
    {Action::sim_turn, "y turns only a QR the console started in qrsim", nullptr, nullptr},
    {Action::sim_radio_off, "m moves only the arm switch of qrsim's radio (--sim-arg --rc --sim-arg crsf)",
     "radio off\n", "sim radio: the arm switch off (in a flight mode: panic)"},
};

// The number after " name=" in a truth line.
bool field(const std::string& line, const char* name, double& out) {
  const std::string key = std::string(" ") + name + "=";
  const size_t at = line.find(key);
  if (at == std::string::npos) return false;
  char* end = nullptr;
  out = std::strtod(line.c_str() + at + key.size(), &end);
  return end != line.c_str() + at + key.size();
}

// "rotors=A,B,C,D" in a truth line: four numbers.
std::optional<std::array<double, 4>> rotor_field(const std::string& line) {
  const std::string key = " rotors=";
  const size_t at = line.find(key);
  if (at == std::string::npos) return std::nullopt;
  std::array<double, 4> speeds{};
  const char* p = line.c_str() + at + key.size();
  for (size_t i = 0; i < speeds.size(); ++i) {
    if (i > 0 && *p++ != ',') return std::nullopt;
    char* end = nullptr;
    speeds[i] = std::strtod(p, &end);
    if (end == p) return std::nullopt;
    p = end;
  }
  return speeds;
}

}  // namespace

bool SimulatorControls::act(Action action) {
  for (const SimulatorKey& key : kSimulatorKeys) {
    if (key.action != action) continue;
    if (!present_) {
      note_(Severity::warning, std::string("no simulator: ") + key.without_simulator);
    } else if (key.command == nullptr) {
      turn();
    } else {
      commands_.emplace_back(key.command);
      note_(Severity::info, key.said);
    }
    return true;
  }
  return false;
}

void SimulatorControls::turn() {
  // Two turns in 4 s: 180 deg/s at the peak, well inside the gyro's 500. The axes in the order the
  // calibration is usually made: flat on the table, on its tail, on its side.
  static constexpr char kAxes[] = {'z', 'x', 'y'};
  const char axis = kAxes[next_turn_axis_];
  next_turn_axis_ = (next_turn_axis_ + 1) % 3;
  commands_.emplace_back(std::string("turn ") + axis + " 2 4\n");
  note_(Severity::info, std::string("sim: the hand turns the QR twice about its ") + axis +
                            " axis in 4 s (with gyro_turns = 2 and a calibration: that axis' gyro scale)");
}

bool SimulatorControls::hand_tilt(size_t axis) {
  // 45 deg out in a third of a second, held as long, back as fast: at most 212 deg/s, inside the
  // gyro's 500, and a step answered in under 1.5 s.
  static constexpr struct {
    char axis;
    const char* said;
  } kTilts[] = {{'x', "right side down"}, {'y', "nose up"}, {'z', "nose right"}};
  if (!present_ || axis >= 3) return false;
  commands_.emplace_back(std::string("tilt ") + kTilts[axis].axis + " 45 1\n");
  note_(Severity::info,
        std::string("sim: the hand tilts the QR ") + kTilts[axis].said + " 45 deg, holds it and sets it down");
  return true;
}

bool SimulatorControls::take_mode_request(wire::Mode mode, bool in_safe, const TelemetryModel& telemetry) {
  switch (radio_arming(mode, in_safe, present_, telemetry)) {
    case RadioArming::console: return false;
    case RadioArming::refused:
      note_(Severity::warning, std::string("not moving the radio's switches for ") + mode_name(mode) +
                                   ": the radio arms from safe only, and its arm switch off in flight is a panic (m)");
      return true;
    case RadioArming::arm:
      commands_.emplace_back(std::string("radio arm ") + wire::mode_key(mode) + "\n");
      note_(Severity::info,
            std::string("sim radio: mode switch to ") + mode_name(mode) + ", arm switch off and on (m: off)");
      return true;
  }
  return false;
}

std::optional<PlotModel::TrueState> SimulatorControls::on_line(const std::string& line, uint32_t now_ms) {
  if (line.rfind("error radio", 0) == 0) {
    // The switches were asked for because the QR says its radio flies (pilot = 1, saved perhaps
    // from a session with a radio): say how to fly from the keys again.
    note_(Severity::warning, "sim: " + line + ": pilot = 1 makes the radio the pilot; set pilot 0 on the parameter " +
                                 "screen (Tab Tab, select pilot, =) to fly from the keys");
    return std::nullopt;
  }
  if (line.rfind("error", 0) == 0) {
    note_(Severity::warning, "sim: " + line);
    return std::nullopt;
  }
  if (line.rfind("ok reset", 0) == 0) {
    note_(Severity::info, "sim: the QR stands upright and still; calibrate (3) again if the attitude is off");
    return std::nullopt;
  }
  if (line.rfind("devboard ", 0) == 0) {
    take_devboard(line);
    return std::nullopt;
  }
  if (line.rfind("truth ", 0) != 0) return std::nullopt;  // "ok push" and anything newer
  double roll = 0, pitch = 0, yaw = 0, height = 0, climb = 0, t_s = 0;
  if (field(line, "t", t_s)) {
    const int64_t offset = static_cast<int64_t>(now_ms) - std::llround(t_s * 1000);
    if (!clock_offset_ms_ || offset < *clock_offset_ms_) clock_offset_ms_ = offset;
  }
  if (const std::optional<std::array<double, 4>> rotors = rotor_field(line)) rotors_ = rotors;
  if (!field(line, "roll", roll) || !field(line, "pitch", pitch) || !field(line, "yaw", yaw) ||
      !field(line, "height", height)) {
    return std::nullopt;
  }
  char text[96];
  std::snprintf(text, sizeof text, "truth roll %+.1f pitch %+.1f yaw %+.1f height %.2f m", roll, pitch, yaw, height);
  truth_ = text;
  constexpr double kRadPerDeg = 0.017453292519943295;
  if (!field(line, "climb", climb)) climb = std::nan("");  // an older simulator's line: no climb truth
  return PlotModel::TrueState{roll * kRadPerDeg, pitch * kRadPerDeg, yaw * kRadPerDeg, height, climb};
}

void SimulatorControls::take_devboard(const std::string& line) {
  double mhz = 0, mean = 0, max = 0, ticks = 0;
  if (!field(line, "core_mhz", mhz) || !field(line, "tick_instr_mean", mean) || !field(line, "tick_instr_max", max) ||
      !field(line, "ticks", ticks) || mhz < 0 || mean < 0 || max < 0 || ticks < 0) {
    return;
  }
  devboard_ = DevboardFigures{static_cast<uint32_t>(mhz), mean, static_cast<uint32_t>(max),
                              static_cast<uint32_t>(ticks)};
}

std::vector<std::string> SimulatorControls::take_commands() {
  std::vector<std::string> commands;
  commands.swap(commands_);
  return commands;
}

}  // namespace qrterm
