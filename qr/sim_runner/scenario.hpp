// Headless flights: the QR firmware in the simulated world, flown by the simulated pilot through
// the wire, scored on the simulator's truth against a scenario's pass bands. A scenario is a
// ScenarioScript (scenario_script.hpp), read from a file a user writes or from the built-in
// files of sim/scenarios/ compiled into qrsim (builtin_scenarios.hpp).
#pragma once

#include <stdint.h>

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <common/parameter_table.hpp>
#include <qr/boards/sim/flying_qr.hpp>
#include <qr/sim_runner/scenario_script.hpp>
#include <sim/vehicle.hpp>

namespace qrsim {

// Multipliers a robustness sweep draws for one run (sweep.hpp), on top of the scenario's own
// modifiers. All 1: the scenario as written.
struct VehicleDraw {
  double mass = 1, inertia = 1, motor_tau = 1, vibration = 1, noise = 1;
};

struct RunOptions {
  double seconds = 0;  // <= 0: the scenario's
  uint64_t seed = 1;
  // --vehicle: replaces the scenario's vehicle (its own file or the compiled-in default).
  std::optional<sim::VehicleParams> vehicle;
  std::string vehicle_name;
  bool sensor_noise = true;  // false: perfect IMU (no noise, bias, scale error or vibration)
  std::vector<std::pair<wire::ParamId, int32_t>> parameters;  // --param, after the scenario's own
  VehicleDraw draw;
  std::string trace_path;  // non-empty: every control period as a CSV line (truth, estimate, engines)
  // Non-empty: the QR's sensor samples and sticks from its first calibration tick on, in the
  // replay's input format (docs/replay.md), so `qrsim --replay` can run the flight again.
  std::string record_path;
  // Non-empty: fly this RV32 ELF on the emulated devboard, in lock-step over the sensor link
  // (devboard_qr.hpp), instead of the host build.
  std::string devboard_elf;
  // With devboard_elf, --core-mhz N: the board's core runs at N MHz, its ticks can run late.
  uint32_t devboard_core_mhz = 0;
  // --rc crsf: the pilot flies through a radio (CRSF frames at 150 Hz on the receiver line, armed
  // by its switch; the pilot parameter set to the radio), the PC link keeping the rest.
  bool radio = false;
  // --esc dshot: the engines go out as DShot frames to simulated ESCs that answer with their eRPM.
  bool dshot = false;
  // --sensors drivers (the default): the MPU-6050 and the MS5611 are register-level chips on the sim
  // board's I2C bus, read by the firmware's drivers (qr/core/sensor_stage.hpp); direct (false): the
  // board hands the firmware the plant's sample. On the devboard the sensor link carries the bus
  // (qr/boards/sim/devboard_qr.hpp) or the samples.
  bool sensor_drivers = true;
  // Called every control period with the firmware's view before its tick (qrsim --autotune's log).
  std::function<void(double t, const FirmwareView& view)> on_tick;
};

struct Figure {
  std::string name;
  double value;
};

struct CheckResult {
  std::string band;  // e.g. "rise_s < 0.3"
  bool pass;
};

struct ScenarioResult {
  std::string scenario;
  std::string vehicle;
  std::string firmware = "host";  // "rv32": the devboard's binary flew
  std::string error;              // non-empty: the flight never got to its manoeuvre, or a turn was refused
  std::string final_mode;
  std::string known_failure;    // the scenario's, copied
  std::vector<Figure> figures;  // in print order
  std::vector<CheckResult> checks;
  // What the flight did otherwise than the file says, for the user to know (a stick beyond full
  // stick, clamped): "at 2 s: roll 45 deg asks for more than max_tilt_mrad allows (30 deg): ...".
  std::vector<std::string> notes;
  bool pass = false;

  double figure(const std::string& name) const;
};

ScenarioResult run_scenario(const ScenarioScript& script, const RunOptions& options);

// A built-in scenario by name, or else a scenario file by path.
bool find_scenario(const std::string& name_or_path, ScenarioScript& out, std::string& error);

const char* mode_name(uint8_t mode);  // "safe", "panic", ... as the figures name them

// One JSON object on one line.
std::string to_json(const ScenarioResult& result);

}  // namespace qrsim
