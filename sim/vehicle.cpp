#include <sim/vehicle.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

namespace sim {
namespace {

using Field = double& (*)(VehicleParams&);

struct ParamRow {
  const char* name;
  Field field;
  bool optional = false;  // may be missing: the field keeps VehicleParams' default
};

// The file's vocabulary. Names carry their unit where it is not obvious.
constexpr ParamRow kRows[] = {
    {"mass_kg", [](VehicleParams& v) -> double& { return v.mass_kg; }},
    {"inertia_xx_kgm2", [](VehicleParams& v) -> double& { return v.inertia_kgm2.x; }},
    {"inertia_yy_kgm2", [](VehicleParams& v) -> double& { return v.inertia_kgm2.y; }},
    {"inertia_zz_kgm2", [](VehicleParams& v) -> double& { return v.inertia_kgm2.z; }},
    {"arm_m", [](VehicleParams& v) -> double& { return v.arm_m; }},
    {"hub_height_m", [](VehicleParams& v) -> double& { return v.hub_height_m; }},
    {"body_drag_area_x_m2", [](VehicleParams& v) -> double& { return v.body_drag_area_m2.x; }},
    {"body_drag_area_y_m2", [](VehicleParams& v) -> double& { return v.body_drag_area_m2.y; }},
    {"body_drag_area_z_m2", [](VehicleParams& v) -> double& { return v.body_drag_area_m2.z; }},
    {"thrust_coeff", [](VehicleParams& v) -> double& { return v.thrust_coeff; }},
    {"torque_coeff", [](VehicleParams& v) -> double& { return v.torque_coeff; }},
    {"rotor_inertia_kgm2", [](VehicleParams& v) -> double& { return v.rotor_inertia; }},
    {"rotor_drag_coeff", [](VehicleParams& v) -> double& { return v.rotor_drag_coeff; }},
    {"motor_kv_rpm_per_v", [](VehicleParams& v) -> double& { return v.motor_kv_rpm_per_v; }},
    {"motor_load_factor", [](VehicleParams& v) -> double& { return v.motor_load_factor; }},
    {"motor_tau_up_s", [](VehicleParams& v) -> double& { return v.motor_tau_up_s; }},
    {"motor_tau_down_s", [](VehicleParams& v) -> double& { return v.motor_tau_down_s; }},
    {"powertrain_efficiency", [](VehicleParams& v) -> double& { return v.powertrain_efficiency; }},
    {"battery_cells", [](VehicleParams& v) -> double& { return v.battery_cells; }},
    {"battery_capacity_mah", [](VehicleParams& v) -> double& { return v.battery_capacity_mah; }},
    {"battery_resistance_ohm", [](VehicleParams& v) -> double& { return v.battery_resistance_ohm; }},
    {"battery_initial_soc", [](VehicleParams& v) -> double& { return v.battery_initial_soc; }},
    {"avionics_current_a", [](VehicleParams& v) -> double& { return v.avionics_current_a; }},
    {"foot_radius_m", [](VehicleParams& v) -> double& { return v.foot_radius_m; }},
    {"foot_depth_m", [](VehicleParams& v) -> double& { return v.foot_depth_m; }},
    {"top_height_m", [](VehicleParams& v) -> double& { return v.top_height_m; }},
    {"contact_stiffness_n_per_m", [](VehicleParams& v) -> double& { return v.contact_stiffness; }},
    {"contact_damping_ns_per_m", [](VehicleParams& v) -> double& { return v.contact_damping; }},
    {"ground_friction", [](VehicleParams& v) -> double& { return v.ground_friction; }},
    {"vibration_ref_speed_rad_s", [](VehicleParams& v) -> double& { return v.vibration_ref_speed; }},
    {"vibration_accel_h1_g", [](VehicleParams& v) -> double& { return v.vibration_accel_g.x; }},
    {"vibration_accel_h2_g", [](VehicleParams& v) -> double& { return v.vibration_accel_g.y; }},
    {"vibration_accel_h3_g", [](VehicleParams& v) -> double& { return v.vibration_accel_g.z; }},
    {"vibration_accel_z_ratio", [](VehicleParams& v) -> double& { return v.vibration_accel_z_ratio; }},
    {"vibration_gyro_h1_dps", [](VehicleParams& v) -> double& { return v.vibration_gyro_dps.x; }},
    {"vibration_gyro_h2_dps", [](VehicleParams& v) -> double& { return v.vibration_gyro_dps.y; }},
    {"vibration_gyro_h3_dps", [](VehicleParams& v) -> double& { return v.vibration_gyro_dps.z; }},
    {"gyro_noise_dps_rthz", [](VehicleParams& v) -> double& { return v.gyro_noise_dps_rthz; }},
    {"accel_noise_ug_rthz", [](VehicleParams& v) -> double& { return v.accel_noise_ug_rthz; }},
    {"imu_bandwidth_hz", [](VehicleParams& v) -> double& { return v.imu_bandwidth_hz; }},
    {"gyro_bias_dps", [](VehicleParams& v) -> double& { return v.gyro_bias_dps; }},
    {"accel_bias_xy_mg", [](VehicleParams& v) -> double& { return v.accel_bias_xy_mg; }},
    {"accel_bias_z_mg", [](VehicleParams& v) -> double& { return v.accel_bias_z_mg; }},
    {"imu_scale_error", [](VehicleParams& v) -> double& { return v.scale_error; }},
    {"battery_sense_noise_mv", [](VehicleParams& v) -> double& { return v.battery_sense_noise_mv; }},
    {"battery_sense_lsb_mv", [](VehicleParams& v) -> double& { return v.battery_sense_lsb_mv; }},
    // Optional: vehicle files older than the barometer do not name them.
    {"baro_noise_pa", [](VehicleParams& v) -> double& { return v.baro_noise_pa; }, true},
    {"baro_temp_coeff_pa_per_k", [](VehicleParams& v) -> double& { return v.baro_temp_coeff_pa_per_k; }, true},
    {"baro_warmup_k", [](VehicleParams& v) -> double& { return v.baro_warmup_k; }, true},
    {"baro_warmup_tau_s", [](VehicleParams& v) -> double& { return v.baro_warmup_tau_s; }, true},
};
constexpr size_t kRowCount = std::size(kRows);

std::string trim(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const size_t last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

// Physical sanity: a file that parses but describes no vehicle that can fly is an error too.
bool check(const VehicleParams& v, std::string& error) {
  struct Rule {
    bool ok;
    const char* what;
  };
  const Rule rules[] = {
      {v.mass_kg > 0, "mass_kg must be > 0"},
      {v.inertia_kgm2.x > 0 && v.inertia_kgm2.y > 0 && v.inertia_kgm2.z > 0, "inertias must be > 0"},
      {v.arm_m > 0, "arm_m must be > 0"},
      {v.thrust_coeff > 0 && v.torque_coeff > 0, "thrust and torque coefficients must be > 0"},
      {v.motor_kv_rpm_per_v > 0 && v.motor_load_factor > 0 && v.motor_load_factor <= 1,
       "motor_kv_rpm_per_v > 0 and 0 < motor_load_factor <= 1"},
      {v.motor_tau_up_s > 0 && v.motor_tau_down_s > 0, "motor time constants must be > 0"},
      {v.powertrain_efficiency > 0 && v.powertrain_efficiency <= 1, "0 < powertrain_efficiency <= 1"},
      {v.battery_cells >= 1 && v.battery_cells == std::floor(v.battery_cells), "battery_cells: a whole number >= 1"},
      {v.battery_capacity_mah > 0, "battery_capacity_mah must be > 0"},
      {v.battery_initial_soc > 0 && v.battery_initial_soc <= 1, "0 < battery_initial_soc <= 1"},
      {v.contact_stiffness > 0 && v.contact_damping >= 0, "contact stiffness > 0, damping >= 0"},
      {v.foot_depth_m > 0 && v.foot_radius_m > 0, "feet must be below and away from the centre"},
      {v.imu_bandwidth_hz > 0, "imu_bandwidth_hz must be > 0"},
      {v.battery_sense_lsb_mv > 0, "battery_sense_lsb_mv must be > 0"},
      {v.baro_noise_pa >= 0 && v.baro_warmup_tau_s > 0, "baro_noise_pa >= 0 and baro_warmup_tau_s > 0"},
  };
  for (const Rule& r : rules) {
    if (!r.ok) {
      error = r.what;
      return false;
    }
  }
  return true;
}

}  // namespace

double VehicleParams::hover_speed() const { return std::sqrt(mass_kg * 9.80665 / (4 * thrust_coeff)); }

bool parse_vehicle(const std::string& text, VehicleParams& out, std::string& error) {
  VehicleParams v;
  bool seen[kRowCount] = {};
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string content = trim(line.substr(0, line.find('#')));
    if (content.empty()) continue;
    const size_t eq = content.find('=');
    if (eq == std::string::npos) {
      error = "line " + std::to_string(number) + ": expected `name = value`";
      return false;
    }
    const std::string name = trim(content.substr(0, eq));
    const std::string value = trim(content.substr(eq + 1));
    if (is_wiring_name(name)) {
      if (!parse_wiring_row(name, value, v.wiring, error)) {
        error = "line " + std::to_string(number) + ": " + error;
        return false;
      }
      continue;
    }
    size_t row = 0;
    while (row < kRowCount && name != kRows[row].name) ++row;
    if (row == kRowCount) {
      error = "line " + std::to_string(number) + ": unknown parameter `" + name + "`";
      return false;
    }
    char* end = nullptr;
    const double parsed = std::strtod(value.c_str(), &end);
    if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(parsed)) {
      error = "line " + std::to_string(number) + ": `" + value + "` is not a number";
      return false;
    }
    if (seen[row]) {
      error = "line " + std::to_string(number) + ": `" + name + "` given twice";
      return false;
    }
    seen[row] = true;
    kRows[row].field(v) = parsed;
  }
  for (size_t row = 0; row < kRowCount; ++row) {
    if (!seen[row] && !kRows[row].optional) {
      error = std::string("missing parameter `") + kRows[row].name + "`";
      return false;
    }
  }
  if (!check(v, error)) return false;
  out = v;
  return true;
}

bool load_vehicle_file(const std::string& path, VehicleParams& out, std::string& error) {
  std::ifstream file(path);
  if (!file) {
    error = "cannot open " + path;
    return false;
  }
  std::ostringstream text;
  text << file.rdbuf();
  if (!parse_vehicle(text.str(), out, error)) {
    error = path + ": " + error;
    return false;
  }
  return true;
}

VehicleParams default_vehicle() {
  VehicleParams v;
  std::string error;
  if (!parse_vehicle(default_vehicle_text(), v, error)) std::abort();  // a build-time file: tested
  return v;
}

}  // namespace sim
