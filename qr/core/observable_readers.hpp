// Where each observable of the shared table (common/observable_table.hpp) is read in the flight:
// one line per observable in observable_source() below, keyed by the observable's id, so a line
// cannot stand in the wrong place (the lines may come in any order) and a table row without one
// does not compile. A line says what the observable samples, in the flight's own numbers:
//   - a number of the chain's (its Numbers: a Q format in flight; an angle in rad, a rate in
//     rad/s, a moment in thrust units), which observe() converts by the row's scale (value in the
//     row's unit = wire value x 10^scale), or
//   - an integer already in the row's units (raw counts, engine units, mV, us, cycles, rpm, CRSF
//     channel units, and the safety machine's tilt_mrad and height_mm), which it takes as it is;
// then saturated to the row's 16-bit type. observe<id>(flight) is that value as it travels.
// Telemetry, the logs and the simulator's view read the observable where they carry the same
// quantity, so the conversion to wire units is written once, here, from the table's scale.
//
// The stream's run-time readers (read_observable) are made from the table's own list of rows, so
// row i is observable i's reader by construction. Templates over the flight, so tests can read
// from a flight with a scripted chain.
#pragma once

#include <stdint.h>

#include <common/drivers/crsf.hpp>
#include <common/observable_table.hpp>
#include <common/units.hpp>
#include <qr/core/chain/decimal_units.hpp>

