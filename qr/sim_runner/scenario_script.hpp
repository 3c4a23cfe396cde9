// A scenario as a user writes it (docs/simulator.md section 6.2, the file format): how the flight
// starts, the vehicle and its modifiers, the pilot's timed events after the preflight, and the
// bands the flight is judged by. parse_scenario reads the text; it touches no file, so it can be
// fuzzed (tests/fuzz/scenario_file_fuzz.cpp). load_scenario_file also reads the vehicle file it
// names.
#pragma once

#include <stdint.h>

#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <common/mode.hpp>
#include <common/parameter_table.hpp>
#include <qr/host/parameter_text.hpp>
#include <sim/hand_turn.hpp>
#include <sim/vec3.hpp>
#include <sim/vehicle.hpp>
#include <sim/wiring.hpp>

namespace qrsim {

enum class Start : uint8_t {
  hover,   // calibrate, full control, take off to 1.5 m, settle 1.5 s: then t0
  ground,  // calibrate, full control with the lift at 0, still on the ground: then t0
  safe,    // calibrate: then t0, in safe on the ground; the script arms (`mode full`) itself
};

// <, <=, ==, >, >=: a floor (a figure that must reach a value) is as natural a band as a ceiling.
enum class Compare : uint8_t { below, at_most, equal, above, at_least };

// A pass band: figure `compare` limit. A figure that was not measured (NaN) fails.
struct Band {
  std::string figure;
  Compare compare = Compare::below;
  double limit = 0;  // final_mode: the mode's number
  int line = 0;
};

enum class Action : uint8_t {
  roll,         // value: stick for this roll angle, degrees
  pitch,        // value: degrees
  yaw,          // value: yaw-rate stick, rad/s
  lift_hold,    // the pilot holds the hover height (1.5 m), taking off if on the ground
  lift_height,  // value: the pilot holds this height, m
  lift_share,   // value: this share of the hover lift, held open loop (0: lift stick down)
  lift_still,   // the pilot's hand stops: the lift stick stays where it is (height hold flies)
  mode,         // mode: the pilot requests it
  param,        // param, raw: the pilot uploads it
  torque,       // vector: N·m in body axes, for duration_s
  force,        // vector: N in world axes (north, east, down), for duration_s
  wind,         // vector: air velocity in world axes, m/s, held until changed
  link,         // value 1: the pilot's line is live, 0: silent
  console,      // value 1: the console sends at the line's full rate (full_line_console.hpp), 0: as usual
  log_start,    // the pilot starts both logs
  log_stop,     // the pilot stops them
  download,     // value 0: the pilot downloads the whole sensor log, 1: the telemetry log
  turn,         // turn: a hand turns the vehicle about a body axis (sim/hand_turn.hpp)
  // Faults on the sensors' bus and chips (--sensors drivers; docs/drivers.md section 7, "Faults"):
  nack,           // value: the 7-bit address that NACKs, for duration_s
  sda_stuck,      // the bus answers bus_stuck for duration_s (infinity: for ever)
  imu_identity,   // value: what the MPU's WHO_AM_I reads from now on
  prom_bad,       // the MS5611's PROM reads with a bad CRC from now on
  baro_slow,      // value: ms each MS5611 conversion commanded takes beyond its time, for duration_s
  fifo_overflow,  // the MPU's FIFO overflowed (the driver does not use it)
  imu_self_test,  // the MPU's gyroscope x responds to its self-test at half its trim, from power-up
};

struct Event {
  double at_s = 0;  // after t0
  Action action = Action::roll;
  double value = 0;
  sim::Vec3 vector;
  double duration_s = 0;
  wire::Mode mode = wire::Mode::safe;
  wire::ParamId param = wire::ParamId::idle_level;
  int32_t raw = 0;
  sim::HandTurnSpec turn;
  int line = 0;
};

inline constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

struct ScenarioScript {
  std::string name;     // the file's name without its extension
  std::string origin;   // where the text came from, for messages ("sim/scenarios/hover.txt")
  std::string summary;  // one line for qrsim --list
  double seconds = 0;   // scored window from t0
  Start start = Start::hover;
  std::string vehicle_file;  // as written, relative to the scenario file
  int vehicle_line = 0;
  std::optional<sim::VehicleParams> vehicle;  // loaded by load_scenario_file
  double mass_scale = 1, inertia_scale = 1;
  double motor_tau_ms = kUnset;  // spin-up; spin-down keeps the vehicle's ratio
  double battery_pct = kUnset;   // charge at start
  double noise_scale = 1, vibration_scale = 1;
  // The vehicle put together wrong (sim/wiring.hpp): a file that names a wiring row gives the whole
  // wiring (the rows it does not name: right).
  sim::Wiring wiring;
  std::vector<std::pair<wire::ParamId, int32_t>> parameters;  // uploaded before the flight
  std::vector<Event> events;                                  // in time order
  std::vector<Band> bands;
  std::string known_failure;  // non-empty: today's firmware fails a band, and why
};

// Reads a scenario's text. `name` names it; `origin` starts every error message
// ("origin:line: what is wrong").
bool parse_scenario(const std::string& text, const std::string& name, const std::string& origin, ScenarioScript& out,
                    std::string& error);

// Reads a scenario file and the vehicle file it names (relative to the scenario file).
bool load_scenario_file(const std::string& path, ScenarioScript& out, std::string& error);

// Where a user reads the format when a file does not read: qrsim's messages point there.
inline constexpr const char* kScenarioFormatDoc = "docs/simulator.md section 6.2";

// A parameter by its name and a value in its unit (qr::host::parameter_from_text), for the
// scenario files' param lines and events and qrsim's --param. A value out of range is told the
// parameter's range and unit, so a user need not look them up. Empty on success.
std::string parameter_from_text(const std::string& name, const std::string& value, wire::ParamId& id, int32_t& raw);

const char* compare_text(Compare compare);  // "<", "<=", "==", ">", ">="
std::string band_text(const Band& band);    // "rise_s < 0.3", "final_mode == full"

}  // namespace qrsim
