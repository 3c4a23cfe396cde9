// The controllers: signs (docs/conventions.md), saturation, gains in the parameter formats, and
// the Q instantiation against double.
#include <gtest/gtest.h>

#include <random>

#include <qr/core/chain/controllers.hpp>
#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/host/real_numbers.hpp>

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

// The sign and saturation checks use plain P-P gains (p1 = 4 /s, p2 = 50 thrust units per
// rad/s, no I or D: the IN4073 cascade), so their expected values are easy to read; the integral
// and derivative have tests of their own below.
template <class N>
AttitudeController<N> tilt_controller(int32_t p1 = 1024, int32_t p2 = 800, int32_t i = 0, int32_t d = 0) {
  AttitudeController<N> c;
  c.set_gains(p1, p2, i, d);
  return c;
}
template <class N>
YawRateController<N> yaw_controller(int32_t yaw_p = 1600) {
  YawRateController<N> c;
  c.set_gains(yaw_p);
  return c;
}

template <class N>
double roll_moment(double setpoint, double angle, double rate) {
  auto c = tilt_controller<N>();
  return test::as_double(
      c.moment(to<typename N::Angle>(setpoint), to<typename N::Angle>(angle), to<typename N::Rate>(rate)));
}

TEST(Controllers, PositiveAngleErrorGivesPositiveMoment) {
  // Set-point above the estimate (vehicle should roll right / pitch nose up): positive moment.
  EXPECT_GT(roll_moment<F>(0.1, 0.0, 0.0), 0.0);
  EXPECT_GT(roll_moment<F>(0.0, -0.1, 0.0), 0.0);
  EXPECT_LT(roll_moment<F>(0.0, 0.1, 0.0), 0.0);                   // tilted right, level wanted: roll back left
  EXPECT_NEAR(roll_moment<F>(0.1, 0.0, 0.0), 4 * 0.1 * 50, 1e-3);  // P2 x P1 x error
}

TEST(Controllers, RateLoopDampsMotion) {
  // On target but rolling right: the rate loop pushes back.
  EXPECT_LT(roll_moment<F>(0.0, 0.0, 0.5), 0.0);
  EXPECT_GT(roll_moment<F>(0.0, 0.0, -0.5), 0.0);
  EXPECT_NEAR(roll_moment<F>(0.0, 0.0, 0.5), -25.0, 1e-3);
}

TEST(Controllers, PositiveYawRateErrorGivesPositiveYawMoment) {
  auto c = yaw_controller<F>();
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
  auto y = yaw_controller<F>(16000);
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
    auto yf = yaw_controller<F>(g2);
    auto yd = yaw_controller<D>(g2);
    const F::Rate ys = to<F::Rate>(rate(rng));
    yaw.add(yf.moment(ys, r).to_double() - yd.moment(ys.to_double(), r.to_double()), 0);
  }
  const double tilt_bound = 1000 * 0x1p-28 + 0x1p-17;  // P2 max 1000 x half a Rate lsb + half a Thrust lsb
  tilt.print(tilt_bound);
  yaw.print(0x1p-17);
  EXPECT_LE(tilt.max(), tilt_bound);
  EXPECT_LE(yaw.max(), 0x1p-17);
}

// ---- the rate loop's integral and derivative ----

using FAngle = F::Angle;
using FRate = F::Rate;

// I = 100 thrust units per rad (raw Q<4> 1600): a steady rate error of 0.1 rad/s adds
// 100 x 0.1 = 10 thrust units per second to the moment, at 1 kHz and at 500 Hz alike.
template <uint32_t Hz>
void IntegralAddsTheRateErrorOverTime() {
  AttitudeController<F, Hz> c;
  c.set_gains(0, 800, 1600, 0);  // P1 = 0: the rate set-point is 0, the rate error is -rate
  F::Thrust m{};
  for (uint32_t n = 0; n < Hz; ++n) m = c.moment(FAngle{}, FAngle{}, test::quantise<FRate>(-0.1), true);
  EXPECT_NEAR(c.integral().to_double(), 10.0, 1e-4);
  EXPECT_NEAR(m.to_double(), 50 * 0.1 + 10.0, 1e-4);  // P2 x error + integral
}
TEST(Controllers, IntegralAddsTheRateErrorOverTimeAt1kHz) { IntegralAddsTheRateErrorOverTime<1000>(); }
TEST(Controllers, IntegralAddsTheRateErrorOverTimeAt500Hz) { IntegralAddsTheRateErrorOverTime<500>(); }