namespace qr {

namespace observable_detail {
// Integers are in their row's units already; anything else is a number of the chain's.
template <class T>
inline constexpr bool kInteger = false;
template <>
inline constexpr bool kInteger<int16_t> = true;
template <>
inline constexpr bool kInteger<uint16_t> = true;
template <>
inline constexpr bool kInteger<int32_t> = true;
template <>
inline constexpr bool kInteger<uint32_t> = true;

template <wire::ObservableId>
inline constexpr bool kNoReader = false;

// An integer in the row's units into its 16-bit type: an i16 row saturates, a u16 row also takes
// a negative value as 0.
template <wire::ObservableType Type, class T>
constexpr auto fit(T value) {
  constexpr bool kSigned = T(-1) < T(0);
  if constexpr (Type == wire::ObservableType::i16) {
    static_assert(kSigned || sizeof(T) < sizeof(int32_t), "an unsigned 32-bit value for an i16 row");
    return wire::saturate_i16(static_cast<int32_t>(value));
  } else if constexpr (kSigned) {
    return wire::saturate_u16(value < 0 ? 0u : static_cast<uint32_t>(value));
  } else {
    return wire::saturate_u16(static_cast<uint32_t>(value));
  }
}

// A number of the chain's in a row's units and type.
template <wire::ObservableType Type, int Digits, class Numbers, class T>
constexpr auto converted(T value) {
  return fit<Type>(chain::in_decimal_units<Digits, Numbers>(value));
}
// The same out of line, for the stream's readers: one copy for all rows of a number type and
// scale (the three angles, the three rates, ...), where each row's reader inlined its own.
template <wire::ObservableType Type, int Digits, class Numbers, class T>
[[gnu::noinline, gnu::cold]] int32_t converted_out_of_line(T value) {
  return converted<Type, Digits, Numbers>(value);
}

// A task's last run as the scheduler measured it, saturated (0 before the first tick's
// accounting). Out of line: fifteen rows share it.
template <class Flight>
[[gnu::noinline, gnu::cold]] uint16_t task_cycles(const Flight& f, uint8_t task) {
  const auto* stats = f.task_stats();
  return stats == nullptr ? uint16_t{0} : wire::saturate_u16(stats->task[task].last);
}
// The radio's channel as last received. Out of line: sixteen rows share it.
template <class Flight>
[[gnu::noinline, gnu::cold]] uint16_t rc_channel(const Flight& f, uint8_t ch) {
  return f.rc_channel(ch);
}
}  // namespace observable_detail

// What observable `id` samples: one line per observable of common/observable_table.hpp.
template <wire::ObservableId id, class Flight>
constexpr auto observable_source(const Flight& f) {
  using enum wire::ObservableId;
  const auto& c = f.chain();
  if constexpr (id == phi) return c.roll();
  else if constexpr (id == theta) return c.pitch();
  else if constexpr (id == psi) return c.yaw();
  else if constexpr (id == p) return c.p();
  else if constexpr (id == q) return c.q();
  else if constexpr (id == r) return c.r();
  else if constexpr (id == phi_sp) return c.roll_setpoint();
  else if constexpr (id == theta_sp) return c.pitch_setpoint();
  else if constexpr (id == r_sp) return c.yaw_rate_setpoint();
  else if constexpr (id == lift) return f.controls().lift;
  else if constexpr (id == engine_front) return f.engines().value[0];
  else if constexpr (id == engine_right) return f.engines().value[1];
  else if constexpr (id == engine_back) return f.engines().value[2];
  else if constexpr (id == engine_left) return f.engines().value[3];
  else if constexpr (id == gyro_x) return f.sample().gyro[0];
  else if constexpr (id == gyro_y) return f.sample().gyro[1];
  else if constexpr (id == gyro_z) return f.sample().gyro[2];
  else if constexpr (id == accel_x) return f.sample().accel[0];
  else if constexpr (id == accel_y) return f.sample().accel[1];
  else if constexpr (id == accel_z) return f.sample().accel[2];
  else if constexpr (id == gyro_x_f) return c.gyro_filtered(0);
  else if constexpr (id == gyro_y_f) return c.gyro_filtered(1);
  else if constexpr (id == gyro_z_f) return c.gyro_filtered(2);
  else if constexpr (id == accel_x_f) return c.accel_filtered(0);
  else if constexpr (id == accel_y_f) return c.accel_filtered(1);
  else if constexpr (id == accel_z_f) return c.accel_filtered(2);
  else if constexpr (id == battery) return f.sample().battery_mv;
  else if constexpr (id == height) return c.height_mm();
  else if constexpr (id == climb) return c.climb();
  else if constexpr (id == tilt) return c.tilt_mrad();
  else if constexpr (id == tick_busy) return f.last_busy_us();
  else if constexpr (id == time_ms) return (f.tick_us() / 1000u) & 0xFFFFu;
  else if constexpr (id == p_sp) return c.rate_setpoint(0);
  else if constexpr (id == q_sp) return c.rate_setpoint(1);
  else if constexpr (id == roll_p_term) return c.p_term(0);
  else if constexpr (id == roll_d_term) return c.d_term(0);
  else if constexpr (id == roll_integral) return c.integral(0);
  else if constexpr (id == pitch_p_term) return c.p_term(1);
  else if constexpr (id == pitch_d_term) return c.d_term(1);
  else if constexpr (id == pitch_integral) return c.integral(1);
  else if constexpr (id == yaw_p_term) return c.p_term(2);
  else if constexpr (id == yaw_integral) return c.integral(2);
  else if constexpr (id == roll_moment) return c.moment(0);
  else if constexpr (id == pitch_moment) return c.moment(1);
  else if constexpr (id == yaw_moment) return c.moment(2);
  else if constexpr (id == climb_sp) return c.climb_setpoint();
  else if constexpr (id == vertical_p_term) return c.vertical_p_term();
  else if constexpr (id == vertical_integral) return c.vertical_integral();
  else if constexpr (id == vertical_thrust) return c.vertical_thrust();
  // cycles_<task>: one row per task in the wire's task order (observable_table.hpp asserts it).
  else if constexpr (static_cast<uint8_t>(id) >= wire::kFirstTaskCyclesObservable &&
                     static_cast<uint8_t>(id) < wire::kFirstTaskCyclesObservable + wire::kTaskCount)
    return observable_detail::task_cycles(f, static_cast<uint8_t>(id) - wire::kFirstTaskCyclesObservable);
  else if constexpr (id == rpm_front) return f.engine_rpm(0);
  else if constexpr (id == rpm_right) return f.engine_rpm(1);
  else if constexpr (id == rpm_back) return f.engine_rpm(2);
  else if constexpr (id == rpm_left) return f.engine_rpm(3);
  // rc_ch<N>: one row per radio channel in channel order (observable_table.hpp asserts it).
  else if constexpr (static_cast<uint8_t>(id) >= wire::kFirstRcChannelObservable &&
                     static_cast<uint8_t>(id) < wire::kFirstRcChannelObservable + drivers::kCrsfChannelCount)
    return observable_detail::rc_channel(f, static_cast<uint8_t>(id) - wire::kFirstRcChannelObservable);
  else static_assert(observable_detail::kNoReader<id>, "an observable of the table without its line here");
}

// Observable `id` as it travels: in its row's units, saturated to its row's type (int16_t for an
// i16 row, uint16_t for a u16 one).
template <wire::ObservableId id, class Flight>
constexpr auto observe(const Flight& f) {
  constexpr wire::ObservableWireRow kRow = wire::kObservableWire[static_cast<uint8_t>(id)];
  auto value = observable_source<id>(f);
  if constexpr (observable_detail::kInteger<decltype(value)>) {
    return observable_detail::fit<kRow.type>(value);
  } else {
    return observable_detail::converted<kRow.type, -kRow.scale, typename Flight::ChainType::Numbers>(value);
  }
}

// The stream's readers, indexed by id: one per row of the table's own list. The same values as
// observe(), compiled for size (the stream reads a few observables a tick at most).
template <class Flight>
using ObservableReader = int32_t (*)(const Flight&);

template <wire::ObservableId id, class Flight>
[[gnu::cold]] int32_t read_observable_row(const Flight& f) {
  constexpr wire::ObservableWireRow kRow = wire::kObservableWire[static_cast<uint8_t>(id)];
  auto value = observable_source<id>(f);
  if constexpr (observable_detail::kInteger<decltype(value)>) {
    return observable_detail::fit<kRow.type>(value);
  } else {
    using Numbers = typename Flight::ChainType::Numbers;
    return observable_detail::converted_out_of_line<kRow.type, -kRow.scale, Numbers>(value);
  }
}

template <class Flight>
inline constexpr ObservableReader<Flight> kObservableReaders[wire::kObservableCount] = {
#define QR_OBSERVABLE_READER(name, id, unit, type, scale, meaning) \
  &read_observable_row<wire::ObservableId::name, Flight>,
    WIRE_OBSERVABLE_ROWS(QR_OBSERVABLE_READER)
#undef QR_OBSERVABLE_READER
};

template <class Flight>
int32_t read_observable(const Flight& f, uint8_t id) {
  const ObservableReader<Flight> read = kObservableReaders<Flight>[id];
  return read(f);
}

// The 16 bits a value travels as: saturated to the row's type, a u16 carried in the same bits.
constexpr int16_t observable_bits(wire::ObservableType type, int32_t value) {
  if (type == wire::ObservableType::i16) return wire::saturate_i16(value);
  return static_cast<int16_t>(wire::saturate_u16(value < 0 ? 0u : static_cast<uint32_t>(value)));
}

}  // namespace qr
