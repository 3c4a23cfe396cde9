// Helpers shared by the simulator's tests.
#pragma once

#include <stdint.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <sim/quadrotor.hpp>
#include <sim/vehicle.hpp>

namespace sim_test {

// The default vehicle with a perfect IMU: no bias, no scale error, optionally no noise and no
// vibration, so a reading can be compared with the truth count for count.
inline sim::VehicleParams ideal_imu(sim::VehicleParams v, bool noise = false, bool vibration = false) {
  v.gyro_bias_dps = 0;
  v.accel_bias_xy_mg = 0;
  v.accel_bias_z_mg = 0;
  v.scale_error = 0;
  if (!noise) {
    v.gyro_noise_dps_rthz = 0;
    v.accel_noise_ug_rthz = 0;
  }
  if (!vibration) {
    v.vibration_accel_g = {};
    v.vibration_gyro_dps = {};
  }
  return v;
}

// Far above the ground, level, at rest, every rotor already at `speed` and commanded to stay.
inline void place_in_air(sim::Quadrotor& plant, double speed, double height = 100) {
  sim::PlantState s;
  s.position = {0, 0, -height};
  s.rotor_speed = {speed, speed, speed, speed};
  plant.set_state(s);
  const uint16_t e = static_cast<uint16_t>(std::lround(plant.steady_command(speed)));
  plant.set_engines({e, e, e, e});
}

inline void run(sim::Quadrotor& plant, double seconds, double dt = 125e-6) {
  const long steps = std::lround(seconds / dt);
  for (long i = 0; i < steps; ++i) plant.step(dt);
}

// A CSV file (a scenario's trace, a recording, a replay) as rows of named fields.
inline std::vector<std::map<std::string, std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::map<std::string, std::string> row;
    for (size_t i = 0; i < names.size() && std::getline(fields, row[names[i]], ','); ++i) {
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace sim_test
