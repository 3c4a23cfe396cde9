// The gyro's scale: the per-axis correction where counts become units (0 ppm is the nominal, bit
// for bit), offsets converted again when the scale changes, and the turn measurement: a turn of
// the count asked for about one body axis gives that axis' scale; a miscounted turn, a turn about
// a tilted axis, and no turn at all give none.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/core/chain/gyro_turns.hpp>
#include <qr/core/chain/sensor_calibration.hpp>
#include <qr/host/real_numbers.hpp>

namespace qr::chain {
namespace {

using Units = SensorUnits<FixedNumbers>;
using Rate = FixedNumbers::Rate;
constexpr uint32_t kHz = 1000;
constexpr double kTwoPi = 2 * std::numbers::pi;

TEST(GyroScale, ZeroPpmIsTheNominalScaleBitForBit) {
  EXPECT_EQ(Units::rate_per_count(0).raw(), 35764);
  for (int32_t c = INT16_MIN; c <= INT16_MAX; ++c) {
    ASSERT_EQ(Units::rate_of(c, Units::rate_per_count(0)).raw(), Units::rate_of(c).raw()) << c;
  }
  // The calibration's sums (9 fractional bits) as well: the offsets of a default vehicle are the
  // ones it had before the correction existed.
  for (int32_t sum = -(1 << 24); sum <= (1 << 24); sum += 997) {
    ASSERT_EQ(Units::rate_of<kCalibrationShift>(sum, Units::rate_per_count(0)).raw(),
              Units::rate_of<kCalibrationShift>(sum).raw())
        << sum;
  }
  EXPECT_EQ(SensorUnits<DoubleNumbers>::rate_per_count(0), SensorUnits<DoubleNumbers>::kRadPerSecPerCount);
}

TEST(GyroScale, ACountOfAHighReadingAxisIsWorthLess) {
  for (const int32_t ppm : {-100000, -30000, -1, 1, 20000, 100000}) {
    const double expected = SensorUnits<DoubleNumbers>::kRadPerSecPerCount / (1 + ppm * 1e-6);
    EXPECT_NEAR(Units::rate_per_count(ppm).to_double(), expected, 0.51 / (1 << 27)) << ppm;
    EXPECT_NEAR(SensorUnits<DoubleNumbers>::rate_per_count(ppm), expected, 1e-15) << ppm;
    // The whole counts' fast product is the exact one.
    for (const int32_t c : {INT16_MIN, -12345, -1, 0, 1, 9999, INT16_MAX}) {
      ASSERT_EQ(Units::rate_of(c, Units::rate_per_count(ppm)).raw(),
                (product<Rate>(FixedNumbers::fixed<0>(c), Units::rate_per_count(ppm)).raw()))
          << ppm << " " << c;
    }
  }
}

TEST(GyroScale, OffsetsInUseFollowAScaleChange) {
  SensorCalibration<FixedNumbers> c;
  SensorSample s;
  s.gyro[0] = 400;
  s.accel[2] = -8192;
  for (int32_t n = 0; n < kCalibrationSamples; ++n) c.add(s);
  const Rate scale[3] = {Units::rate_per_count(50000), Units::rate_per_count(0), Units::rate_per_count(0)};
  c.set_gyro_scale(scale);
  EXPECT_EQ(c.gyro_offset(0).raw(), Units::rate_of(400, scale[0]).raw());
  // A run started (sums forgotten) keeps converting the offsets in use, not its partial sums.
  c.restart();
  const Rate nominal[3] = {Units::rate_per_count(0), Units::rate_per_count(0), Units::rate_per_count(0)};
  c.set_gyro_scale(nominal);
  EXPECT_EQ(c.gyro_offset(0).raw(), Units::rate_of(400).raw());
}

// A person turning the vehicle: `turns` turns about body axis `axis` tilted by `tilt` rad towards
// the next axis, in `seconds` with a rate that starts and ends at zero, the gyro reading `scale`
// times the truth plus `bias` counts; rest before and after.
struct TurnRig {
  int32_t offsets[3] = {};
  int16_t bias[3] = {40, -25, 15};

