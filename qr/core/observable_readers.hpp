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
};

template <class Flight>
inline constexpr ObservableSource<Flight> kObservableSources[wire::kObservableCount] = {
    {ObservableRead<Flight>::angle, 0},          {ObservableRead<Flight>::angle, 1},
    {ObservableRead<Flight>::angle, 2},          {ObservableRead<Flight>::rate, 0},
    {ObservableRead<Flight>::rate, 1},           {ObservableRead<Flight>::rate, 2},
    {ObservableRead<Flight>::setpoint, 0},       {ObservableRead<Flight>::setpoint, 1},
    {ObservableRead<Flight>::setpoint, 2},       {ObservableRead<Flight>::setpoint, 3},
    {ObservableRead<Flight>::engine, 0},         {ObservableRead<Flight>::engine, 1},
    {ObservableRead<Flight>::engine, 2},         {ObservableRead<Flight>::engine, 3},
    {ObservableRead<Flight>::gyro, 0},           {ObservableRead<Flight>::gyro, 1},
    {ObservableRead<Flight>::gyro, 2},           {ObservableRead<Flight>::accel, 0},
    {ObservableRead<Flight>::accel, 1},          {ObservableRead<Flight>::accel, 2},
    {ObservableRead<Flight>::gyro_filtered, 0},  {ObservableRead<Flight>::gyro_filtered, 1},
    {ObservableRead<Flight>::gyro_filtered, 2},  {ObservableRead<Flight>::accel_filtered, 0},
    {ObservableRead<Flight>::accel_filtered, 1}, {ObservableRead<Flight>::accel_filtered, 2},
    {ObservableRead<Flight>::state, 0},          {ObservableRead<Flight>::state, 1},
    {ObservableRead<Flight>::state, 2},          {ObservableRead<Flight>::state, 3},
    {ObservableRead<Flight>::state, 4},          {ObservableRead<Flight>::state, 5},
};

template <class Flight>
constexpr bool every_observable_has_a_reader() {
  for (const ObservableSource<Flight>& source : kObservableSources<Flight>) {
    if (source.read == nullptr) return false;
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