// Its sign is the proportional part's: a held angle error (set-point above the estimate) builds
// a positive moment, which is what holds a banked vehicle against a moment that tilts it back.
TEST(Controllers, IntegralOfAHeldAngleErrorPushesTowardTheSetPoint) {
  auto c = tilt_controller<F>(1024, 800, 1600);
  double first = 0, last = 0;
  for (int n = 0; n < 500; ++n) {
    const double m = c.moment(test::quantise<FAngle>(0.02), FAngle{}, FRate{}, true).to_double();
    if (n == 0) first = m;
    last = m;
  }
  EXPECT_GT(c.integral().to_double(), 0.0);
  EXPECT_NEAR(c.integral().to_double(), 100 * 4 * 0.02 * 0.5, 1e-3);  // I x P1 x error x 0.5 s
  EXPECT_GT(last, first);
  auto n = tilt_controller<F>(1024, 800, 1600);
  for (int k = 0; k < 500; ++k) n.moment(test::quantise<FAngle>(-0.02), FAngle{}, FRate{}, true);
  EXPECT_NEAR(n.integral().to_double(), -4.0, 1e-3);
}

// Anti-windup: no growth while the caller says no (the mixer limited the moments), none while
// the moment is at its clamp, never beyond kMaxIntegralMoment, and reset() empties it.
TEST(Controllers, IntegralIsHeldClampedAndReset) {
  auto held = tilt_controller<F>(1024, 800, 1600);
  for (int n = 0; n < 1000; ++n) held.moment(test::quantise<FAngle>(0.1), FAngle{}, FRate{}, false);
  EXPECT_EQ(held.integral(), F::Thrust{});

  // A rate error of 2 rad/s: P2 x 2 = 100 thrust units, the integral grows 200 per second.
  auto growing = tilt_controller<F>(0, 800, 1600);
  for (int n = 0; n < 3000; ++n) growing.moment(FAngle{}, FAngle{}, test::quantise<FRate>(-2.0), true);
  EXPECT_EQ(growing.integral(), kMaxIntegralMoment<F>);
  for (int n = 0; n < 3000; ++n) growing.moment(FAngle{}, FAngle{}, test::quantise<FRate>(2.0), true);
  EXPECT_EQ(growing.integral(), -kMaxIntegralMoment<F>);
  // Back from the clamp at once: the sum was clamped with it, nothing is stored beyond it.
  growing.moment(FAngle{}, FAngle{}, test::quantise<FRate>(-0.5), true);
  EXPECT_GT(growing.integral(), -kMaxIntegralMoment<F>);
  growing.reset();
  EXPECT_EQ(growing.integral(), F::Thrust{});

  // At the moment's own clamp (P alone asks for more than 1000) the integral stays where it is.
  auto saturated = tilt_controller<F>(0, 16000, 1600);
  for (int n = 0; n < 1000; ++n) {
    EXPECT_EQ(saturated.moment(FAngle{}, FAngle{}, test::quantise<FRate>(-2.0), true), kMaxMoment<F>);
  }
  EXPECT_EQ(saturated.integral(), F::Thrust{});
}

// Far from the set-point the integral learns at an eighth of its rate (kIntegralZone): a push
// that holds the angle off must not be learnt as a trim, or the vehicle hangs the other way
// after it (sim/scenarios/held-push.txt). Within the zone it learns at its full rate.
TEST(Controllers, IntegralLearnsSlowlyFarFromTheSetPoint) {
  // P1 = 4 /s, I = 100: an angle error of 0.05 rad (within 5 degrees) is a rate error of 0.2
  // rad/s, 20 thrust units a second; one of 0.2 rad (11 degrees) is 0.8 rad/s, 80 a second at
  // the full rate and 10 at an eighth.
  auto near = tilt_controller<F>(1024, 800, 1600);
  auto far = tilt_controller<F>(1024, 800, 1600);
  for (int n = 0; n < 1000; ++n) {
    near.moment(test::quantise<FAngle>(0.05), FAngle{}, FRate{}, true);
    far.moment(test::quantise<FAngle>(0.2), FAngle{}, FRate{}, true);
  }
  EXPECT_NEAR(near.integral().to_double(), 20.0, 1e-3);
  EXPECT_NEAR(far.integral().to_double(), 10.0, 1e-3);
  // Either side of the set-point alike.
  auto below = tilt_controller<F>(1024, 800, 1600);
  for (int n = 0; n < 1000; ++n) below.moment(FAngle{}, test::quantise<FAngle>(0.2), FRate{}, true);
  EXPECT_NEAR(below.integral().to_double(), -10.0, 1e-3);
}