  SensorSample sample(const double (&rate)[3], const double (&scale)[3]) const {
    SensorSample s;
    for (int i = 0; i < 3; ++i) {
      s.gyro[i] = static_cast<int16_t>(std::lround(bias[i] + scale[i] * rate[i] * sensor::kGyroCountsPerRadPerSec));
    }
    s.accel[2] = -8192;
    return s;
  }
  void calibrate(GyroTurns<kHz>& t, int32_t turns) {
    SensorCalibration<FixedNumbers> c;
    const double still[3] = {0, 0, 0}, unit[3] = {1, 1, 1};
    for (int32_t n = 0; n < kCalibrationSamples; ++n) c.add(sample(still, unit));
    for (int i = 0; i < 3; ++i) offsets[i] = c.gyro_offset_counts()[i];
    t.start(turns, c.gyro_offset_counts());
  }
  // Runs rest, turn, rest through t; the sample count at which it ended (0: it did not).
  int32_t turn(GyroTurns<kHz>& t, int axis, double turns, double seconds, const double (&scale)[3],
               double tilt = 0) const {
    const double still[3] = {0, 0, 0};
    int32_t n = 0;
    for (int k = 0; k < 700; ++k, ++n) {
      if (t.add(sample(still, scale))) return n + 1;
    }
    const int32_t samples = static_cast<int32_t>(seconds * kHz);
    for (int32_t k = 0; k < samples; ++k, ++n) {
      const double w = kTwoPi * turns / seconds * (1 - std::cos(kTwoPi * (k + 0.5) / samples));
      double rate[3] = {0, 0, 0};
      rate[axis] = w * std::cos(tilt);
      rate[(axis + 1) % 3] = w * std::sin(tilt);
      if (t.add(sample(rate, scale))) return n + 1;
    }
    for (int k = 0; k < 2000; ++k, ++n) {
      if (t.add(sample(still, scale))) return n + 1;
    }
    return 0;
  }
};

// A calibration asking for `asked` turns, then `turned` turns about `axis` in `seconds`: the result.
GyroTurnsResult measure(int32_t asked, int axis, double turned, double seconds, const double (&scale)[3],
                        double tilt = 0) {
  TurnRig rig;
  GyroTurns<kHz> t;
  rig.calibrate(t, asked);
  EXPECT_GT(rig.turn(t, axis, turned, seconds, scale, tilt), 0) << "the measurement ends";
  return t.result();
}

TEST(GyroTurns, ATurnOfTheCountAskedForGivesThatAxisScale) {
  for (int axis = 0; axis < 3; ++axis) {
    for (const double e : {-0.03, 0.0, 0.0213}) {
      for (const double direction : {1.0, -1.0}) {
        double scale[3] = {1.01, 0.98, 1.02};
        scale[axis] = 1 + e;
        TurnRig rig;
        GyroTurns<kHz> t;
        rig.calibrate(t, 2);
        const int32_t ended = rig.turn(t, axis, 2 * direction, 5.0, scale);
        ASSERT_GT(ended, 0) << axis << " " << e;
        // It ends half a second after the rate fell below 1 deg/s, 94 samples before the turn's
        // end (700 still + 5000 turning + 500 still).
        EXPECT_GE(ended, 700 + 5000 + 500 - 100) << axis;
        EXPECT_LE(ended, 700 + 5000 + 500 - 90) << axis;
        const GyroTurnsResult& r = t.result();
        ASSERT_TRUE(r.found) << axis << " " << e;
        EXPECT_EQ(r.axis, axis);
        // Counts round to whole numbers: the sum of 5000 roundings is far inside 100 ppm of
        // 2 turns (2.4e10 Q9 counts).
        EXPECT_NEAR(r.ppm, e * 1e6, 100) << axis << " " << e;
      }
    }
  }
}

TEST(GyroTurns, AMiscountedTurnSetsNothing) {
  const double scale[3] = {1, 1, 1.03};
  for (const double turned : {1.0, 3.0}) EXPECT_FALSE(measure(2, 2, turned, 6.0, scale).found) << turned;
  // The scale tolerance itself: 7 % high is a scale, 9 % high is not.
  for (const double e : {0.07, 0.09}) {
    const double high[3] = {1, 1, 1 + e};
    EXPECT_EQ(measure(1, 2, 1, 4.0, high).found, e < 0.08) << e;
  }
}

TEST(GyroTurns, ATurnAboutATiltedAxisSetsNothing) {
  const double scale[3] = {1, 1, 1};
  for (const double tilt_deg : {2.0, 4.0}) {
    // sin 2 deg = 3.5 % of the turn on x, inside the 5 %; sin 4 deg = 7 %, beyond.
    EXPECT_EQ(measure(2, 2, 2, 5.0, scale, tilt_deg * std::numbers::pi / 180).found, tilt_deg < 3) << tilt_deg;
  }
}

TEST(GyroTurns, StillnessBeforeATurnDoesNotEndItAndNoTurnTimesOut) {
  TurnRig rig;
  GyroTurns<kHz> t;
  rig.calibrate(t, 1);
  const double still[3] = {0, 0, 0}, unit[3] = {1, 1, 1};
  for (int32_t n = 1; n < GyroTurns<kHz>::kTimeoutSamples; ++n) ASSERT_FALSE(t.add(rig.sample(still, unit))) << n;
  EXPECT_TRUE(t.add(rig.sample(still, unit)));
  EXPECT_FALSE(t.running());
  EXPECT_FALSE(t.result().found);
}

}  // namespace
}  // namespace qr::chain
