// The safety rules that live in the chain (docs/safety.md rules 4 and 6), each on the real
// FlightChain: a calibration run counts only when it is whole, a landing ends on its impact near
// the ground, the integrals stay empty on the ground, a clipped gyro run still turns the estimate.
// scripts/mutate weakens each and builds this file alone (chain-rule-tests), so every mutant of
// the chain's rules is killed by a test that names its rule.
#include <gtest/gtest.h>

#include <cmath>

#include <qr/core/chain/flight_chain.hpp>

#include "chain_pilot.hpp"

namespace qr {
namespace {

using chain::test::climbing;
using chain::test::Mode;
using chain::test::Pilot;
using chain::test::sample_at;
using chain::test::sticks;

// Rule 4: yaw and full control need a finished calibration. A run left before its last sample
// (the pilot's abort key, a panic) is none, and does not undo an earlier whole run either.
TEST(ChainRules, AnAbortedCalibrationIsNoCalibration) {
  FixedChain chain;
  chain.enter_calibration();
  for (int32_t n = 0; n < chain::kCalibrationSamples - 1; ++n) {
    chain.filter(sample_at(0, 0));
    ASSERT_FALSE(chain.calibrate()) << "sample " << n;
  }
  EXPECT_FALSE(chain.calibrated()) << "one sample short of a run";
  chain.enter_calibration();  // again, and this time whole
  int32_t n = 0;
  for (chain.filter(sample_at(0, 0)); !chain.calibrate(); chain.filter(sample_at(0, 0))) ++n;
  EXPECT_EQ(n + 1, chain::kCalibrationSamples);
  EXPECT_TRUE(chain.calibrated());
  chain.enter_calibration();  // a third, aborted after one sample: the second's offsets stay
  chain.filter(sample_at(0, 0));
  EXPECT_FALSE(chain.calibrate());
  EXPECT_TRUE(chain.calibrated());
}

// A chain flying as the flight's task table runs it, with the height task and the vertical loops
// at their 250 Hz, the barometer reading `pressure_pa`.
struct Landing {
  Pilot<FixedChain> p;
  static constexpr int32_t kGroundPa = 101325;
  // The barometer's reading at h metres above the ground (the standard atmosphere's 12 Pa/m).
  static int32_t pressure_at(double h) { return kGroundPa - static_cast<int32_t>(std::lround(12.0 * h)); }
  void tick(const SensorSample& s, uint16_t lift) {
    p.tick(Mode::full, s, sticks(lift));
    if (p.ticks_run % FixedChain::kHeightDivider == 1) {
      p.chain.estimate_height();
      p.chain.control_vertical();
    }
  }
  // Calibrated on the ground, then climbing off and hovering at `height` for 3 s.
  void fly_at(double height) {
    SensorSample rest = sample_at(0, 0);
    rest.pressure_pa = pressure_at(0);
    p.chain.enter_calibration();
    for (p.chain.filter(rest); !p.chain.calibrate(); p.chain.filter(rest)) {
    }
    for (int t = 0; t < 500; ++t) {
      SensorSample s = climbing(1.2);
      s.pressure_pa = pressure_at(height * t / 500.0);
      tick(s, 600);
    }
    for (int t = 0; t < 3000; ++t) {
      SensorSample s = sample_at(0, 0);
      s.pressure_pa = pressure_at(height);
      tick(s, 550);
    }
    ASSERT_FALSE(p.chain.landed());
  }
};

// Rule 6: a landing ends at its touchdown, and the touchdown near the ground is the impact: the
// accelerometer beyond 1.3 g against the thrust for 5 ms. Here the vehicle is still sinking
// when it hits (the barometer says so), so only the impact can end the landing; the engines
// must stop within the impact's 5 ms and the filters' few.
TEST(ChainRules, ALandingEndsOnItsImpactNearTheGround) {
  Landing l;
  l.fly_at(0.5);
  l.p.chain.start_descent(550);
  l.p.chain.fly(chain::kLanding);
  for (int t = 0; t < 1000; ++t) {  // sinking at 0.5 m/s from 0.5 m
    SensorSample s = sample_at(0, 0);
    s.pressure_pa = Landing::pressure_at(std::max(0.0, 0.5 - 0.5 * t / 1000.0));
    l.tick(s, 0);
    ASSERT_FALSE(l.p.chain.landed()) << "before the impact, tick " << t;
  }
  int ticks = 0;
  for (; ticks < 100 && !l.p.chain.landed(); ++ticks) {
    SensorSample s = climbing(2.5);  // the ground's blow
    s.pressure_pa = Landing::pressure_at(0);
    l.tick(s, 0);
  }
  EXPECT_TRUE(l.p.chain.landed());
  EXPECT_LE(ticks, 20) << "the impact ends the landing";
}

// Rule 6: the same blow high above the ground (a gust, a vibration burst) is no touchdown: the
// landing flies on.
TEST(ChainRules, AnImpactHighAboveTheGroundIsNoTouchdown) {
  Landing l;
  l.fly_at(5);
  l.p.chain.start_descent(550);
  l.p.chain.fly(chain::kLanding);
  for (int t = 0; t < 1000; ++t) {
    SensorSample s = t > 500 && t < 600 ? climbing(2.5) : sample_at(0, 0);
    s.pressure_pa = Landing::pressure_at(5 - 0.5 * t / 1000.0);
    l.tick(s, 0);
  }
  EXPECT_FALSE(l.p.chain.landed());
}

// The integrals on the ground (issue 14): held empty from lift 0 until the vehicle climbs off,
// whatever the sticks ask for, for far longer than they would take to wind up in flight.
TEST(ChainRules, OnTheGroundTheIntegralsStayEmpty) {
  Pilot<FixedChain> p;
  p.calibrate_level();
  // Sticks the mixer can answer at this lift (scaled-down moments would hold the integrals anyway).
  p.run(Mode::full, sample_at(0, 0), sticks(400, 100, -100, 300), 20000);
  EXPECT_TRUE(p.chain.landed());
  EXPECT_EQ(p.chain.roll_integral_e3(), 0);
  EXPECT_EQ(p.chain.pitch_integral_e3(), 0);
  EXPECT_EQ(p.chain.integral_e1(2), 0);
}

// What a gyro run clipped at full scale hid is added to the estimate (gyro_clip.hpp): a roll
// rate that rises to 1.5 times full scale and back turns the estimate by nearly what it turned,
// where the clipped samples alone fall a fifth short.
TEST(ChainRules, AClippedGyroRunStillTurnsTheEstimate) {
  Pilot<FixedChain> p;
  p.calibrate_level();
  p.run(Mode::manual, sample_at(0, 0), sticks(0), 100);
  const double c = sensor::kGyroCountsPerRadPerSec, full = 32767 / c;  // rad/s
  double turned = 0;                                                   // rad, the truth
  for (int t = 0; t <= 160; ++t) {
    const double rate = 1.5 * full * (t <= 80 ? t / 80.0 : (160 - t) / 80.0);
    turned += rate * 0.001;
    SensorSample s = sample_at(0, 0);  // the accelerometer still level: only the gyro speaks
    s.gyro[0] = chain::test::counts(c * rate);
    p.tick(Mode::manual, s, sticks(0));
  }
  p.run(Mode::manual, sample_at(0, 0), sticks(0), 50);  // the filter settles, the bridge adds
  const double roll = p.chain.roll_e4() * 1e-4;
  EXPECT_NEAR(roll, turned, 0.05 * turned) << "turned " << turned << " rad, estimated " << roll;
}

}  // namespace
}  // namespace qr