// An integral far below the Thrust lsb per tick still accumulates: 1e-6 rad/s of rate error at
// I = 100 is 1e-7 thrust units per tick (the Thrust lsb is 1.5e-5, so a Thrust sum would stay
// at 0), 0.01 after 100 s (the rate quantised to Q<27> is 0.9984e-6 rad/s).
TEST(Controllers, IntegralOfATinyRateErrorIsNotLost) {
  auto c = tilt_controller<F>(0, 800, 1600);
  const FRate tiny = test::quantise<FRate>(-1e-6);
  for (int n = 0; n < 100000; ++n) c.moment(FAngle{}, FAngle{}, tiny, true);
  // Within the read-out's rounding (half a Thrust lsb) and I dt's own (2^-20 / 0.1 relative).
  EXPECT_NEAR(c.integral().to_double(), 100 * 100 * -tiny.to_double(), 0x1p-17 + 1e-7);
}

// D acts on the measured rate: a set-point step gives no kick, a growing rate is opposed
// (D x d rate / dt), and the first call after reset() has no derivative.
TEST(Controllers, DerivativeOpposesRateChangesAndIgnoresSetPointSteps) {
  auto c = tilt_controller<F>(1024, 800, 0, 768);  // D = 3 thrust units per rad/s^2
  c.moment(FAngle{}, FAngle{}, FRate{});
  // Set-point step: P1 P2 x 0.1 = 20, and nothing from D.
  EXPECT_NEAR(c.moment(test::quantise<FAngle>(0.1), FAngle{}, FRate{}).to_double(), 20.0, 1e-3);
  // The rate grows by 0.01 rad/s in one tick (10 rad/s^2): D adds -30, P2 -0.5.
  EXPECT_NEAR(c.moment(FAngle{}, FAngle{}, test::quantise<FRate>(0.01)).to_double(), -30.5, 1e-3);
  // Steady rate: no derivative.
  EXPECT_NEAR(c.moment(FAngle{}, FAngle{}, test::quantise<FRate>(0.01)).to_double(), -0.5, 1e-3);
  c.reset();
  EXPECT_NEAR(c.moment(FAngle{}, FAngle{}, test::quantise<FRate>(0.5)).to_double(), -25.0, 1e-3);
}

