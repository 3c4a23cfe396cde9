// The plant against physics we can work out by hand, and against docs/conventions.md.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <sim/battery.hpp>
#include <sim/quadrotor.hpp>
#include <sim/vehicle.hpp>

#include "sim_test_support.hpp"

namespace {

using sim::kGravity;
using sim::Quadrotor;
using sim::Vec3;
using sim_test::place_in_air;
using sim_test::run;

TEST(Plant, DefaultVehicleHoversAroundEngine530) {
  const Quadrotor plant(sim::default_vehicle());
  // The brief: hover around 500-600 of 1000, leaving control authority both ways.
  EXPECT_GT(plant.hover_command(), 500);
  EXPECT_LT(plant.hover_command(), 600);
}

TEST(Plant, HoverThrustBalancesWeight) {
  Quadrotor plant(sim::default_vehicle());
  place_in_air(plant, plant.vehicle().hover_speed());
  const double command = plant.hover_command();
  const uint16_t e = static_cast<uint16_t>(std::lround(command));
  plant.set_engines({e, e, e, e});
  run(plant, 1.0);  // motors settle on the loaded voltage
  const double v0 = plant.state().velocity.z;
  run(plant, 1.0);
  const double vertical_accel = plant.state().velocity.z - v0;
  // The command is whole engine units: half a unit of rounding is 2 x 0.5 / 531 of the weight.
  const double rounding = 2 * std::abs(e - command) / command * kGravity;
  EXPECT_LT(std::abs(vertical_accel), rounding + 0.005) << "command " << command;
  // Level hover with equal rotors: no rotation starts.
  EXPECT_LT(sim::norm(plant.state().rate), 1e-9);
}

TEST(Plant, FreeFallFollowsHalfGTSquared) {
  sim::VehicleParams v = sim::default_vehicle();
  v.body_drag_area_m2 = {};
  Quadrotor plant(v);
  place_in_air(plant, 0, 1000);
  plant.set_engines({0, 0, 0, 0});
  EXPECT_NEAR(sim::norm(plant.specific_force()), 0, 1e-12);  // an accelerometer in free fall reads 0
  run(plant, 3.0);
  EXPECT_NEAR(plant.state().position.z, -1000 + 0.5 * kGravity * 9, 1e-6);
  EXPECT_NEAR(plant.state().velocity.z, kGravity * 3, 1e-9);
  EXPECT_NEAR(sim::norm(plant.specific_force()), 0, 1e-12);
}

TEST(Plant, RestsOnTheGroundAndNeverFallsThrough) {
  Quadrotor plant(sim::default_vehicle());
  const double resting_z = plant.state().position.z;
  sim::PlantState s = plant.state();
  s.position.z -= 1.0;  // dropped from 1 m, engines off
  plant.set_state(s);
  double deepest = -1, lowest_centre = -1, highest_after_touch = -1e9;
  bool touched = false;
  for (int i = 0; i < 3 * 8000; ++i) {
    plant.step(125e-6);
    deepest = std::max(deepest, plant.deepest_contact());
    lowest_centre = std::max(lowest_centre, plant.state().position.z);
    if (plant.deepest_contact() > 0) touched = true;
    if (touched) highest_after_touch = std::max(highest_after_touch, -plant.state().position.z);
  }
  ASSERT_TRUE(touched);
  EXPECT_LT(deepest, 0.010) << "feet sank " << deepest * 1000 << " mm on a 1 m drop";
  EXPECT_LT(lowest_centre, 0) << "centre of mass below the ground";
  // No bounce: after touching down it never rises more than 5 mm above its resting height.
  EXPECT_LT(highest_after_touch, -resting_z + 0.005);
  // At rest again, where it started, level.
  EXPECT_NEAR(plant.state().position.z, resting_z, 1e-4);
  EXPECT_LT(sim::norm(plant.state().velocity), 1e-3);
  EXPECT_LT(sim::norm(plant.state().rate), 1e-3);
  const sim::Euler e = sim::to_euler(plant.state().attitude);
  EXPECT_LT(std::abs(e.roll) + std::abs(e.pitch), 1e-3);
}

TEST(Plant, UpsideDownCrashStaysAboveGround) {
  Quadrotor plant(sim::default_vehicle());
  sim::PlantState s;
  s.position = {0, 0, -0.5};
  s.attitude = sim::from_euler({3.0, 0.2, 0});
  s.velocity = {1.0, 0, 2.0};
  s.rate = {3, -2, 1};
  plant.set_state(s);
  plant.set_engines({0, 0, 0, 0});
  double deepest = -1, lowest_centre = -1;
  for (int i = 0; i < 4 * 8000; ++i) {
    plant.step(125e-6);
    deepest = std::max(deepest, plant.deepest_contact());
    lowest_centre = std::max(lowest_centre, plant.state().position.z);
  }
  EXPECT_LT(deepest, 0.010);
  EXPECT_LT(lowest_centre, -0.02) << "the top of the battery keeps the centre off the ground";
  EXPECT_LT(sim::norm(plant.state().velocity), 1e-2);
  EXPECT_LT(sim::norm(plant.state().rate), 1e-2);
}

// docs/conventions.md: L = b l (w3^2 - w1^2), M = b l (w0^2 - w2^2), N = d (w1^2 + w3^2 - w0^2 - w2^2).
TEST(Plant, EachEngineTurnsTheBodyAsTheConventionsSay) {
  struct Expect {
    int engine;
    int p, q, r;  // expected sign of each rate after speeding that engine up
  };
  const Expect rows[] = {
      {0, 0, +1, -1},  // front up: nose up; clockwise rotor faster: yaw left
      {1, -1, 0, +1},  // right up: rolls left; counter-clockwise rotor faster: yaw right
      {2, 0, -1, -1},  // back up: nose down; clockwise: yaw left
      {3, +1, 0, +1},  // left up: rolls right (right side down); counter-clockwise: yaw right
  };
  for (const Expect& row : rows) {
    Quadrotor plant(sim::default_vehicle());
    place_in_air(plant, plant.vehicle().hover_speed());
    std::array<uint16_t, 4> e = plant.engines();
    e[static_cast<size_t>(row.engine)] = static_cast<uint16_t>(e[static_cast<size_t>(row.engine)] + 100);
    plant.set_engines(e);
    run(plant, 0.05);
    const Vec3 w = plant.state().rate;
    const double rates[3] = {w.x, w.y, w.z};
    const int signs[3] = {row.p, row.q, row.r};
    for (int axis = 0; axis < 3; ++axis) {
      const double rate = rates[axis];
      if (signs[axis] == 0) {
        // Not exactly zero: the rotors' net angular momentum, no longer balanced, couples the
        // pitch (or roll) rate into roll (or pitch) gyroscopically. An order of magnitude less.
        EXPECT_LT(std::abs(rate), 0.1 * std::max(std::abs(w.x), std::abs(w.y)))
            << "engine " << row.engine << " axis " << axis << " rate " << rate;
      } else {
        EXPECT_GT(rate * signs[axis], 0.01) << "engine " << row.engine << " axis " << axis << " rate " << rate;
      }
    }
  }
}

// Time for the speed to cover 63.2 % of a step: one time constant of a first-order lag.
double time_constant(double from_command, double to_command) {
  Quadrotor plant(sim::default_vehicle());
  const double volts = plant.battery_volts();
  const double spv = plant.vehicle().speed_per_volt();
  place_in_air(plant, from_command / 1000 * spv * volts);
  plant.set_engines({static_cast<uint16_t>(to_command), 0, 0, 0});
  const double start = plant.state().rotor_speed[0];
  const double target = to_command / 1000 * spv * volts;
  const double mark = start + (target - start) * (1 - std::exp(-1.0));
  for (int i = 1; i < 8000; ++i) {
    plant.step(125e-6);
    const double w = plant.state().rotor_speed[0];
    if ((target - mark) * (w - mark) >= 0) return i * 125e-6;
  }
  return 1e9;
}

TEST(Plant, MotorsSpinUpFasterThanDown) {
  const sim::VehicleParams v = sim::default_vehicle();
  const double up = time_constant(300, 700), down = time_constant(700, 300);
  // The voltage sags a little as the current changes, so allow 5 %.
  EXPECT_NEAR(up, v.motor_tau_up_s, 0.05 * v.motor_tau_up_s);
  EXPECT_NEAR(down, v.motor_tau_down_s, 0.05 * v.motor_tau_down_s);
  EXPECT_LT(up, down);
}

TEST(Plant, BatterySagsUnderLoadAndDrains) {
  const sim::VehicleParams v = sim::default_vehicle();
  double sag_at[3] = {};
  const uint16_t commands[3] = {0, 530, 1000};
  for (int i = 0; i < 3; ++i) {
    Quadrotor plant(v);
    place_in_air(plant, 0);
    plant.set_engines({commands[i], commands[i], commands[i], commands[i]});
    run(plant, 0.5);
    const double ocv = plant.battery().open_circuit_volts();
    sag_at[i] = ocv - plant.battery_volts();
    EXPECT_NEAR(sag_at[i], plant.battery_current() * v.battery_resistance_ohm, 1e-3);
  }
  EXPECT_NEAR(sag_at[0], v.avionics_current_a * v.battery_resistance_ohm, 1e-9);
  EXPECT_GT(sag_at[1], 0.15);  // hover: about 8 A
  EXPECT_GT(sag_at[2], 2 * sag_at[1]);
  EXPECT_LT(sag_at[2], 2.0);

  // Charge taken out = integral of the current.
  Quadrotor plant(v);
  place_in_air(plant, 0);
  plant.set_engines({800, 800, 800, 800});
  double charge_as = 0;
  for (int i = 0; i < 8000 * 10; ++i) {
    plant.step(125e-6);
    charge_as += plant.battery_current() * 125e-6;
  }
  EXPECT_NEAR(v.battery_initial_soc - plant.battery().soc(), charge_as / (v.battery_capacity_mah * 3.6), 1e-9);
  EXPECT_LT(plant.battery().soc(), v.battery_initial_soc - 0.01);
}

TEST(Plant, LipoCurveIsMonotonic) {
  EXPECT_DOUBLE_EQ(sim::lipo_cell_volts(1.0), 4.20);
  for (double soc = 0; soc < 1; soc += 0.01) EXPECT_LT(sim::lipo_cell_volts(soc), sim::lipo_cell_volts(soc + 0.01));
}

TEST(Plant, TorqueFreeSpinConservesEnergyAndAngularMomentum) {
  sim::VehicleParams v = sim::default_vehicle();
  v.inertia_kgm2 = {0.011, 0.015, 0.021};  // three different moments: the middle axis tumbles
  Quadrotor plant(v);
  sim::PlantState s;
  s.position = {0, 0, -10000};
  s.rate = {0.05, 4.0, 0.1};  // mostly about the intermediate axis: unstable, it flips over
  plant.set_state(s);
  plant.set_engines({0, 0, 0, 0});
  auto momentum = [&] { return sim::rotate(plant.state().attitude, sim::scale(v.inertia_kgm2, plant.state().rate)); };
  auto energy = [&] { return 0.5 * sim::dot(plant.state().rate, sim::scale(v.inertia_kgm2, plant.state().rate)); };
  const Vec3 h0 = momentum();
  const double e0 = energy();
  double max_p = 0;
  for (int i = 0; i < 8000 * 10; ++i) {
    plant.step(125e-6);
    max_p = std::max(max_p, std::abs(plant.state().rate.x));
  }
  EXPECT_GT(max_p, 1.0) << "the intermediate-axis spin should have tumbled";
  EXPECT_LT(sim::norm(momentum() - h0) / sim::norm(h0), 1e-8);
  EXPECT_LT(std::abs(energy() - e0) / e0, 1e-8);
}

TEST(Plant, RotorDragOpposesHorizontalVelocitySoTheAccelerometerSeesIt) {
  sim::VehicleParams v = sim::default_vehicle();
  v.body_drag_area_m2 = {};
  Quadrotor plant(v);
  place_in_air(plant, v.hover_speed());
  sim::PlantState s = plant.state();
  s.velocity = {5, 0, 0};
  plant.set_state(s);
  // Four rotors: D = 4 c w v, in the rotor plane, against the motion.
  const double expected = -4 * v.rotor_drag_coeff * v.hover_speed() * 5 / v.mass_kg;
  EXPECT_NEAR(plant.specific_force().x, expected, 1e-9);
  EXPECT_LT(expected, -1.0);
}

// Drag depends on the velocity through the air only: flying north at 5 m/s in still air and
// hanging still in a 5 m/s wind from the north are the same to every drag term; still air and a
// wind the vehicle moves with are the same too.
TEST(Plant, WindActsThroughTheVelocityRelativeToTheAir) {
  const sim::VehicleParams v = sim::default_vehicle();
  Quadrotor moving(v), blown(v);
  place_in_air(moving, v.hover_speed());
  place_in_air(blown, v.hover_speed());
  sim::PlantState s = moving.state();
  s.velocity = {5, 0, 0};
  moving.set_state(s);
  blown.set_wind({-5, 0, 0});
  const sim::Vec3 a = moving.specific_force(), b = blown.specific_force();
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
  EXPECT_NEAR(a.z, b.z, 1e-12);
  EXPECT_LT(b.x, -1.0) << "pushed downwind (south) by the rotor and airframe drag";
  moving.set_wind({5, 0, 0});  // moving with the air: no drag at all
  EXPECT_NEAR(moving.specific_force().x, 0, 1e-12);
}

TEST(Plant, VehicleFileErrorsAreReported) {
  sim::VehicleParams v;
  std::string error;
  std::string text = sim::default_vehicle_text();
  EXPECT_TRUE(sim::parse_vehicle(text, v, error)) << error;
  EXPECT_FALSE(sim::parse_vehicle(text + "\nmass_kgg = 1\n", v, error));
  EXPECT_NE(error.find("unknown parameter `mass_kgg`"), std::string::npos) << error;
  EXPECT_FALSE(sim::parse_vehicle(text + "\nmass_kg = 2\n", v, error));
  EXPECT_NE(error.find("given twice"), std::string::npos) << error;
  const size_t at = text.find("arm_m = ");
  EXPECT_FALSE(
      sim::parse_vehicle(text.substr(0, at) + "arm_m = 0.2x\n" + text.substr(text.find('\n', at) + 1), v, error));
  EXPECT_NE(error.find("not a number"), std::string::npos) << error;
  EXPECT_FALSE(sim::parse_vehicle(text.substr(0, at) + text.substr(text.find('\n', at) + 1), v, error));
  EXPECT_NE(error.find("missing parameter `arm_m`"), std::string::npos) << error;
}

TEST(Plant, EveryVehicleFileInTheTreeParses) {
  for (const char* name : {"in4073.txt", "in4073_heavy.txt"}) {
    sim::VehicleParams v;
    std::string error;
    EXPECT_TRUE(sim::load_vehicle_file(std::string(QR_SIM_VEHICLE_DIR) + "/" + name, v, error)) << error;
    const Quadrotor plant(v);
    EXPECT_GT(plant.hover_command(), 300) << name;
    EXPECT_LT(plant.hover_command(), 750) << name;
  }
}

}  // namespace
