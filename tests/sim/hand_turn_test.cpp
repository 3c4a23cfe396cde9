// A hand turning the vehicle about a body axis (sim/hand_turn.hpp), as a person does for a gyro
// scale calibration: what the IMU reads over the turn, where the vehicle is afterwards, when the
// hand is refused, and the scenario event that does it with the firmware in safe.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <qr/sim_runner/scenario.hpp>
#include <qr/sim_runner/scenario_script.hpp>
#include <sim/hand_turn.hpp>
#include <sim/world.hpp>

#include "sim_test_support.hpp"

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kGyroCountsPerRadS = sim::kGyroCountsPerDps * 180 / std::numbers::pi;
constexpr uint64_t kSampleUs = 1000;  // the IMU read at every 1 kHz kick, as the firmware reads it

struct Sums {
  std::array<double, 3> counts{};
  int samples = 0;
};

// The gyro's counts summed over the samples in (from_us, to_us].
Sums gyro_sums(sim::World& world, uint64_t from_us, uint64_t to_us) {
  Sums s;
  for (uint64_t t = from_us + kSampleUs; t <= to_us; t += kSampleUs) {
    world.advance_to(t);
    const sim::ImuReading r = world.sample().imu;
    for (size_t a = 0; a < 3; ++a) s.counts[a] += r.gyro[a];
    ++s.samples;
  }
  return s;
}

class HandTurnAbout : public ::testing::TestWithParam<sim::BodyAxis> {};

// Two turns in 4 s: the integrated gyro on the turning axis is 2 pi N times that axis' drawn scale
// factor (the zero-rate offset taken out as the calibration does, from 0.5 s at rest before), the
// other two axes see next to nothing, and the vehicle is put back exactly as it was.
TEST_P(HandTurnAbout, GyroIntegratesTheTurnTimesItsScaleAndTheVehicleIsPutBack) {
  const int axis = static_cast<int>(GetParam());
  for (const uint64_t seed : {1u, 2u, 3u}) {
    sim::World world(sim::default_vehicle(), sim::WorldConfig{.seed = seed});
    world.advance_to(1000000);
    const Sums rest = gyro_sums(world, world.now_us(), world.now_us() + 500000);
    const sim::PlantState before = world.plant().state();
    const sim::HandTurnSpec spec{GetParam(), 2, 4.0};
    ASSERT_EQ(world.start_hand_turn(spec), "");
    EXPECT_TRUE(world.held());
    const uint64_t start = world.now_us();
    const Sums turn = gyro_sums(world, start, start + 4000000);
    EXPECT_FALSE(world.held()) << "the hand lets go at the turn's end";

    const double turned = kTwoPi * spec.turns;
    for (int a = 0; a < 3; ++a) {
      const size_t i = static_cast<size_t>(a);
      const double offset = rest.counts[i] / rest.samples;
      const double integrated = (turn.counts[i] - offset * turn.samples) / kGyroCountsPerRadS / 1000.0;
      if (a == axis) {
        const double expected = turned * world.imu().gyro_scale()[a];
        EXPECT_NEAR(integrated / expected, 1.0, 1e-3) << "seed " << seed << ", scale " << world.imu().gyro_scale()[a];
      } else {
        EXPECT_LT(std::abs(integrated), 0.005 * kTwoPi) << "seed " << seed << ", axis " << a;
      }
    }

    const sim::PlantState& after = world.plant().state();
    EXPECT_NEAR(after.attitude.w, before.attitude.w, 1e-9);
    EXPECT_NEAR(after.attitude.x, before.attitude.x, 1e-9);
    EXPECT_NEAR(after.attitude.y, before.attitude.y, 1e-9);
    EXPECT_NEAR(after.attitude.z, before.attitude.z, 1e-9);
    for (const double v :
         {after.velocity.x, after.velocity.y, after.velocity.z, after.rate.x, after.rate.y, after.rate.z})
      EXPECT_EQ(v, 0.0);
    EXPECT_EQ(after.position.x, before.position.x);
    EXPECT_EQ(after.position.y, before.position.y);
    EXPECT_EQ(after.position.z, before.position.z);
    // Set down on its feet: it stays there, still.
    world.advance_to(world.now_us() + 500000);
    EXPECT_NEAR(world.plant().state().position.z, before.position.z, 1e-6);
    EXPECT_LT(sim::norm(world.plant().state().rate), 1e-6);
    EXPECT_LT(world.plant().deepest_contact(), 1e-3) << "on its feet, not in the ground";
    EXPECT_GT(world.plant().deepest_contact(), 0) << "on the ground";
  }
}