// The terms a live plot shows (roll_p_term, roll_d_term, roll_integral, yaw_p_term, ...) are the
// ones the moment was made of: P2 x error, -D x the rate's change and the integral add up to the
// moment while it is inside its clamp, on random inputs and gains.
TEST(Controllers, TheTermsAPlotShowsAddUpToTheMoment) {
  auto c = tilt_controller<F>(1024, 800, 0, 768);
  c.moment(FAngle{}, FAngle{}, FRate{});
  c.moment(FAngle{}, FAngle{}, test::quantise<FRate>(0.01));  // 10 rad/s^2: D x 10 = 30, P2 x 0.01
  EXPECT_NEAR(c.p_term().to_double(), -0.5, 1e-3);
  EXPECT_NEAR(c.d_term().to_double(), -30.0, 1e-3);

  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> angle(-0.2, 0.2), rate(-0.01, 0.01);
  std::uniform_int_distribution<int32_t> p1(0, 2560), p2(0, 2400), i(0, 3200), d(0, 1280);
  int checked = 0;
  for (int run = 0; run < 100; ++run) {
    AttitudeController<F> tilt;
    tilt.set_gains(p1(rng), p2(rng), i(rng), d(rng));
    YawRateController<F> yaw;
    yaw.set_gains(p2(rng), i(rng));
    for (int n = 0; n < 100; ++n) {
      const F::Rate r = to<F::Rate>(rate(rng));
      const double m = tilt.moment(to<F::Angle>(angle(rng)), to<F::Angle>(angle(rng)), r, n % 5 != 0).to_double();
      const double sum = tilt.p_term().to_double() + tilt.d_term().to_double() + tilt.integral().to_double();
      EXPECT_NEAR(m, sum, 3 * 0x1p-16) << "run " << run << " tick " << n;  // each part rounded to a Thrust lsb
      const double y = yaw.moment(to<F::Rate>(angle(rng)), r, n % 3 != 0).to_double();
      EXPECT_NEAR(y, yaw.p_term().to_double() + yaw.integral().to_double(), 1e-9);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 10000);
}

// Sequences of random inputs and gains through the PID cascade, Q against double, with the
// inputs quantised alike. Gains and inputs are drawn so that the moment never reaches its clamp
// (P2 <= 150 x 4 rad/s, D <= 5 x 0.02 rad/s per tick x 1000, integral <= 200: at most 900), so
// both sides always take the same branch. The differences: the rate set-point's rounding to
// Rate times P2 (150 x 2^-28), the P, D and integral parts' roundings to Thrust (3 x 2^-17), and
// I dt rounded to Q<19> (2^-20) times the rate error (<= 4.01 rad/s), summed over 200 ticks.
TEST(Controllers, PidCascadeFixedFollowsDouble) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> angle(-0.2, 0.2), rate(-0.01, 0.01);
  std::uniform_int_distribution<int32_t> p1(0, 2560), p2(0, 2400), i(0, 3200), d(0, 1280);
  test::MaxError err("PID cascade over 200-tick sequences, thrust units");
  for (int run = 0; run < 500; ++run) {
    const int32_t g1 = p1(rng), g2 = p2(rng), gi = i(rng), gd = d(rng);
    AttitudeController<F> cf;
    AttitudeController<D> cd;
    cf.set_gains(g1, g2, gi, gd);
    cd.set_gains(g1, g2, gi, gd);
    for (int n = 0; n < 200; ++n) {
      const F::Angle sp = to<F::Angle>(angle(rng)), a = to<F::Angle>(angle(rng));
      const F::Rate r = to<F::Rate>(rate(rng));
      const bool integrate = n % 7 != 0;
      const double mf = cf.moment(sp, a, r, integrate).to_double();
      const double md = cd.moment(sp.to_double(), a.to_double(), r.to_double(), integrate);
      err.add(mf - md, md);
    }
  }
  const double bound = 150 * 0x1p-28 + 3 * 0x1p-17 + 200 * 4.01 * 0x1p-20;
  err.print(bound);
  EXPECT_LE(err.max(), bound);
}

}  // namespace
}  // namespace qr::chain

namespace qr::chain {
namespace {

// The feed-forward (the body rate that holds the angle while yawing) adds to the angle loop's
// rate set-point: with no angle error the rate loop is asked for exactly it, and the integral
// sees no error when the vehicle turns at it. The sum is clamped as before (+-4 rad/s).
TEST(Controllers, FeedForwardAddsToTheRateSetPoint) {
  auto c = tilt_controller<F>(1024, 800, 1600);
  c.moment(FAngle{}, FAngle{}, FRate{}, true, test::quantise<FRate>(0.3));
  EXPECT_NEAR(c.rate_setpoint().to_double(), 0.3, 1e-8);
  // Turning at the feed-forward rate: no rate error, no moment, the integral stays empty.
  c.reset();
  for (int n = 0; n < 1000; ++n) {
    EXPECT_EQ(c.moment(FAngle{}, FAngle{}, test::quantise<FRate>(0.3), true, test::quantise<FRate>(0.3)), F::Thrust{});
  }
  EXPECT_EQ(c.integral(), F::Thrust{});
  // With an angle error the two add: P1 x 0.1 = 0.4, plus 0.3.
  c.moment(test::quantise<FAngle>(0.1), FAngle{}, FRate{}, false, test::quantise<FRate>(0.3));
  EXPECT_NEAR(c.rate_setpoint().to_double(), 0.7, 1e-6);
  // Clamped: P1 x 2 = 8 and 4 more are 4, and -8 with +4 is -4, not a wrapped value.
  c.moment(test::quantise<FAngle>(2.0), FAngle{}, FRate{}, false, test::quantise<FRate>(9.0));
  EXPECT_EQ(c.rate_setpoint(), kMaxTiltRateSetpoint<F>);
  c.moment(test::quantise<FAngle>(-3.0), FAngle{}, FRate{}, false, test::quantise<FRate>(4.0));
  EXPECT_NEAR(c.rate_setpoint().to_double(), -4.0, 1e-8);
}

}  // namespace
}  // namespace qr::chain
