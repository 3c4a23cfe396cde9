// The world's two physics steps (docs/simulator.md section 1): 500 µs in free flight, 125 µs
// wherever the ground can be touched or a barometer instant falls. The coarse step must fly the
// same flight as the fine one, to far below what the sensors resolve, and never be taken where
// the contact could act.
#include <gtest/gtest.h>

#include <cmath>

#include <sim/world.hpp>

#include "sim_test_support.hpp"

namespace {

using sim_test::place_in_air;

sim::WorldConfig fine_only() {
  sim::WorldConfig c;
  c.free_flight_step_us = 0;
  return c;
}

// Hover thrust with a rocking roll command set at every 1 ms kick, for `seconds`, with the
// sensors read at every kick.
struct Flight {
  sim::World world;
  std::vector<int32_t> pressure;

  Flight(const sim::WorldConfig& config, double height) : world(sim::default_vehicle(), config) {
    place_in_air(world.plant(), world.plant().vehicle().hover_speed(), height);
  }
  void fly(double seconds) {
    const uint16_t hover = world.plant().engines()[0];
    for (uint64_t t = 1000; t <= static_cast<uint64_t>(seconds * 1e6); t += 1000) {
      // Right and left apart by 2 commands, the other way every 70 ms: a roll rocking by a few
      // degrees, and a slow yaw.
      const uint16_t rock = (t / 70000) % 2 == 0 ? 2 : 0;
      world.plant().set_engines(
          {hover, static_cast<uint16_t>(hover + rock), hover, static_cast<uint16_t>(hover + 2 - rock)});
      world.advance_to(t);
      pressure.push_back(world.sample().pressure_pa);
    }
  }
};

TEST(WorldStep, FreeFlightTakesTheCoarseStepAndFliesTheFineStepsFlight) {
  Flight coarse({}, 50), fine(fine_only(), 50);
  coarse.fly(3);
  fine.fly(3);
  EXPECT_EQ(coarse.world.free_flight_step_us(), 500u);
  EXPECT_LT(coarse.world.steps_taken(), fine.world.steps_taken() / 3) << "most steps were coarse";
  const sim::PlantState& a = coarse.world.plant().state();
  const sim::PlantState& b = fine.world.plant().state();
  // Far below what the sensors resolve, after 3 s: the rates within a fifth of one gyro sample's
  // noise (0.080 °/s), the position within a millimetre (the barometer's step is 8 cm), the
  // rotor's vibration phase within 0.6°. The difference is not RK4's truncation on the smooth parts
  // (1e-11) but the motor lag's switch between its two time constants at the target, and the
  // battery voltage the ESC sees one step late: both first order in the step.
  EXPECT_GT(std::abs(b.rate.x), 0.01) << "the flight rocked";
  constexpr double kGyroNoiseRadS = 0.080 * 3.14159265358979 / 180;
  EXPECT_NEAR(a.rate.x, b.rate.x, kGyroNoiseRadS / 5);
  EXPECT_NEAR(a.rate.z, b.rate.z, kGyroNoiseRadS / 5);
  EXPECT_NEAR(a.position.x, b.position.x, 1e-3);
  EXPECT_NEAR(a.position.z, b.position.z, 1e-3);
  // The roll, open loop for 3 s, within 0.01°: a third of the firmware's own estimate error in hover.
  EXPECT_NEAR(sim::to_euler(a.attitude).roll * 180 / 3.14159265358979,
              sim::to_euler(b.attitude).roll * 180 / 3.14159265358979, 0.01);
  EXPECT_NEAR(a.rotor_speed[1], b.rotor_speed[1], 1e-3);
  EXPECT_NEAR(coarse.world.plant().rotor_phase(1), fine.world.plant().rotor_phase(1), 0.01);
  ASSERT_EQ(coarse.pressure.size(), fine.pressure.size());
  for (size_t i = 0; i < coarse.pressure.size(); ++i) {
    ASSERT_EQ(coarse.pressure[i] == 0, fine.pressure[i] == 0) << "the barometer publishes at the same instants, " << i;
    ASSERT_NEAR(coarse.pressure[i], fine.pressure[i], 1) << "within its 1 Pa step, " << i;
  }
}

TEST(WorldStep, NearTheGroundEveryStepIsFine) {
  sim::World world(sim::default_vehicle(), {});
  world.plant().rest_on_ground();
  world.advance_to(100000);
  EXPECT_EQ(world.steps_taken(), 100000u / world.step_us()) << "standing on the ground";
  // Half a millimetre above the farthest contact point's reach: still fine (the margin is 1 mm);
  // 2 cm above it: coarse.
  const double reach = sim::GroundContact(sim::default_vehicle()).reach();
  Flight low({}, reach + 0.0005), higher({}, reach + 0.02);
  low.fly(0.01);
  higher.fly(0.01);
  EXPECT_EQ(low.world.steps_taken(), 10000u / low.world.step_us());
  EXPECT_LT(higher.world.steps_taken(), 10000u / higher.world.step_us());
}

TEST(WorldStep, AFastMotorGetsAShorterStep) {
  sim::VehicleParams v = sim::default_vehicle();
  v.motor_tau_up_s = 0.010;
  EXPECT_EQ(sim::World(v, {}).free_flight_step_us(), 250u);
  v.motor_tau_up_s = 0.001;
  EXPECT_EQ(sim::World(v, {}).free_flight_step_us(), 125u);
}

}  // namespace
