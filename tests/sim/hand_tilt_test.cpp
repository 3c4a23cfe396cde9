// A hand tilting the vehicle to an angle about a body axis and back (sim/hand_tilt.hpp), as a
// person does for the console's orientation check: where the vehicle points while held, what the
// IMU reads, that it is put back exactly, and when the hand is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include <sim/hand_tilt.hpp>
#include <sim/world.hpp>

#include "sim_test_support.hpp"

namespace {

constexpr double kDegPerRad = 180 / std::numbers::pi;
constexpr double kGyroCountsPerRadS = sim::kGyroCountsPerDps * kDegPerRad;

// The Euler angle a positive tilt about each body axis moves: roll right side down, pitch nose up,
// yaw nose right (docs/conventions.md).
double euler_of(const sim::Euler& e, sim::BodyAxis axis) {
  const double angles[] = {e.roll, e.pitch, e.yaw};
  return angles[static_cast<int>(axis)];
}

class HandTiltAbout : public ::testing::TestWithParam<sim::BodyAxis> {};

// 45 degrees in 1.5 s: at the hold the vehicle stands at +45 degrees of that axis' Euler angle
// and nothing else, the gyro reads the kinematics count for count (a perfect IMU), and at the end
// the vehicle is where and as it was, still.
TEST_P(HandTiltAbout, HoldsAtTheAngleAndPutsTheVehicleBack) {
  const sim::BodyAxis axis = GetParam();
  sim::World world(sim_test::ideal_imu(sim::default_vehicle()), {});
  world.advance_to(500000);
  const sim::PlantState before = world.plant().state();
  const sim::HandTiltSpec spec{axis, 45, 1.5};
  ASSERT_EQ(world.start_hand_tilt(spec), "");
  const sim::HandTilt hand(before.attitude, spec, 500000);
  double most_deg = 0;
  for (uint64_t t = 501000; t <= 2000000; t += 1000) {
    world.advance_to(t);
    const sim::ImuReading r = world.sample().imu;
    const sim::Vec3 rate = hand.rate(t);
    for (int a = 0; a < 3; ++a) {
      ASSERT_EQ(r.gyro[static_cast<size_t>(a)], sim::to_counts(rate[a], kGyroCountsPerRadS))
          << "axis " << a << " at " << t << " us";
    }
    most_deg = std::max(most_deg, euler_of(sim::to_euler(world.plant().state().attitude), axis) * kDegPerRad);
  }
  EXPECT_NEAR(most_deg, 45.0, 1e-6);
  EXPECT_FALSE(world.held()) << "the hand lets go at the tilt's end";
  const sim::PlantState& after = world.plant().state();
  EXPECT_NEAR(after.attitude.w, before.attitude.w, 1e-12);
  EXPECT_NEAR(after.attitude.x, before.attitude.x, 1e-12);
  EXPECT_NEAR(after.attitude.y, before.attitude.y, 1e-12);
  EXPECT_NEAR(after.attitude.z, before.attitude.z, 1e-12);
  EXPECT_EQ(sim::norm(after.rate), 0.0);
  EXPECT_EQ(after.position.z, before.position.z);
}

TEST_P(HandTiltAbout, AtTheHoldOnlyItsOwnAngleMoved) {
  const sim::BodyAxis axis = GetParam();
  sim::World world(sim::default_vehicle(), {});
  world.advance_to(200000);
  const sim::Euler level = sim::to_euler(world.plant().state().attitude);
  ASSERT_EQ(world.start_hand_tilt({axis, -30, 3.0}), "");
  world.advance_to(1700000);  // the middle of the hold
  const sim::Euler held = sim::to_euler(world.plant().state().attitude);
  for (const sim::BodyAxis other : {sim::BodyAxis::x, sim::BodyAxis::y, sim::BodyAxis::z}) {
    const double moved = (euler_of(held, other) - euler_of(level, other)) * kDegPerRad;
    EXPECT_NEAR(moved, other == axis ? -30.0 : 0.0, 0.05) << "axis " << static_cast<int>(other);
  }
}

INSTANTIATE_TEST_SUITE_P(EachBodyAxis, HandTiltAbout,
                         ::testing::Values(sim::BodyAxis::x, sim::BodyAxis::y, sim::BodyAxis::z),
                         [](const auto& info) { return std::string(1, "xyz"[static_cast<int>(info.param)]); });

// Out, hold and back a third each, the rate zero where the hand starts, holds and lets go.
TEST(HandTilt, ProfileOutHoldAndBack) {
  const sim::HandTilt hand({}, {sim::BodyAxis::y, 60, 3.0}, 0);
  const double a = 60 / kDegPerRad;
  EXPECT_EQ(hand.angle(0), 0.0);
  EXPECT_NEAR(hand.angle(500000), a / 2, 1e-12);
  EXPECT_NEAR(hand.rate(500000).y, 3 * std::numbers::pi * a / (2 * 3.0), 1e-12) << "the peak, 3 pi A / (2 S)";
  EXPECT_NEAR(hand.angle(1000000), a, 1e-12);
  EXPECT_EQ(hand.angle(1500000), a);
  EXPECT_EQ(sim::norm(hand.rate(1500000)), 0.0);
  EXPECT_NEAR(hand.angle(2500000), a / 2, 1e-12);
  EXPECT_NEAR(hand.rate(2500000).y, -3 * std::numbers::pi * a / (2 * 3.0), 1e-12);
  EXPECT_EQ(hand.rate(2500000).x, 0.0);
  EXPECT_TRUE(hand.done(3000000));
  EXPECT_EQ(hand.angle(3000000), 0.0);
  EXPECT_NEAR(sim::hand_tilt_peak_rate({sim::BodyAxis::y, 60, 3.0}), std::numbers::pi * a / 2, 1e-12);
}

// One hand: a tilt while a turn is under way is refused and the other way round; so is a tilt
// with the engines running.
TEST(HandTilt, RefusedWhileAnEngineRunsOrTheHandHoldsIt) {
  sim::World world(sim::default_vehicle(), {});
  world.advance_to(100000);
  world.plant().set_engines({0, 130, 0, 0});
  EXPECT_EQ(world.start_hand_tilt({sim::BodyAxis::x, 45, 1.5}), "the engines are running (safe first)");
  EXPECT_FALSE(world.held());
  world.plant().set_engines({0, 0, 0, 0});
  ASSERT_EQ(world.start_hand_tilt({sim::BodyAxis::x, 45, 1.5}), "");
  EXPECT_EQ(world.start_hand_turn({sim::BodyAxis::z, 1, 2.0}), "a tilt is under way");
  EXPECT_EQ(world.start_hand_tilt({sim::BodyAxis::y, 45, 1.5}), "a tilt is under way");
  world.advance_to(1600000);
  EXPECT_FALSE(world.held());
  ASSERT_EQ(world.start_hand_turn({sim::BodyAxis::z, 1, 2.0}), "");
  EXPECT_EQ(world.start_hand_tilt({sim::BodyAxis::y, 45, 1.5}), "a turn is under way");
}

TEST(HandTilt, LimitsKeepItATiltTheGyroReads) {
  EXPECT_EQ(sim::hand_tilt_problem({sim::BodyAxis::x, 45, 1.5}), "");
  EXPECT_EQ(sim::hand_tilt_problem({sim::BodyAxis::z, -90, 60.0}), "");
  EXPECT_EQ(sim::hand_tilt_problem({sim::BodyAxis::x, 0, 1.5}), "the angle is a tilt: not 0, within +-90 degrees");
  EXPECT_EQ(sim::hand_tilt_problem({sim::BodyAxis::x, 91, 1.5}), "the angle is a tilt: not 0, within +-90 degrees");
  EXPECT_EQ(sim::hand_tilt_problem({sim::BodyAxis::x, 10, 0.4}), "a tilt takes 0.5 .. 60 s");
  EXPECT_EQ(sim::hand_tilt_problem({sim::BodyAxis::x, 10, 61.0}), "a tilt takes 0.5 .. 60 s");
  // 90 deg: 3 pi (pi/2) / (2 S) is 8.14 rad/s at 0.91 s (beyond), 7.99 at 0.926 s (within).
  EXPECT_NE(sim::hand_tilt_problem({sim::BodyAxis::x, 90, 0.91}).find("beyond the gyro's 8 rad/s"), std::string::npos);
  EXPECT_EQ(sim::hand_tilt_problem({sim::BodyAxis::x, 90, 0.926}), "");
}

}  // namespace
