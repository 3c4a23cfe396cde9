// The landed detector (landed_detector.hpp) on its own, in flight's fixed point: each way it
// decides, and the vibration, bumps and thrusts that must not fool it (issue 29).
#include <gtest/gtest.h>

#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/core/chain/landed_detector.hpp>

namespace qr::chain {
namespace {

using N = FixedNumbers;
constexpr uint32_t kHz = 1000;
using Detector = LandedDetector<N, kHz>;

// A run-time value in a Q format, rounded (the formats' constructors take constants only).
template <class Q>
Q q(double x) {
  return Q::from_raw(static_cast<decltype(Q{}.raw())>(__builtin_llround(__builtin_ldexp(x, Q::frac_bits))));
}

// Thrust in thrust units, specific force in g, height in m, climb in m/s.
Detector::Senses senses(double thrust, double f_z, double height, double climb) {
  return {q<N::Thrust>(thrust), q<N::Accel>(f_z), q<N::Height>(height), q<N::Climb>(climb)};
}

// Ticks until the detector says flying (or `limit`).
template <class SensesAt>
uint32_t ticks_to_fly(Detector& d, uint32_t limit, SensesAt at) {
  uint32_t n = 0;
  while (d.landed() && n < limit) d.update(at(n++));
  return n;
}

// A hover that teaches the detector its hover thrust: taken off by the accelerometer, then 3 s at 1 g.
void learn_hover(Detector& d, double thrust) {
  for (uint32_t n = 0; n < 100; ++n) d.update(senses(thrust * 1.3, -1.3, 0, 0));
  ASSERT_FALSE(d.landed());
  for (uint32_t n = 0; n < 3 * kHz; ++n) d.update(senses(thrust, -1.0, 2.0, 0));
}

// Vibration the 20 Hz low-pass leaves, and the height estimate's noise on the ground at x10 (the
// simulator: within 0.05 m and 0.07 m/s): a deterministic mix of frequencies.
double wobble(uint32_t n, double amplitude) {
  return amplitude * (0.6 * __builtin_sin(n * 0.07) + 0.4 * __builtin_sin(n * 0.31 + 1.0));
}

TEST(LandedDetector, StartsLandedAndNoThrustIsLanded) {
  Detector d;
  EXPECT_TRUE(d.landed());
  EXPECT_FALSE(d.hover_known());
  learn_hover(d, 300);
  d.update(senses(0, -1.0, 2.0, 0));
  EXPECT_TRUE(d.landed()) << "the engines stopped";
}

TEST(LandedDetector, AFirmTakeOffIsSeenByTheAccelerometerIn50ms) {
  Detector d;
  const uint32_t n = ticks_to_fly(d, 1000, [](uint32_t) { return senses(400, -1.3, 0, 0); });
  EXPECT_EQ(n, Detector::kClimbSamples);
}

// A climb at 0.3 m/s that never reads more than 1 g: the height estimate sees it once it is
// 0.1 m up (about 0.33 s) and has stayed so for 50 ms.
TEST(LandedDetector, AGentleTakeOffIsSeenByTheHeightWithinASecond) {
  Detector d;
  for (uint32_t n = 0; n < 2 * kHz; ++n) d.update(senses(280, -1.0 + wobble(n, 0.08), wobble(n, 0.04), 0));
  ASSERT_TRUE(d.landed());
  const uint32_t n = ticks_to_fly(d, 3 * kHz, [](uint32_t k) {
    const double t = k / double{kHz};
    return senses(310, -1.0, 0.3 * t, 0.3);
  });
  EXPECT_LT(n, 1 * kHz) << "ticks from leaving the ground";
  EXPECT_GT(n, 330u) << "not before it is 0.1 m up";
}

// On the ground with the lift below the hover: the accelerometer's vibration, the height
// estimate's noise and a slow drift of it must not read as a take-off, for a whole minute.
TEST(LandedDetector, VibrationAndADriftingHeightOnTheGroundAreNoTakeOff) {
  Detector d;
  for (uint32_t n = 0; n < 60 * kHz; ++n) {
    const double drift = 0.3 * n / (60.0 * kHz);  // the barometer drifting 0.3 m in a minute
    d.update(senses(250, -1.0 + wobble(n, 0.08), drift + wobble(n, 0.05), wobble(n + 500, 0.07)));
    ASSERT_TRUE(d.landed()) << "at tick " << n;
  }
}

// With the hover learnt, a thrust below 90 % of it cannot lift the vehicle: a bump that shakes
// the accelerometer past 1.1 g for 100 ms is no take-off; the same at the hover thrust is.
TEST(LandedDetector, ABumpBelowTheHoverThrustIsNoTakeOff) {
  Detector d;
  learn_hover(d, 300);
  ASSERT_TRUE(d.hover_known());
  EXPECT_NEAR(d.hover().to_double(), 300, 1);
  d.update(senses(0, -1.0, 0, 0));  // set down, engines stopped
  ASSERT_TRUE(d.landed());
  for (uint32_t n = 0; n < 100; ++n) d.update(senses(250, -1.3, 0, 0));
  EXPECT_TRUE(d.landed()) << "250 is below 90 % of the hover thrust 300";
  for (uint32_t n = 0; n < 100; ++n) d.update(senses(300, -1.3, 0, 0));
  EXPECT_FALSE(d.landed());
}

// The hover is learnt only while the accelerometer reads 1 g in the air, and kept.
TEST(LandedDetector, TheHoverIsTheThrustThatFliesAtOneG) {
  Detector d;
  learn_hover(d, 320);
  EXPECT_NEAR(d.hover().to_double(), 320, 1);
  // A climb (1.2 g) with more thrust for 3 s: only the accelerometer mean's first 45 ms or so
  // (its 64 ms time constant) still read 1 g, worth about 2 units; ungated, 3 s at 420 would
  // have taught 398.
  for (uint32_t n = 0; n < 3 * kHz; ++n) d.update(senses(420, -1.2, 5, 2));
  EXPECT_NEAR(d.hover().to_double(), 320, 4);
  const double learnt = d.hover().to_double();
  d.update(senses(0, -1.0, 0, 0));
  EXPECT_EQ(d.hover().to_double(), learnt) << "kept across a landing";
}

// A landing with the lift on: once the hover is known, a thrust below 90 % of it while the
// accelerometer reads 1 g and the height stands still is the ground carrying the vehicle; it
// takes 0.5 s. In the air the same thrust reads less than 1 g (0.67 g here): flying on.
TEST(LandedDetector, TheGroundCarryingTheVehicleIsALanding) {
  Detector d;
  learn_hover(d, 300);
  for (uint32_t n = 0; n < 2 * kHz; ++n) {
    d.update(senses(200, -0.67 + wobble(n, 0.05), 10 - n * 0.001, -1.0));
    ASSERT_FALSE(d.landed()) << "falling, at tick " << n;
  }
  uint32_t n = 0;
  while (!d.landed() && n < kHz) d.update(senses(200, -1.0 + wobble(n++, 0.05), 0, 0));
  EXPECT_GE(n, Detector::kGroundSamples);
  EXPECT_LT(n, Detector::kGroundSamples + 100);
  // At the hover thrust the same readings are a hover, not the ground.
  Detector h;
  learn_hover(h, 300);
  for (uint32_t k = 0; k < 5 * kHz; ++k) h.update(senses(300, -1.0, 0, 0));
  EXPECT_FALSE(h.landed());
}

// Sinking slowly on a thrust below the weight (0.95 g, -0.1 m/s) teaches the weight's thrust,
// T / |f|, not T; a fast descent, where the airframe's drag carries part of the weight and the
// accelerometer reads 1 g on less thrust, teaches nothing (by hand: 6 m/s down on a lift of 510
// taught 510 for a hover of 535).
TEST(LandedDetector, TheHoverIsTheWeightsThrustNotTheThrustOfADescent) {
  Detector d;
  learn_hover(d, 300);
  for (uint32_t n = 0; n < 10 * kHz; ++n) d.update(senses(285, -0.95, 20, -0.1));
  EXPECT_NEAR(d.hover().to_double(), 285 / 0.95, 1.5) << "the weight's thrust, 300";
  for (uint32_t n = 0; n < 10 * kHz; ++n) d.update(senses(250, -1.0, 10, -6));
  EXPECT_NEAR(d.hover().to_double(), 300, 1.5) << "a fast descent on 250 at 1 g teaches nothing";
}

// On the ground with the lift a little below the hover (94 % of the hover lift: 88 % of its
// thrust), the vehicle is not flying: the ground carries the rest.
TEST(LandedDetector, ALiftJustBelowTheHoverOnTheGroundIsLanded) {
  Detector d;
  learn_hover(d, 300);
  uint32_t n = 0;
  while (!d.landed() && n < 2 * kHz) d.update(senses(265, -1.0 + wobble(n++, 0.05), 0, 0));
  EXPECT_TRUE(d.landed()) << "at 88 % of the hover thrust, on the ground";
  EXPECT_LT(n, Detector::kGroundSamples + 100);
}

// The ground carrying the vehicle needs the accelerometer to agree: with the height estimate
// standing still (a barometer stuck, or an estimate the vibration biases) but the accelerometer
// reading 0.7 g, a thrust of 70 % of the hover is a fall, not the ground.
TEST(LandedDetector, AStillHeightWithoutOneGIsNoLanding) {
  Detector d;
  learn_hover(d, 300);
  for (uint32_t n = 0; n < 3 * kHz; ++n) {
    d.update(senses(210, -0.7, 2.0, 0));
    ASSERT_FALSE(d.landed()) << "at tick " << n;
  }
}

// A landing's touchdown (a vibrating accelerometer's impact) counts only near the ground the
// vehicle took off from: at 4 m it is refused, at 0.5 m taken.
TEST(LandedDetector, ATouchdownInTheAirIsRefused) {
  Detector d;
  d.take_off();
  d.touch_down(q<N::Height>(4.0));
  EXPECT_FALSE(d.landed());
  d.touch_down(q<N::Height>(0.5));
  EXPECT_TRUE(d.landed());
}

TEST(LandedDetector, NearGroundIsWithinOneMetreOfWhereItLastStood) {
  Detector d;
  for (uint32_t n = 0; n < 100; ++n) d.update(senses(100, -1.0, 2.0, 0));  // rests at 2 m (a table)
  EXPECT_TRUE(d.near_ground(N::Height(2.9)));
  EXPECT_FALSE(d.near_ground(N::Height(3.1)));
  EXPECT_TRUE(d.near_ground(N::Height(-4.0))) << "below the table is near too";
}

}  // namespace
}  // namespace qr::chain
