// One line of each log, assembled from the flight's read-outs at the tick the logger runs:
// the sensor line (raw and filtered sensors) and the telemetry line (mode, set-points, attitude,
// rates, engines, timing). Formats: common/log_records.hpp. The set-points, attitude and rates are
// those observables' values (observable_readers.hpp), as telemetry sends them.
#pragma once

#include <common/log_records.hpp>
#include <common/units.hpp>
#include <qr/core/observable_readers.hpp>

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
  using Id = wire::ObservableId;
  wire::TelemetryLogRecord t;
  t.time_us = f.tick_us();
  t.mode = f.mode();
  t.flags = f.telemetry_flags();
  t.lift = f.controls().lift;
  t.roll = observe<Id::phi_sp>(f);
  t.pitch = observe<Id::theta_sp>(f);
  t.yaw_rate = observe<Id::r_sp>(f);
  t.phi = observe<Id::phi>(f);
  t.theta = observe<Id::theta>(f);
  t.psi = observe<Id::psi>(f);
  t.p = observe<Id::p>(f);
  t.q = observe<Id::q>(f);
  t.r = observe<Id::r>(f);
  for (int i = 0; i < 4; ++i) t.engine[i] = f.engines().value[i];
  t.loop_time_us = wire::saturate_u16(f.last_busy_us());
  t.battery_mv = f.sample().battery_mv;
  t.cpu_load = f.telemetry().cpu_load_permille();
  t.deadline_misses = static_cast<uint16_t>(f.telemetry().deadline_misses());
  return t;
}

}  // namespace qr
