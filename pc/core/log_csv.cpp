#include <pc/core/log_csv.hpp>

namespace qrterm {

std::vector<std::string> log_header(const wire::SensorLogRecord&) {
  return {"line",      "time_us",   "gyro_x",    "gyro_y",    "gyro_z",
          "accel_x",   "accel_y",   "accel_z",   "gyro_filtered_x", "gyro_filtered_y",
          "gyro_filtered_z", "accel_filtered_x", "accel_filtered_y", "accel_filtered_z", "battery_mv"};
}

std::vector<std::string> log_header(const wire::TelemetryLogRecord&) {
  return {"line",  "time_us",      "mode",         "flags",       "lift",        "roll",
          "pitch", "yaw_rate",     "phi",          "theta",       "psi",         "p",
          "q",     "r",            "engine_front", "engine_right", "engine_back", "engine_left",
          "loop_time_us", "battery_mv", "cpu_load", "deadline_misses"};
}

}  // namespace qrterm
