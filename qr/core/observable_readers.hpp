// Where each observable of the shared table (common/observable_table.hpp) is read in the flight:
// one source per id, in the table's order: a reader and the index it reads (axis, engine),
// returning the value in the row's wire units (saturated to 16 bits by the stream). Readers are
// shared by the rows of one kind, so the table costs the image little. A template over the
// flight so tests can stream from a flight with a scripted chain.
#pragma once

#include <stdint.h>

#include <common/observable_table.hpp>
#include <common/units.hpp>

namespace qr {

template <class Flight>
struct ObservableSource {
  int32_t (*read)(const Flight&, uint8_t index);
  uint8_t index;
};

template <class Flight>
struct ObservableRead {
  static int32_t angle(const Flight& f, uint8_t i) {
    return i == 0 ? f.chain().roll_e4() : i == 1 ? f.chain().pitch_e4() : f.chain().yaw_e4();
  }
  static int32_t rate(const Flight& f, uint8_t i) {
    return i == 0 ? f.chain().p_e3() : i == 1 ? f.chain().q_e3() : f.chain().r_e3();
  }
  static int32_t setpoint(const Flight& f, uint8_t i) {
    return i == 0   ? f.chain().roll_setpoint_e4()
           : i == 1 ? f.chain().pitch_setpoint_e4()
           : i == 2 ? f.chain().yaw_rate_setpoint_e3()
                    : f.controls().lift;
  }
  static int32_t engine(const Flight& f, uint8_t i) { return f.engines().value[i]; }
  static int32_t gyro(const Flight& f, uint8_t i) { return f.sample().gyro[i]; }
  static int32_t accel(const Flight& f, uint8_t i) { return f.sample().accel[i]; }
  static int32_t gyro_filtered(const Flight& f, uint8_t i) { return f.chain().gyro_filtered(i); }
  static int32_t accel_filtered(const Flight& f, uint8_t i) { return f.chain().accel_filtered(i); }
  static int32_t state(const Flight& f, uint8_t i) {
    return i == 0   ? int32_t{f.sample().battery_mv}
           : i == 1 ? f.chain().height_mm()
           : i == 2 ? f.chain().climb_mm_s()
           : i == 3 ? f.chain().tilt_mrad()
           : i == 4 ? static_cast<int32_t>(wire::saturate_u16(f.last_busy_us()))
                    : static_cast<int32_t>((f.tick_us() / 1000u) & 0xFFFFu);
  }
  // The controllers' terms, as the loops last formed them (the chain's read-outs).
  static int32_t rate_setpoint(const Flight& f, uint8_t i) { return f.chain().rate_setpoint_e3(i); }
  static int32_t p_term(const Flight& f, uint8_t i) { return f.chain().p_term_e1(i); }
  static int32_t d_term(const Flight& f, uint8_t i) { return f.chain().d_term_e1(i); }
  static int32_t integral(const Flight& f, uint8_t i) { return f.chain().integral_e1(i); }
  static int32_t moment(const Flight& f, uint8_t i) { return f.chain().moment_e1(i); }
  static int32_t vertical(const Flight& f, uint8_t i) {
    return i == 0   ? f.chain().climb_setpoint_mm_s()
           : i == 1 ? f.chain().vertical_p_term_mm_s2()
           : i == 2 ? f.chain().vertical_integral_mm_s2()
                    : f.chain().vertical_thrust_e1();
  }
  // A task's last run as the scheduler measured it (0 before the first tick's accounting).
  static int32_t task_cycles(const Flight& f, uint8_t i) {
    const auto* stats = f.task_stats();
    return stats == nullptr ? 0 : static_cast<int32_t>(wire::saturate_u16(stats->task[i].last));
  }
  static int32_t rpm(const Flight& f, uint8_t i) { return f.engine_rpm(i); }
};

template <class Flight>
inline constexpr ObservableSource<Flight> kObservableSources[wire::kObservableCount] = {
    {ObservableRead<Flight>::angle, 0},
    {ObservableRead<Flight>::angle, 1},
    {ObservableRead<Flight>::angle, 2},
    {ObservableRead<Flight>::rate, 0},
    {ObservableRead<Flight>::rate, 1},
    {ObservableRead<Flight>::rate, 2},
    {ObservableRead<Flight>::setpoint, 0},
    {ObservableRead<Flight>::setpoint, 1},
    {ObservableRead<Flight>::setpoint, 2},
    {ObservableRead<Flight>::setpoint, 3},
    {ObservableRead<Flight>::engine, 0},
    {ObservableRead<Flight>::engine, 1},
    {ObservableRead<Flight>::engine, 2},
    {ObservableRead<Flight>::engine, 3},
    {ObservableRead<Flight>::gyro, 0},
    {ObservableRead<Flight>::gyro, 1},
    {ObservableRead<Flight>::gyro, 2},
    {ObservableRead<Flight>::accel, 0},
    {ObservableRead<Flight>::accel, 1},
    {ObservableRead<Flight>::accel, 2},
    {ObservableRead<Flight>::gyro_filtered, 0},
    {ObservableRead<Flight>::gyro_filtered, 1},
    {ObservableRead<Flight>::gyro_filtered, 2},
    {ObservableRead<Flight>::accel_filtered, 0},
    {ObservableRead<Flight>::accel_filtered, 1},
    {ObservableRead<Flight>::accel_filtered, 2},
    {ObservableRead<Flight>::state, 0},
    {ObservableRead<Flight>::state, 1},
    {ObservableRead<Flight>::state, 2},
    {ObservableRead<Flight>::state, 3},
    {ObservableRead<Flight>::state, 4},
    {ObservableRead<Flight>::state, 5},
    {ObservableRead<Flight>::rate_setpoint, 0},
    {ObservableRead<Flight>::rate_setpoint, 1},
    {ObservableRead<Flight>::p_term, 0},
    {ObservableRead<Flight>::d_term, 0},
    {ObservableRead<Flight>::integral, 0},
    {ObservableRead<Flight>::p_term, 1},
    {ObservableRead<Flight>::d_term, 1},
    {ObservableRead<Flight>::integral, 1},
    {ObservableRead<Flight>::p_term, 2},
    {ObservableRead<Flight>::integral, 2},
    {ObservableRead<Flight>::moment, 0},
    {ObservableRead<Flight>::moment, 1},
    {ObservableRead<Flight>::moment, 2},
    {ObservableRead<Flight>::vertical, 0},
    {ObservableRead<Flight>::vertical, 1},
    {ObservableRead<Flight>::vertical, 2},
    {ObservableRead<Flight>::vertical, 3},
    {ObservableRead<Flight>::task_cycles, 0},
    {ObservableRead<Flight>::task_cycles, 1},
    {ObservableRead<Flight>::task_cycles, 2},
    {ObservableRead<Flight>::task_cycles, 3},
    {ObservableRead<Flight>::task_cycles, 4},
    {ObservableRead<Flight>::task_cycles, 5},
    {ObservableRead<Flight>::task_cycles, 6},
    {ObservableRead<Flight>::task_cycles, 7},
    {ObservableRead<Flight>::task_cycles, 8},
    {ObservableRead<Flight>::task_cycles, 9},
    {ObservableRead<Flight>::task_cycles, 10},
    {ObservableRead<Flight>::task_cycles, 11},
    {ObservableRead<Flight>::task_cycles, 12},
    {ObservableRead<Flight>::task_cycles, 13},
    {ObservableRead<Flight>::task_cycles, 14},
    {ObservableRead<Flight>::rpm, 0},
    {ObservableRead<Flight>::rpm, 1},
    {ObservableRead<Flight>::rpm, 2},
    {ObservableRead<Flight>::rpm, 3},
};

template <class Flight>
constexpr bool every_observable_has_a_reader() {
  for (const ObservableSource<Flight>& source : kObservableSources<Flight>) {
    if (source.read == nullptr) return false;
  }
  // The cycle rows read task i's statistics in the wire's task order (observable_table.hpp).
  for (uint8_t task = 0; task < wire::kTaskCount; ++task) {
    const ObservableSource<Flight>& source = kObservableSources<Flight>[wire::kFirstTaskCyclesObservable + task];
    if (source.read != ObservableRead<Flight>::task_cycles || source.index != task) return false;
  }
  return true;
}

template <class Flight>
int32_t read_observable(const Flight& f, uint8_t id) {
  const ObservableSource<Flight>& source = kObservableSources<Flight>[id];
  return source.read(f, source.index);
}

// The 16 bits a value travels as: saturated to the row's type, a u16 carried in the same bits.
constexpr int16_t observable_bits(wire::ObservableType type, int32_t value) {
  if (type == wire::ObservableType::i16) return wire::saturate_i16(value);
  return static_cast<int16_t>(wire::saturate_u16(value < 0 ? 0u : static_cast<uint32_t>(value)));
}

}  // namespace qr
