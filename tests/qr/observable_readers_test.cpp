// Each observable's reader reads what its row's name says (qr/core/observable_readers.hpp). A
// flight in a known state gives every quantity a different value: observable i's quantity holds
// 100 + i in the row's wire units (the roll estimate is 0.0100 rad, phi's; the pitch estimate
// 0.0101 rad, theta's; ...). Each row must read 100 + its id, both at run time (the stream's
// readers, read_observable) and at compile time (observe<id>, which telemetry and the logs use):
// a reader pointed at another quantity, or two readers swapped, reads another row's value.
#include <gtest/gtest.h>

#include <type_traits>
#include <utility>

#include <common/observable_table.hpp>
#include <qr/core/board.hpp>
#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/core/flight_types.hpp>
#include <qr/core/observable_readers.hpp>

namespace qr {
namespace {

using wire::ObservableId;
using Id = wire::ObservableId;

// The value observable `id` must read: 100 + its id, in its row's units.
constexpr int32_t known(ObservableId id) { return 100 + static_cast<int32_t>(id); }
// ... as the chain's own number: the row's value x 10^scale, in the row's unit.
constexpr double in_unit(ObservableId id) {
  double value = known(id);
  for (int8_t s = wire::kObservableTable[static_cast<uint8_t>(id)].scale; s < 0; ++s) value /= 10.0;
  return value;
}

// The chain's read-outs, each named for the quantity it is, each holding its observable's value.
struct KnownChain {
  using Numbers = chain::FixedNumbers;
  using Angle = Numbers::Angle;
  using Rate = Numbers::Rate;
  using Thrust = Numbers::Thrust;
  using Climb = Numbers::Climb;
  using VerticalAccel = Numbers::VerticalAccel;
  Angle roll() const { return Angle(in_unit(Id::phi)); }
  Angle pitch() const { return Angle(in_unit(Id::theta)); }
  Angle yaw() const { return Angle(in_unit(Id::psi)); }
  Rate p() const { return Rate(in_unit(Id::p)); }
  Rate q() const { return Rate(in_unit(Id::q)); }
  Rate r() const { return Rate(in_unit(Id::r)); }
  Angle roll_setpoint() const { return Angle(in_unit(Id::phi_sp)); }
  Angle pitch_setpoint() const { return Angle(in_unit(Id::theta_sp)); }
  Rate yaw_rate_setpoint() const { return Rate(in_unit(Id::r_sp)); }
  int16_t gyro_filtered(int axis) const { return static_cast<int16_t>(known(Id::gyro_x_f) + axis); }
  int16_t accel_filtered(int axis) const { return static_cast<int16_t>(known(Id::accel_x_f) + axis); }
  int32_t height_mm() const { return known(ObservableId::height); }
  Climb climb() const { return Climb(in_unit(Id::climb)); }
  int32_t tilt_mrad() const { return known(Id::tilt); }
  Rate rate_setpoint(int axis) const { return axis == 0 ? Rate(in_unit(Id::p_sp)) : Rate(in_unit(Id::q_sp)); }
  Thrust p_term(int axis) const {
    return axis == 0   ? Thrust(in_unit(Id::roll_p_term))
           : axis == 1 ? Thrust(in_unit(Id::pitch_p_term))
                       : Thrust(in_unit(Id::yaw_p_term));
  }
  Thrust d_term(int axis) const {
    return axis == 0 ? Thrust(in_unit(Id::roll_d_term)) : Thrust(in_unit(Id::pitch_d_term));
  }
  Thrust integral(int axis) const {
    return axis == 0   ? Thrust(in_unit(Id::roll_integral))
           : axis == 1 ? Thrust(in_unit(Id::pitch_integral))
                       : Thrust(in_unit(Id::yaw_integral));
  }
  Thrust moment(int axis) const {
    return axis == 0   ? Thrust(in_unit(Id::roll_moment))
           : axis == 1 ? Thrust(in_unit(Id::pitch_moment))
                       : Thrust(in_unit(Id::yaw_moment));
  }
  Climb climb_setpoint() const { return Climb(in_unit(Id::climb_sp)); }
  VerticalAccel vertical_p_term() const { return VerticalAccel(in_unit(Id::vertical_p_term)); }
  VerticalAccel vertical_integral() const { return VerticalAccel(in_unit(Id::vertical_integral)); }
  Thrust vertical_thrust() const { return Thrust(in_unit(Id::vertical_thrust)); }
};

struct KnownStats {
  struct {
    uint32_t last;
  } task[wire::kTaskCount];
};

// The flight's read-outs the readers use, in the same known state.
struct KnownFlight {
  using ChainType = KnownChain;
  KnownChain chain_;
  KnownStats stats_{};
  KnownFlight() {
    for (uint8_t task = 0; task < wire::kTaskCount; ++task) {
      stats_.task[task].last = static_cast<uint32_t>(known(Id::cycles_link) + task);
    }
  }
  const KnownChain& chain() const { return chain_; }
  ControlInput controls() const {
    ControlInput c;
    c.lift = static_cast<uint16_t>(known(Id::lift));
    return c;
  }
  EngineCommand engines() const {
    EngineCommand e;
    for (int i = 0; i < 4; ++i) e.value[i] = static_cast<uint16_t>(known(Id::engine_front) + i);
    return e;
  }
  SensorSample sample() const {
    SensorSample s;
    for (int i = 0; i < 3; ++i) {
      s.gyro[i] = static_cast<int16_t>(known(Id::gyro_x) + i);
      s.accel[i] = static_cast<int16_t>(known(Id::accel_x) + i);
    }
    s.battery_mv = static_cast<uint16_t>(known(Id::battery));
    return s;
  }
  uint32_t last_busy_us() const { return static_cast<uint32_t>(known(Id::tick_busy)); }
  uint32_t tick_us() const { return static_cast<uint32_t>(known(Id::time_ms)) * 1000u + 999u; }
  const KnownStats* task_stats() const { return &stats_; }
  uint16_t engine_rpm(uint8_t i) const { return static_cast<uint16_t>(known(Id::rpm_front) + i); }
  uint16_t rc_channel(uint8_t ch) const { return static_cast<uint16_t>(known(Id::rc_ch1) + ch); }
};

const char* name_of(uint8_t id) { return wire::kObservableTable[id].name; }

TEST(ObservableReaders, EveryRowReadsTheQuantityItsNameSays) {
  const KnownFlight flight;
  for (uint8_t id = 0; id < wire::kObservableCount; ++id) {
    EXPECT_EQ(read_observable(flight, id), known(static_cast<ObservableId>(id)))
        << name_of(id) << " (id " << int{id} << ") reads another quantity: the row of id "
        << read_observable(flight, id) - 100 << "'s?";
  }
}

template <ObservableId id>
void expect_observe_reads_its_own(const KnownFlight& flight) {
  EXPECT_EQ(observe<id>(flight), known(id)) << name_of(static_cast<uint8_t>(id));
}
template <size_t... Ids>
void expect_each_observe_reads_its_own(const KnownFlight& flight, std::index_sequence<Ids...>) {
  (expect_observe_reads_its_own<static_cast<ObservableId>(Ids)>(flight), ...);
}

TEST(ObservableReaders, ObserveReadsTheSameAsTheStream) {
  const KnownFlight flight;
  expect_each_observe_reads_its_own(flight, std::make_index_sequence<wire::kObservableCount>{});
}

// What telemetry and the logs carry goes through the same conversion: observe() is the row's
// type, saturated to it (an angle beyond 3.2767 rad shows as the scale's end, not wrapped).
struct FarChain : KnownChain {
  Angle roll() const { return Angle(4.0); }
  Angle pitch() const { return Angle(-4.0); }
  Rate p() const { return Rate(-0.0004); }  // rounds half up: -0.4 to 0
  Climb climb() const { return Climb(-40.0); }
  int32_t tilt_mrad() const { return 70000; }
};
struct FarFlight : KnownFlight {
  using ChainType = FarChain;
  FarChain far_;
  const FarChain& chain() const { return far_; }
};

TEST(ObservableReaders, ValuesAreSaturatedToTheRowsType) {
  const FarFlight flight;
  static_assert(std::is_same_v<decltype(observe<ObservableId::phi>(flight)), int16_t>);
  static_assert(std::is_same_v<decltype(observe<ObservableId::tilt>(flight)), uint16_t>);
  EXPECT_EQ(observe<ObservableId::phi>(flight), 32767);
  EXPECT_EQ(observe<ObservableId::theta>(flight), -32768);
  EXPECT_EQ(observe<ObservableId::p>(flight), 0);
  EXPECT_EQ(observe<ObservableId::climb>(flight), -32768);
  EXPECT_EQ(observe<ObservableId::tilt>(flight), 65535);
  EXPECT_EQ(read_observable(flight, static_cast<uint8_t>(ObservableId::phi)), 32767);
  EXPECT_EQ(read_observable(flight, static_cast<uint8_t>(ObservableId::tilt)), 65535);
}

}  // namespace
}  // namespace qr