INSTANTIATE_TEST_SUITE_P(EachBodyAxis, HandTurnAbout,
                         ::testing::Values(sim::BodyAxis::x, sim::BodyAxis::y, sim::BodyAxis::z),
                         [](const auto& info) { return std::string(1, "xyz"[static_cast<int>(info.param)]); });

// With a perfect IMU the readings are the kinematics, count for count: the body rate along the
// axis, and a body held still against gravity, (0, 0, -g) in world axes seen in body axes.
TEST(HandTurn, TheImuReadsTheRateAndGravityOfABodyHeldStill) {
  sim::World world(sim_test::ideal_imu(sim::default_vehicle()), {});
  world.advance_to(500000);
  const sim::Quat start = world.plant().state().attitude;
  ASSERT_EQ(world.start_hand_turn({sim::BodyAxis::x, -1, 2.0}), "");
  const sim::HandTurn hand(start, {sim::BodyAxis::x, -1, 2.0}, 500000);
  double highest_accel_z = -1e9;
  for (uint64_t t = 501000; t <= 2500000; t += kSampleUs) {
    world.advance_to(t);
    const sim::ImuReading r = world.sample().imu;
    const sim::Vec3 rate = hand.rate(t);
    const sim::Vec3 force = sim::held_specific_force(hand.attitude(t), sim::kGravity);
    for (int a = 0; a < 3; ++a) {
      const size_t i = static_cast<size_t>(a);
      ASSERT_EQ(r.gyro[i], sim::to_counts(rate[a], kGyroCountsPerRadS)) << "axis " << a << " at " << t << " us";
      ASSERT_EQ(r.accel[i], sim::to_counts(force[a], sim::kAccelCountsPerG / sim::kStandardGravity))
          << "axis " << a << " at " << t << " us";
    }
    highest_accel_z = std::max(highest_accel_z, force.z);
  }
  EXPECT_GT(highest_accel_z, 0.99 * sim::kGravity) << "half-way round it was upside down";
  EXPECT_NEAR(hand.rate(1500000).x, -4 * std::numbers::pi / 2.0, 1e-12) << "peak rate 4 pi N / S, half-way";
  EXPECT_NEAR(hand.angle(1500000), -std::numbers::pi, 1e-12);
}

// A hand does not go into turning rotors, and one turn at a time.
TEST(HandTurn, RefusedWhileAnEngineRunsOrATurnIsUnderWay) {
  sim::World world(sim::default_vehicle(), {});
  world.advance_to(100000);
  world.plant().set_engines({0, 0, 120, 0});
  EXPECT_EQ(world.start_hand_turn({sim::BodyAxis::z, 1, 2.0}), "the engines are running (safe first)");
  EXPECT_FALSE(world.held());
  world.advance_to(110000);
  EXPECT_FALSE(world.held());
  world.plant().set_engines({0, 0, 0, 0});
  EXPECT_EQ(world.start_hand_turn({sim::BodyAxis::z, 1, 2.0}), "");
  EXPECT_EQ(world.start_hand_turn({sim::BodyAxis::y, 1, 2.0}), "a turn is under way");
}

TEST(HandTurn, LimitsKeepTheTurnReadable) {
  EXPECT_EQ(sim::hand_turn_problem({sim::BodyAxis::z, 2, 4.0}), "");
  EXPECT_EQ(sim::hand_turn_problem({sim::BodyAxis::z, -10, 60.0}), "");
  EXPECT_NE(sim::hand_turn_problem({sim::BodyAxis::z, 0, 4.0}), "");
  EXPECT_NE(sim::hand_turn_problem({sim::BodyAxis::z, 11, 60.0}), "");
  EXPECT_NE(sim::hand_turn_problem({sim::BodyAxis::z, 1, 0.4}), "");
  EXPECT_NE(sim::hand_turn_problem({sim::BodyAxis::z, 1, 61.0}), "");
  // 4 pi / 1.5 = 8.38 rad/s: beyond; 4 pi / 1.6 = 7.85: within.
  EXPECT_NE(sim::hand_turn_problem({sim::BodyAxis::z, 1, 1.5}).find("beyond the gyro's 8 rad/s"), std::string::npos);
  EXPECT_EQ(sim::hand_turn_problem({sim::BodyAxis::z, 1, 1.6}), "");
}

