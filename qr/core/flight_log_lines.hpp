// One line of each log, assembled from the flight's read-outs at the tick the logger runs:
// the sensor line (raw and filtered sensors) and the telemetry line (mode, set-points, attitude,
// rates, engines, timing). Formats: common/log_records.hpp.
#pragma once

#include <common/log_records.hpp>
#include <common/units.hpp>

namespace qr {

template <class Flight>
wire::SensorLogRecord sensor_log_line(const Flight& f) {
  wire::SensorLogRecord s;
  s.time_us = f.tick_us();
  for (int axis = 0; axis < 3; ++axis) {
    s.gyro[axis] = f.sample().gyro[axis];
    s.accel[axis] = f.sample().accel[axis];
    s.gyro_filtered[axis] = f.chain().gyro_filtered(axis);
    s.accel_filtered[axis] = f.chain().accel_filtered(axis);
  }
  s.battery_mv = f.sample().battery_mv;
  return s;
}

template <class Flight>
wire::TelemetryLogRecord telemetry_log_line(const Flight& f) {
  const auto& chain = f.chain();
  wire::TelemetryLogRecord t;
  t.time_us = f.tick_us();
  t.mode = f.mode();
  t.flags = f.telemetry_flags();
  t.lift = f.controls().lift;
  t.roll = chain.roll_setpoint_e4();
  t.pitch = chain.pitch_setpoint_e4();
  t.yaw_rate = chain.yaw_rate_setpoint_e3();
  t.phi = chain.roll_e4();
  t.theta = chain.pitch_e4();
  t.psi = chain.yaw_e4();
  t.p = chain.p_e3();
  t.q = chain.q_e3();
  t.r = chain.r_e3();
  for (int i = 0; i < 4; ++i) t.engine[i] = f.engines().value[i];
  t.loop_time_us = wire::saturate_u16(f.last_busy_us());
  t.battery_mv = f.sample().battery_mv;
  t.cpu_load = f.telemetry().cpu_load_permille();
  t.deadline_misses = static_cast<uint16_t>(f.telemetry().deadline_misses());
  return t;
}

}  // namespace qr
