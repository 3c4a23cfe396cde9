// The height estimate (height_estimator.hpp) on synthetic data: a step in the barometer's height,
// a constant climb, a constant accelerometer error that must be learnt, a noisy barometer, a
// tilted vehicle, no barometer; the flight's Q formats against double; the standard atmosphere's
// table against the closed form. Each world is exact: the accelerometer reads the specific force
// of the true motion in the body axes of the true attitude, the barometer the ISA pressure of the
// true height (rounded to the MS5611's 1 Pa), a new reading every 20 ms held in between.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <qr/core/chain/fixed_numbers.hpp>
#include <qr/core/chain/height_estimator.hpp>
#include <qr/host/real_numbers.hpp>

#include "chain_test_support.hpp"

namespace qr::chain {
namespace {

constexpr int kHz = 250;                // the flight's height task rate
constexpr int kRunsPerBaro = kHz / 50;  // a reading every 20 ms
constexpr double kG0 = 9.80665;

double isa_pa(double metres) { return 101325.0 * std::pow(1.0 - 0.0065 * metres / 288.15, 5.25588); }

struct Truth {
  double height = 0, climb = 0, accel = 0;  // up: m, m/s, m/s²
};

template <class N>
struct Rig {
  HeightEstimator<N, static_cast<uint32_t>(kHz)> e;
  int run = 0;
  int32_t baro = 0;

  // Calibrates on the ground at `ground_pa`.
  explicit Rig(int32_t ground_pa = 101325) {
    e.restart_calibration();
    for (int i = 0; i < kCalibrationSamples; ++i) e.add_calibration(ground_pa);
    e.zero_reference();
  }

