// The fit (tune/axis_fit.hpp) on identification records the tests fly themselves in closed loop
// (closed_loop_flight.hpp: the firmware's controllers, a PRBS on the moment, gyro noise and a
// constant disturbance), for vehicles unlike each other: it finds what they were made with, and
// it refuses records it cannot read, saying why.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include <tune/axis_fit.hpp>

#include "closed_loop_flight.hpp"

namespace tune {
namespace {

// Roll-like axes: the default vehicle (0.18 rad/s^2 per thrust unit, 30 ms motors); a heavy one
// with slow motors and an ESC's latency; a light, quick one. The quick one flies with half the
// default P2, which would not be stable on it (TuneDesign.DefaultsAreUnstableOnAQuickVehicle).
struct Case {
  AxisModel truth;
  int32_t p2_raw;
};
const Case kRollCases[] = {
    {{0.18, 0.030, 0.004, 0, 0, 0}, 3520},
    {{0.09, 0.060, 0.010, 0, 0, 0}, 3520},
    {{0.35, 0.015, 0.002, 0, 0, 0}, 1760},
};

test::FlightSetup identification(const AxisModel& truth, uint32_t seed) {
  test::FlightSetup s;
  s.truth = truth;
  s.seed = seed;  // the noise's
  return s;
}

void expect_within(double found, double truth, double share, const char* what) {
  EXPECT_NEAR(found / truth, 1.0, share) << what << ": found " << found << ", truth " << truth;
}

TEST(TuneFit, RecoversGainLagAndDelayOfRollLikeAxes) {
  for (const Case& c : kRollCases) {
    test::FlightSetup s = identification(c.truth, 7);
    s.gains.p2 = c.p2_raw;
    std::string why;
    const auto model = fit_axis(test::fly(s).record, &why);
    ASSERT_TRUE(model.has_value()) << why;
    expect_within(model->gain, c.truth.gain, 0.05, "gain");
    expect_within(model->motor_tau_s, c.truth.motor_tau_s, 0.05, "motor lag");
    expect_within(model->delay_s, c.truth.delay_s, 0.05, "delay");
    EXPECT_EQ(model->lead_s, 0.0);
    EXPECT_EQ(model->damping_per_s, 0.0);
    EXPECT_LT(model->residual, 0.2);
  }
}

// Yaw: a weak moment (the rotors' drag), the rotors' reaction as a lead, and drag damping of the
// rate; the PRBS is larger, as an identification flight's on yaw would be.
TEST(TuneFit, RecoversTheYawAxisWithItsLeadAndDamping) {
  const AxisModel truth{0.0069, 0.040, 0.003, 0.23, 0.8, 0};
  test::FlightSetup s = identification(truth, 3);
  s.yaw = true;
  s.prbs_amplitude = 200;
  std::string why;
  const auto model = fit_axis(test::fly(s).record, &why);
  ASSERT_TRUE(model.has_value()) << why;
  expect_within(model->gain, truth.gain, 0.05, "gain");
  expect_within(model->motor_tau_s, truth.motor_tau_s, 0.05, "motor lag");
  expect_within(model->delay_s, truth.delay_s, 0.05, "delay");
  expect_within(model->lead_s, truth.lead_s, 0.10, "lead");
  expect_within(model->damping_per_s, truth.damping_per_s, 0.15, "damping");
}

// Without noise the equation is exact: what is left of the error is the tests' integration.
TEST(TuneFit, IsExactOnANoiselessRecord) {
  test::FlightSetup s = identification(kRollCases[0].truth, 1);
  s.gyro_noise = 0;
  const auto model = fit_axis(test::fly(s).record);
  ASSERT_TRUE(model.has_value());
  expect_within(model->gain, s.truth.gain, 0.002, "gain");
  expect_within(model->motor_tau_s, s.truth.motor_tau_s, 0.005, "motor lag");
  EXPECT_NEAR(model->delay_s, s.truth.delay_s, 2e-5);
  EXPECT_LT(model->residual, 0.01);
}

// The hover without the sequence: the loops' answer to the noise moves the moment, but far less
// than an excitation must.
TEST(TuneFit, RefusesARecordWithoutExcitation) {
  test::FlightSetup s = identification(kRollCases[0].truth, 1);
  s.prbs_amplitude = 0;
  std::string why;
  EXPECT_FALSE(fit_axis(test::fly(s).record, &why).has_value());
  EXPECT_NE(why.find("no excitation"), std::string::npos) << why;
}

TEST(TuneFit, RefusesARecordTooShort) {
  test::FlightSetup s = identification(kRollCases[0].truth, 1);
  s.seconds = 2.0;  // 0.25 s to settle and 2 s to fit are needed
  std::string why;
  EXPECT_FALSE(fit_axis(test::fly(s).record, &why).has_value());
  EXPECT_NE(why.find("too short"), std::string::npos) << why;
  EXPECT_FALSE(fit_axis(AxisRecord{1000, {}, {}}, &why).has_value());
  EXPECT_NE(why.find("too short"), std::string::npos) << why;
}

TEST(TuneFit, RefusesABrokenRecord) {
  const AxisRecord good = test::fly(identification(kRollCases[0].truth, 1)).record;
  ASSERT_TRUE(fit_axis(good).has_value());
  std::string why;

  AxisRecord shorter_rate = good;
  shorter_rate.rate.pop_back();
  EXPECT_FALSE(fit_axis(shorter_rate, &why).has_value());
  EXPECT_NE(why.find("differ in length"), std::string::npos) << why;

  AxisRecord not_a_number = good;
  not_a_number.moment[1234] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(fit_axis(not_a_number, &why).has_value());
  EXPECT_NE(why.find("not a number"), std::string::npos) << why;

  for (double hz : {0.0, -1000.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    AxisRecord no_rate = good;
    no_rate.sample_hz = hz;
    EXPECT_FALSE(fit_axis(no_rate, &why).has_value()) << hz;
    EXPECT_NE(why.find("sample rate"), std::string::npos) << why;
  }

  // The gyro's sign flipped (an IMU mounted the other way, the orientation not set).
  AxisRecord flipped = good;
  for (double& r : flipped.rate) r = -r;
  EXPECT_FALSE(fit_axis(flipped, &why).has_value());
  EXPECT_NE(why.find("against the moment"), std::string::npos) << why;
}

// A rate that is not this moment's answer: the excitation is there, the model explains nothing.
TEST(TuneFit, RefusesARateTheMomentDoesNotExplain) {
  const AxisRecord roll = test::fly(identification(kRollCases[0].truth, 1)).record;
  test::FlightSetup other = identification(kRollCases[0].truth, 2);
  other.prbs_amplitude = 0;
  other.gyro_noise = 0.05;
  AxisRecord mixed = roll;
  mixed.rate = test::fly(other).record.rate;
  std::string why;
  EXPECT_FALSE(fit_axis(mixed, &why).has_value());
  EXPECT_NE(why.find("explains too little"), std::string::npos) << why;
}

}  // namespace
}  // namespace tune
