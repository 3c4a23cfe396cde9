// Headless flights: the QR firmware in the simulated world, flown by the simulated pilot through
// the wire, scored against pass bands. Every scenario starts the same way (calibrate on the
// ground, full control with neutral sticks, lift to 1.5 m and hover), then does its manoeuvre.
// The scenarios are rows of a table (scenario.cpp); docs/simulator.md lists them with their bands.
#pragma once

#include <stdint.h>

#include <string>
#include <utility>
#include <vector>

#include <common/parameter_table.hpp>
#include <sim/vehicle.hpp>

namespace qrsim {

enum class Manoeuvre : uint8_t {
  none,            // hover
  roll_step,       // amount: degrees, held hold_s
  pitch_step,      // amount: degrees, held hold_s
  yaw_rate_step,   // amount: rad/s, held to the end
  torque_impulse,  // amount: N·m about roll and pitch at once, for hold_s
  link_loss,       // the pilot's cable is pulled
  panic_request,   // the pilot hits the emergency stop
};

enum class Compare : uint8_t { below, at_most, equal };

// A pass band: figure `compare` limit. A figure that was not measured (NaN) fails.
struct Band {
  const char* figure = nullptr;
  Compare compare = Compare::below;
  double limit = 0;
};

inline constexpr int kMaxBands = 5;

struct ScenarioSpec {
  const char* name;
  const char* summary;
  Manoeuvre manoeuvre;
  double amount;
  double hold_s;
  double default_seconds;  // scored flight from the manoeuvre's start
  Band bands[kMaxBands];
};

const std::vector<ScenarioSpec>& scenarios();
const ScenarioSpec* find_scenario(const std::string& name);
const char* mode_name(uint8_t mode);  // "safe", "panic", ... as the figures name them

struct ScenarioOptions {
  std::string name = "hover";
  double seconds = 0;  // <= 0: the scenario's default
  uint64_t seed = 1;
  sim::VehicleParams vehicle = sim::default_vehicle();
  std::string vehicle_name = sim::default_vehicle_name();
  bool sensor_noise = true;  // false: perfect IMU (no noise, bias, scale error or vibration)
  std::vector<std::pair<wire::ParamId, int32_t>> parameters;  // uploaded by the pilot before flight
  std::string trace_path;  // non-empty: every control period as a CSV line (truth, estimate, engines)
  // Non-empty: the QR's sensor samples and sticks from its first calibration tick on, in the
  // replay's input format (docs/replay.md), so `qrsim --replay` can run the flight again.
  std::string record_path;
};

struct Figure {
  std::string name;
  double value;
};

struct CheckResult {
  std::string band;  // e.g. "rise_s < 0.35"
  bool pass;
};

struct ScenarioResult {
  std::string scenario;
  std::string vehicle;
  std::string error;  // non-empty: the flight never got to its manoeuvre
  std::string final_mode;
  std::vector<Figure> figures;  // in print order
  std::vector<CheckResult> checks;
  bool pass = false;

  double figure(const std::string& name) const;
};

ScenarioResult run_scenario(const ScenarioOptions& options);

// One JSON object on one line.
std::string to_json(const ScenarioResult& result);

}  // namespace qrsim
