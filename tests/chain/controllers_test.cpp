// The controllers: signs (docs/conventions.md), saturation, gains in the parameter formats, and
// the Q instantiation against double.
#include <gtest/gtest.h>

#include <random>

#include <qr/core/chain/controllers.hpp>
#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/tools/real_numbers.hpp>

#include "chain_test_support.hpp"

namespace qr::chain {
namespace {

using F = FixedNumbers;
using D = DoubleNumbers;

template <class T>
T to(double v) {
  if constexpr (fx::is_q<T>) {
    return test::quantise<T>(v);
  } else {
    return static_cast<T>(v);
  }
}

// Defaults of the parameter table: p1 = 4 /s, p2 = 50 and yaw_p = 100 thrust units per rad/s.
template <class N>
AttitudeController<N> tilt_controller(int32_t p1 = 1024, int32_t p2 = 800) {
  AttitudeController<N> c;
  c.set_gains(p1, p2);
  return c;
}
template <class N>
YawRateController<N> yaw_controller(int32_t yaw_p = 1600) {
  YawRateController<N> c;
  c.set_gain(yaw_p);
  return c;
}

template <class N>
double roll_moment(double setpoint, double angle, double rate) {
  auto c = tilt_controller<N>();
  return test::as_double(c.moment(to<typename N::Angle>(setpoint), to<typename N::Angle>(angle), to<typename N::Rate>(rate)));
}

TEST(Controllers, PositiveAngleErrorGivesPositiveMoment) {
  // Set-point above the estimate (vehicle should roll right / pitch nose up): positive moment.
  EXPECT_GT(roll_moment<F>(0.1, 0.0, 0.0), 0.0);
  EXPECT_GT(roll_moment<F>(0.0, -0.1, 0.0), 0.0);
  EXPECT_LT(roll_moment<F>(0.0, 0.1, 0.0), 0.0);  // tilted right, level wanted: roll back left
  EXPECT_NEAR(roll_moment<F>(0.1, 0.0, 0.0), 4 * 0.1 * 50, 1e-3);  // P2 x P1 x error
}

TEST(Controllers, RateLoopDampsMotion) {
  // On target but rolling right: the rate loop pushes back.
  EXPECT_LT(roll_moment<F>(0.0, 0.0, 0.5), 0.0);
  EXPECT_GT(roll_moment<F>(0.0, 0.0, -0.5), 0.0);
  EXPECT_NEAR(roll_moment<F>(0.0, 0.0, 0.5), -25.0, 1e-3);
}

TEST(Controllers, PositiveYawRateErrorGivesPositiveYawMoment) {
  const auto c = yaw_controller<F>();
  EXPECT_GT(c.moment(to<F::Rate>(0.5), to<F::Rate>(0.0)).to_double(), 0.0);
  EXPECT_LT(c.moment(to<F::Rate>(0.0), to<F::Rate>(0.5)).to_double(), 0.0);
  EXPECT_NEAR(c.moment(to<F::Rate>(0.5), to<F::Rate>(0.2)).to_double(), 100 * 0.3, 1e-3);
}

TEST(Controllers, OutputsSaturate) {
  auto c = tilt_controller<F>(5120, 16000);  // largest gains the table allows
  EXPECT_EQ(c.moment(to<F::Angle>(0.35), to<F::Angle>(-3.1), to<F::Rate>(-9.0)), kMaxMoment<F>);
  EXPECT_EQ(c.rate_setpoint(), kMaxTiltRateSetpoint<F>);
  EXPECT_EQ(c.moment(to<F::Angle>(-0.35), to<F::Angle>(3.1), to<F::Rate>(9.0)), -kMaxMoment<F>);
  EXPECT_EQ(c.rate_setpoint(), -kMaxTiltRateSetpoint<F>);
  // A yaw error beyond the rate format's +-16 rad/s is still the right sign, clamped.
  const auto y = yaw_controller<F>(16000);
  EXPECT_EQ(y.moment(to<F::Rate>(8.0), to<F::Rate>(-9.0)), kMaxMoment<F>);
  EXPECT_EQ(y.moment(to<F::Rate>(-8.0), to<F::Rate>(9.0)), -kMaxMoment<F>);
}

TEST(Controllers, ZeroGainGivesZeroMoment) {
  auto c = tilt_controller<F>(0, 0);
  EXPECT_EQ(c.moment(to<F::Angle>(0.3), to<F::Angle>(0.0), to<F::Rate>(1.0)), F::Thrust{});
}

// Same inputs, Q against double: the only difference is one rounding per product, to the Rate
// lsb (7.5e-9 rad/s) in the angle loop and the Thrust lsb (1.5e-5) in the rate loop, so the
// moment differs by at most P2 x 0.5 lsb(Rate) + 0.5 lsb(Thrust) = 1.14e-5 thrust units.
TEST(Controllers, FixedFollowsDouble) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(-1.0, 1.0), setpoint(-0.35, 0.35), rate(-8.0, 8.0);
  std::uniform_int_distribution<int32_t> p1(0, 5120), p2(0, 16000);
  test::MaxError tilt("attitude cascade, thrust units"), yaw("yaw rate loop, thrust units");
  for (int i = 0; i < 200000; ++i) {
    const int32_t g1 = p1(rng), g2 = p2(rng);
    auto cf = tilt_controller<F>(g1, g2);
    auto cd = tilt_controller<D>(g1, g2);
    const F::Angle sp = to<F::Angle>(setpoint(rng)), a = to<F::Angle>(angle(rng));
    const F::Rate r = to<F::Rate>(rate(rng));
    const double mf = cf.moment(sp, a, r).to_double();
    const double md = cd.moment(sp.to_double(), a.to_double(), r.to_double());
    tilt.add(mf - md, md);
    const auto yf = yaw_controller<F>(g2);
    const auto yd = yaw_controller<D>(g2);
    const F::Rate ys = to<F::Rate>(rate(rng));
    yaw.add(yf.moment(ys, r).to_double() - yd.moment(ys.to_double(), r.to_double()), 0);
  }
  const double tilt_bound = 1000 * 0x1p-28 + 0x1p-17;  // P2 max 1000 x half a Rate lsb + half a Thrust lsb
  tilt.print(tilt_bound);
  yaw.print(0x1p-17);
  EXPECT_LE(tilt.max(), tilt_bound);
  EXPECT_LE(yaw.max(), 0x1p-17);
}

}  // namespace
}  // namespace qr::chain