  // One run with the vehicle at `t`, attitude roll/pitch (rad), the accelerometer reading
  // `accel_error` m/s² too much upward acceleration, and `baro_noise` Pa added to the reading.
  void step(const Truth& t, double roll = 0, double pitch = 0, double accel_error = 0, double baro_noise = 0,
            bool baro_present = true) {
    using Accel = typename N::Accel;
    using Angle = typename N::Angle;
    // Specific force along earth down, in g: -(g + a_up) / g; in body axes by the third row of
    // the body-to-earth rotation (Z-Y-X).
    const double down = -(kG0 + t.accel + accel_error) / kG0;
    const double f[3] = {-std::sin(pitch) * down, std::sin(roll) * std::cos(pitch) * down,
                         std::cos(roll) * std::cos(pitch) * down};
    const Accel a[3] = {to<Accel>(f[0]), to<Accel>(f[1]), to<Accel>(f[2])};
    if (run++ % kRunsPerBaro == 0) baro = static_cast<int32_t>(std::lround(isa_pa(t.height) + baro_noise));
    e.update(a, to<Angle>(roll), to<Angle>(pitch), baro_present ? baro : 0);
  }
  template <class T>
  static T to(double v) {
    if constexpr (fx::is_q<T>) {
      return test::quantise<T>(v);
    } else {
      return static_cast<T>(v);
    }
  }
  double height() const { return test::as_double(e.height()); }
  double climb() const { return test::as_double(e.climb()); }
  double bias() const { return test::as_double(e.accel_bias()); }
};

// Each check below runs in the flight's Q formats and in double.

// The barometer says 2 m higher at once (no acceleration: the accelerometer disagrees, so the
// filter must weigh them): the estimate reaches 2 m through the loop's three poles at 1/tau, and
// the bias it picked up on the way drains again.
template <class TypeParam>
void StepInTheBarometersHeightIsFollowed() {
  Rig<TypeParam> rig;
  for (int i = 0; i < kHz; ++i) rig.step({});
  EXPECT_NEAR(rig.height(), 0, 0.01);
  double at_half_second = 0, peak = 0;
  for (int i = 0; i < 30 * kHz; ++i) {
    rig.step({2.0, 0, 0});
    if (i == kHz / 2) at_half_second = rig.height();
    peak = std::max(peak, rig.height());
  }
  EXPECT_GT(at_half_second, 0.5) << "the barometer moves the estimate within a fraction of a second";
  EXPECT_LT(peak, 2.0 * 1.4) << "three real poles: a bounded overshoot";
  EXPECT_NEAR(rig.height(), 2.0, 0.03) << "1 Pa of the barometer is 8 cm: the rounding of the reading";
  EXPECT_NEAR(rig.climb(), 0, 0.005);
  EXPECT_NEAR(rig.bias(), 0, 0.01);
}
TEST(HeightEstimator, StepInTheBarometersHeightIsFollowedInFixedPoint) {
  StepInTheBarometersHeightIsFollowed<FixedNumbers>();
}
TEST(HeightEstimator, StepInTheBarometersHeightIsFollowedInDouble) {
  StepInTheBarometersHeightIsFollowed<DoubleNumbers>();
}

// Accelerate at 0.5 m/s² for 1 s, climb at 0.5 m/s for 10 s, stop over 1 s: height and speed
// follow the truth, and the accelerometer's share makes the speed right while the barometer
// alone, in 8 cm steps, could not.
template <class TypeParam>
void ConstantClimbIsTracked() {
  Rig<TypeParam> rig;
  Truth t;
  const double dt = 1.0 / kHz;
  double max_height_error = 0, max_climb_error = 0;
  for (int i = 0; i < 13 * kHz; ++i) {
    const double s = i * dt;
    t.accel = s < 1 ? 0.5 : s < 11 ? 0 : s < 12 ? -0.5 : 0;
    rig.step(t);
    if (s > 3 && s < 11) {
      max_height_error = std::max(max_height_error, std::abs(rig.height() - t.height));
      max_climb_error = std::max(max_climb_error, std::abs(rig.climb() - t.climb));
    }
    t.height += t.climb * dt + 0.5 * t.accel * dt * dt;
    t.climb += t.accel * dt;
  }
  std::printf("  constant climb: height error max %.4f m, climb error max %.4f m/s\n", max_height_error,
              max_climb_error);
  EXPECT_LT(max_height_error, 0.06);
  EXPECT_LT(max_climb_error, 0.03);
  EXPECT_NEAR(rig.height(), 5.5, 0.1);
}
TEST(HeightEstimator, ConstantClimbIsTrackedInFixedPoint) { ConstantClimbIsTracked<FixedNumbers>(); }
TEST(HeightEstimator, ConstantClimbIsTrackedInDouble) { ConstantClimbIsTracked<DoubleNumbers>(); }

// The accelerometer reads 0.3 m/s² too much upward acceleration (a scale error in hover, a
// vibration rectification): the bias state learns it, the height stays put.
template <class TypeParam>
void AccelerometerBiasIsLearnt() {
  Rig<TypeParam> rig;
  double max_height_error = 0;
  for (int i = 0; i < 20 * kHz; ++i) {
    rig.step({}, 0, 0, 0.3);
    max_height_error = std::max(max_height_error, std::abs(rig.height()));
  }
  std::printf("  bias 0.3 m/s^2: learnt %.4f, height error max %.4f m\n", rig.bias(), max_height_error);
  EXPECT_NEAR(rig.bias(), 0.3, 0.01);
  EXPECT_LT(max_height_error, 0.25);
  EXPECT_NEAR(rig.height(), 0, 0.05);
  EXPECT_NEAR(rig.climb(), 0, 0.01);
}
TEST(HeightEstimator, AccelerometerBiasIsLearntInFixedPoint) { AccelerometerBiasIsLearnt<FixedNumbers>(); }
TEST(HeightEstimator, AccelerometerBiasIsLearntInDouble) { AccelerometerBiasIsLearnt<DoubleNumbers>(); }

// The same with the vehicle banked 20° and pitched 10°: the rotation to the earth frame finds
// the vertical, so a level-hover's worth of thrust along a tilted z is no climb.
template <class TypeParam>
void TiltedVehicleClimbsOnlyWhenItDoes() {
  Rig<TypeParam> rig;
  const double roll = 0.35, pitch = 0.17;
  for (int i = 0; i < 10 * kHz; ++i) rig.step({}, roll, pitch);
  EXPECT_NEAR(rig.bias(), 0, 0.003);
  EXPECT_NEAR(rig.climb(), 0, 0.003);
  Truth t{0, 0, 1.0};  // 1 m/s² up for 1 s, tilted
  for (int i = 0; i < kHz; ++i) {
    rig.step(t, roll, pitch);
    t.height += t.climb / kHz + 0.5 * t.accel / (kHz * kHz);
    t.climb += t.accel / kHz;
  }
  EXPECT_NEAR(rig.climb(), 1.0, 0.05);
  EXPECT_NEAR(rig.height(), 0.5, 0.1);
}
TEST(HeightEstimator, TiltedVehicleClimbsOnlyWhenItDoesInFixedPoint) {
  TiltedVehicleClimbsOnlyWhenItDoes<FixedNumbers>();
}
TEST(HeightEstimator, TiltedVehicleClimbsOnlyWhenItDoesInDouble) { TiltedVehicleClimbsOnlyWhenItDoes<DoubleNumbers>(); }

// A barometer with the MS5611's 1.2 Pa of noise at OSR 4096 (10 cm) at rest: the estimate is
// several times quieter than the barometer, and its speed stays near 0.
template <class TypeParam>
void NoisyBarometerIsSmoothed() {
  Rig<TypeParam> rig;
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0, 1.2);
  double sum_h = 0, sum_v = 0, sum_baro = 0;
  int n = 0;
  double held_noise = 0;
  for (int i = 0; i < 60 * kHz; ++i) {
    if (i % kRunsPerBaro == 0) held_noise = noise(random);
    rig.step({}, 0, 0, 0, held_noise);
    if (i > 10 * kHz) {
      sum_h += rig.height() * rig.height();
      sum_v += rig.climb() * rig.climb();
      const double baro = test::as_double(rig.e.baro_height());
      sum_baro += baro * baro;
      ++n;
    }
  }
  const double rms_h = std::sqrt(sum_h / n), rms_v = std::sqrt(sum_v / n), rms_baro = std::sqrt(sum_baro / n);
  std::printf("  noisy barometer: height rms %.4f m (barometer %.4f m), climb rms %.4f m/s\n", rms_h, rms_baro, rms_v);
  EXPECT_GT(rms_baro, 0.08);
  EXPECT_LT(rms_h, 0.4 * rms_baro);
  EXPECT_LT(rms_v, 0.05);
}
TEST(HeightEstimator, NoisyBarometerIsSmoothedInFixedPoint) { NoisyBarometerIsSmoothed<FixedNumbers>(); }
TEST(HeightEstimator, NoisyBarometerIsSmoothedInDouble) { NoisyBarometerIsSmoothed<DoubleNumbers>(); }

// No barometer at calibration: no reference, the estimate stays 0 whatever the accelerometer
// says. A barometer that drops out in flight: the estimate coasts on the accelerometer.
template <class TypeParam>
void NoBarometerNoEstimate() {
  Rig<TypeParam> absent(0);
  EXPECT_FALSE(absent.e.has_reference());
  for (int i = 0; i < kHz; ++i) absent.step({0, 0, 1.0}, 0, 0, 0, 0, false);
  EXPECT_EQ(absent.height(), 0);
  EXPECT_EQ(absent.climb(), 0);

  Rig<TypeParam> dropout;
  EXPECT_TRUE(dropout.e.has_reference());
  for (int i = 0; i < kHz; ++i) dropout.step({0, 0, 1.0}, 0, 0, 0, 0, false);
  EXPECT_NEAR(dropout.climb(), 1.0, 0.01) << "integrated acceleration, no barometer to pull it back";
  EXPECT_NEAR(dropout.height(), 0.5, 0.02);
}
TEST(HeightEstimator, NoBarometerNoEstimateInFixedPoint) { NoBarometerNoEstimate<FixedNumbers>(); }
TEST(HeightEstimator, NoBarometerNoEstimateInDouble) { NoBarometerNoEstimate<DoubleNumbers>(); }

// A new calibration is a new zero, and the metres per pascal are the site's: calibrated at
// 1500 m (where 1 Pa is 0.098 m, not the 0.083 m of sea level), 10 m of climb reads 10 m. The
// barometer's 1 Pa step is 0.1 m here.
template <class TypeParam>
void CalibrationZeroesTheReferenceAtTheSitesPressure() {
  const int32_t site = static_cast<int32_t>(std::lround(isa_pa(1500)));
  Rig<TypeParam> rig(site);
  Truth t{1500, 0, 0};
  for (int i = 0; i < 5 * kHz; ++i) rig.step(t);
  EXPECT_NEAR(rig.height(), 0, 0.05);
  t.height = 1510;
  for (int i = 0; i < 20 * kHz; ++i) rig.step(t);
  EXPECT_NEAR(rig.height(), 10.0, 0.1) << "with sea level's gradient it would read 8.5 m";
}
TEST(HeightEstimator, CalibrationZeroesTheReferenceAtTheSitesPressureInFixedPoint) {
  CalibrationZeroesTheReferenceAtTheSitesPressure<FixedNumbers>();
}
TEST(HeightEstimator, CalibrationZeroesTheReferenceAtTheSitesPressureInDouble) {
  CalibrationZeroesTheReferenceAtTheSitesPressure<DoubleNumbers>();
}

// The flight's formats against double over a noisy climb: within 1 mm and 1 mm/s.
TEST(HeightEstimator, FixedFollowsDouble) {
  Rig<FixedNumbers> q;
  Rig<DoubleNumbers> d;
  std::mt19937 random(3);
  std::normal_distribution<double> noise(0, 1.2);
  Truth t;
  double held = 0, max_h = 0, max_v = 0, max_b = 0;
  for (int i = 0; i < 20 * kHz; ++i) {
    const double s = static_cast<double>(i) / kHz;
    t.accel = s < 2 ? 0.8 : s < 8 ? 0 : s < 10 ? -0.8 : 0;
    if (i % kRunsPerBaro == 0) held = noise(random);
    q.step(t, 0.1, -0.05, 0.2, held);
    d.step(t, 0.1, -0.05, 0.2, held);
    max_h = std::max(max_h, std::abs(q.height() - d.height()));
    max_v = std::max(max_v, std::abs(q.climb() - d.climb()));
    max_b = std::max(max_b, std::abs(q.bias() - d.bias()));
    t.height += t.climb / kHz + 0.5 * t.accel / (kHz * kHz);
    t.climb += t.accel / kHz;
  }
  std::printf("  Q against double: height %.2e m, climb %.2e m/s, bias %.2e m/s^2\n", max_h, max_v, max_b);
  EXPECT_LT(max_h, 1e-3);
  EXPECT_LT(max_v, 1e-3);
  EXPECT_LT(max_b, 1e-4);
}

// The compile-time ISA table against the closed form's derivative with std::pow.
TEST(HeightEstimator, AtmosphereTableIsTheStandardAtmosphere) {
  for (double p = 30000; p <= 120000; p += 5000) {
    const double h = 288.15 / 0.0065 * (1 - std::pow(p / 101325.0, 1 / 5.25588));
    const double dh = 1e-3;
    const double numeric = dh / (isa_pa(h - dh) - isa_pa(h + dh)) * 2;
    EXPECT_NEAR(isa::metres_per_pascal(p), numeric, 1e-7 * numeric) << p;
  }
  EXPECT_NEAR(isa::metres_per_pascal(101325), 1 / (1.225 * kG0), 1e-4) << "1 / (rho0 g0) at sea level";
}

}  // namespace
}  // namespace qr::chain
