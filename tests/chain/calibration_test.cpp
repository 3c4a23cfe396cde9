// Sensor calibration: averages of kCalibrationSamples raw samples, accelerometer offsets that make
// level read (0, 0, -1 g), done after exactly that many samples, fractions of a count kept.
#include <gtest/gtest.h>

#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/core/chain/sensor_calibration.hpp>
#include <qr/host/real_numbers.hpp>

#include "chain_test_support.hpp"

namespace qr::chain {
namespace {

constexpr double kRadPerCount = 1.0 / sensor::kGyroCountsPerRadPerSec;
constexpr double kGPerCount = 1.0 / sensor::kAccelCountsPerG;

SensorSample raw(int16_t gx, int16_t gy, int16_t gz, int16_t ax, int16_t ay, int16_t az) {
  SensorSample s;
  s.gyro[0] = gx;
  s.gyro[1] = gy;
  s.gyro[2] = gz;
  s.accel[0] = ax;
  s.accel[1] = ay;
  s.accel[2] = az;
  return s;
}

TEST(Calibration, DoneAfterExactlyTheSampleCount) {
  SensorCalibration<FixedNumbers> c;
  for (int32_t n = 1; n < kCalibrationSamples; ++n) ASSERT_FALSE(c.add(raw(0, 0, 0, 0, 0, -8192))) << n;
  EXPECT_FALSE(c.done());
  EXPECT_TRUE(c.add(raw(0, 0, 0, 0, 0, -8192)));
  EXPECT_TRUE(c.done());
  EXPECT_TRUE(c.add(raw(100, 0, 0, 0, 0, 0)));  // later samples change nothing
  EXPECT_EQ(c.gyro_offset(0), FixedNumbers::Rate{});
}

template <class N>
void check_offsets() {
  SensorCalibration<N> c;
  // Alternating samples: averages with half counts, which the offsets keep.
  for (int32_t n = 0; n < kCalibrationSamples; ++n) {
    const int16_t odd = static_cast<int16_t>(n & 1);
    c.add(raw(static_cast<int16_t>(40 + odd), -25, 15, static_cast<int16_t>(60 + odd), -35,
              static_cast<int16_t>(-8192 + 90)));
  }
  ASSERT_TRUE(c.done());
  const double expected_gyro[3] = {40.5 * kRadPerCount, -25 * kRadPerCount, 15 * kRadPerCount};
  const double expected_accel[3] = {60.5 * kGPerCount, -35 * kGPerCount, 90 * kGPerCount};
  for (int i = 0; i < 3; ++i) {
    // Q: the average is exact (9 fractional bits of a count), then one rounding to Q<27> and the
    // 1 ppm of the quantised counts-to-rad/s factor.
    EXPECT_NEAR(test::as_double(c.gyro_offset(i)), expected_gyro[i], 1e-8) << i;
    EXPECT_NEAR(test::as_double(c.accel_offset(i)), expected_accel[i], 1e-8) << i;
  }
}

TEST(Calibration, OffsetsAreTheAveragesAndLevelReadsMinusOneG) {
  check_offsets<FixedNumbers>();
  check_offsets<DoubleNumbers>();
}

TEST(Calibration, RestartForgetsTheSumsButKeepsTheOffsetsInUse) {
  SensorCalibration<FixedNumbers> c;
  for (int32_t n = 0; n < kCalibrationSamples; ++n) c.add(raw(10, 0, 0, 0, 0, -8192));
  const auto before = c.gyro_offset(0);
  c.restart();
  EXPECT_TRUE(c.done());
  EXPECT_EQ(c.samples(), 0);
  EXPECT_EQ(c.gyro_offset(0), before);
  for (int32_t n = 0; n < kCalibrationSamples; ++n) c.add(raw(-20, 0, 0, 0, 0, -8192));
  EXPECT_NEAR(c.gyro_offset(0).to_double(), -20 * kRadPerCount, 1e-8);
}

}  // namespace
}  // namespace qr::chain