// A trace's column by name, as numbers.
std::vector<double> column(const std::vector<std::map<std::string, std::string>>& rows, const std::string& name) {
  std::vector<double> out;
  for (const auto& row : rows) {
    const std::string& field = row.at(name);
    out.push_back(field.empty() ? std::nan("") : std::stod(field));
  }
  return out;
}

double max_of(const std::vector<double>& v) {
  double m = -1e300;
  for (const double x : v) m = std::max(m, x);
  return m;
}

// A scenario that turns the vehicle on the ground with the firmware in safe runs through: the
// truth turns at the profile's peak rate, the firmware stays in safe, the vehicle ends upright
// where it stood.
TEST(HandTurn, AScenarioTurnsTheVehicleInSafe) {
  qrsim::ScenarioScript script;
  std::string error;
  ASSERT_TRUE(
      qrsim::parse_scenario("seconds: 7.5\n"
                            "start: safe\n"
                            "at 0.5 turn z 2 for 4\n"
                            "at 5 turn x -1 for 2\n"
                            "band final_mode == safe\n"
                            "band final_upright == 1\n",
                            "turns", "turns.txt", script, error))
      << error;
  qrsim::RunOptions options;
  options.trace_path = ::testing::TempDir() + "hand_turn_trace.csv";
  const qrsim::ScenarioResult r = qrsim::run_scenario(script, options);
  ASSERT_TRUE(r.error.empty()) << r.error;
  EXPECT_TRUE(r.pass);
  EXPECT_EQ(r.final_mode, "safe");
  EXPECT_LT(r.figure("drift_m_end"), 1e-6);
  EXPECT_LT(r.figure("speed_m_s_end"), 1e-6);
  EXPECT_TRUE(std::isnan(r.figure("touchdown_speed_m_s"))) << "set down by a hand, not landed";
  const auto rows = sim_test::read_csv(options.trace_path);
  const std::vector<double> r_rad_s = column(rows, "r_rad_s"), p_rad_s = column(rows, "p_rad_s");
  const std::vector<double> mode = column(rows, "mode"), t_s = column(rows, "t_s");
  ASSERT_GT(r_rad_s.size(), 5000u);
  EXPECT_NEAR(max_of(r_rad_s), 4 * std::numbers::pi * 2 / 4, 1e-3);
  std::vector<double> minus_p;
  for (const double p : p_rad_s) minus_p.push_back(-p);
  EXPECT_NEAR(max_of(minus_p), 4 * std::numbers::pi / 2, 1e-3);
  size_t turning = 0;
  for (size_t i = 0; i < mode.size(); ++i) {
    if (std::abs(r_rad_s[i]) + std::abs(p_rad_s[i]) < 0.01) continue;
    ++turning;
    EXPECT_EQ(mode[i], 0) << "in safe while turned, at " << t_s[i] << " s";
  }
  EXPECT_GT(turning, 5500u) << "4 s and 2 s of turning";
}

// With the engines running the hand is refused, and the flight says where and why.
TEST(HandTurn, AScenarioTurnWithTheEnginesRunningIsAnError) {
  qrsim::ScenarioScript script;
  std::string error;
  ASSERT_TRUE(qrsim::parse_scenario("seconds: 2\nat 0.5 turn z 1 for 2\nband final_mode == full\n", "armed",
                                    "armed.txt", script, error))
      << error;
  const qrsim::ScenarioResult r = qrsim::run_scenario(script, {});
  EXPECT_EQ(r.error, "armed.txt:2: the turn was refused: the engines are running (safe first)");
  EXPECT_FALSE(r.pass);
}

}  // namespace
