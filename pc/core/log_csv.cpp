#include <pc/core/log_csv.hpp>

namespace qrterm {

// Each column name ends in its unit (docs/protocol.md section 8): values stay the wire's integers,
// so a reader needs no table to know what 1 means.
std::vector<std::string> log_header(const wire::SensorLogRecord&) {
  return {"line",
          "time_us",
          "gyro_x_counts",
          "gyro_y_counts",
          "gyro_z_counts",
          "accel_x_counts",
          "accel_y_counts",
          "accel_z_counts",
          "gyro_filtered_x_counts",
          "gyro_filtered_y_counts",
          "gyro_filtered_z_counts",
          "accel_filtered_x_counts",
          "accel_filtered_y_counts",
          "accel_filtered_z_counts",
          "battery_mv"};
}

std::vector<std::string> log_header(const wire::TelemetryLogRecord&) {
  return {"line",
          "time_us",
          "mode",
          "flags",
          "lift_sp_0to1000",
          "roll_sp_1e-4rad",
          "pitch_sp_1e-4rad",
          "yaw_rate_sp_1e-3rad_s",
          "phi_1e-4rad",
          "theta_1e-4rad",
          "psi_1e-4rad",
          "p_1e-3rad_s",
          "q_1e-3rad_s",
          "r_1e-3rad_s",
          "engine_front_0to1000",
          "engine_right_0to1000",
          "engine_back_0to1000",
          "engine_left_0to1000",
          "loop_time_us",
          "battery_mv",
          "cpu_load_permille",
          "deadline_misses"};
}

}  // namespace qrterm
