// The sensor models against the MPU-6050 datasheet and docs/conventions.md.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <qr/core/sensor_scale.hpp>
#include <sim/imu.hpp>
#include <sim/world.hpp>

#include "sim_test_support.hpp"

namespace {

using sim::Vec3;
using sim_test::ideal_imu;
using sim_test::place_in_air;

constexpr double kPi = std::numbers::pi;

TEST(Sensors, ScalesMatchTheFirmware) {
  EXPECT_EQ(sim::kGyroCountsPerDps, qr::sensor::kGyroCountsPerDegPerSec);
  EXPECT_EQ(sim::kAccelCountsPerG, qr::sensor::kAccelCountsPerG);
  EXPECT_EQ(sim::kStandardGravity, qr::sensor::kStandardGravity);
}

struct Stats {
  double mean[3] = {};
  double sigma[3] = {};
};

// `n` samples of the world as it stands (time does not move: only the noise changes).
Stats sample_stats(sim::World& world, int n, bool gyro) {
  Stats s;
  double sum[3] = {}, sum2[3] = {};
  for (int i = 0; i < n; ++i) {
    const sim::ImuReading r = world.sample().imu;
    for (size_t a = 0; a < 3; ++a) {
      const double c = gyro ? r.gyro[a] : r.accel[a];
      sum[a] += c;
      sum2[a] += c * c;
    }
  }
  for (size_t a = 0; a < 3; ++a) {
    s.mean[a] = sum[a] / n;
    s.sigma[a] = std::sqrt(sum2[a] / n - s.mean[a] * s.mean[a]);
  }
  return s;
}

TEST(Sensors, LevelAtRestReadsMinusOneGAlongZ) {
  sim::World world(ideal_imu(sim::default_vehicle(), true), {});
  const sim::VehicleParams& v = world.plant().vehicle();
  const double sigma = v.accel_noise_ug_rthz * 1e-6 * std::sqrt(v.imu_bandwidth_hz) * sim::kAccelCountsPerG;
  const int n = 4000;
  const Stats a = sample_stats(world, n, false);
  const double expected[3] = {0, 0, -8192};
  for (size_t axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(a.mean[axis], expected[axis], 4 * sigma / std::sqrt(n) + 0.5) << "axis " << axis;
  }
  const Stats g = sample_stats(world, n, true);
  for (size_t axis = 0; axis < 3; ++axis) EXPECT_NEAR(g.mean[axis], 0, 0.5) << "axis " << axis;
}

TEST(Sensors, EachBodyRateReadsOnItsOwnGyroAxisWithItsSign) {
  sim::World world(ideal_imu(sim::default_vehicle()), {});
  const double counts_per_rad_s = sim::kGyroCountsPerDps * 180 / kPi;
  const Vec3 rates[3] = {{1, 0, 0}, {0, -0.5, 0}, {0, 0, 2}};
  for (const Vec3& rate : rates) {
    sim::PlantState s = world.plant().state();
    s.position.z = -100;  // off the ground, so nothing but the spin changes the reading
    s.rate = rate;
    world.plant().set_state(s);
    const sim::ImuReading r = world.sample().imu;
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_EQ(r.gyro[static_cast<size_t>(axis)], std::lround(rate[axis] * counts_per_rad_s)) << "axis " << axis;
    }
  }
}

TEST(Sensors, NoiseMatchesTheDatasheetDensities) {
  sim::World world(ideal_imu(sim::default_vehicle(), true), {});
  const sim::VehicleParams& v = world.plant().vehicle();
  // white noise of density d over bandwidth B: sigma = d sqrt(B)
  const double gyro_sigma = 0.005 * std::sqrt(v.imu_bandwidth_hz) * sim::kGyroCountsPerDps;
  const double accel_sigma = 400e-6 * std::sqrt(v.imu_bandwidth_hz) * sim::kAccelCountsPerG;
  ASSERT_EQ(v.gyro_noise_dps_rthz, 0.005);
  ASSERT_EQ(v.accel_noise_ug_rthz, 400);
  const Stats g = sample_stats(world, 20000, true), a = sample_stats(world, 20000, false);
  for (size_t axis = 0; axis < 3; ++axis) {
    // Rounding to counts adds 1/12 count² of variance.
    EXPECT_NEAR(g.sigma[axis], std::sqrt(gyro_sigma * gyro_sigma + 1.0 / 12), 0.03 * gyro_sigma);
    EXPECT_NEAR(a.sigma[axis], accel_sigma, 0.03 * accel_sigma);
  }
}

TEST(Sensors, SaturateAtFullScale) {
  sim::World world(ideal_imu(sim::default_vehicle()), {});
  sim::PlantState s = world.plant().state();
  s.position.z = -100;
  s.rate = {10, -10, 9.0};  // 573 and 516 °/s, beyond ±500 °/s
  world.plant().set_state(s);
  world.plant().set_disturbance({}, {5 * sim::kGravity, 0, 0});  // 5 g pushing forward, beyond ±4 g
  const sim::ImuReading r = world.sample().imu;
  EXPECT_EQ(r.gyro[0], 32767);
  EXPECT_EQ(r.gyro[1], -32768);
  EXPECT_EQ(r.gyro[2], 32767);
  EXPECT_EQ(r.accel[0], 32767);
  EXPECT_EQ(sim::to_counts(-1e9, 1), -32768);
}

TEST(Sensors, TurnOnBiasesSpreadAsTheDatasheetTolerances) {
  const sim::VehicleParams v = sim::default_vehicle();
  double sum2 = 0, max_abs = 0;
  const int parts = 400;
  for (int seed = 1; seed <= parts; ++seed) {
    const sim::Imu imu(v, sim::Random(static_cast<uint64_t>(seed)));
    const double x = imu.gyro_bias().x * 180 / kPi;
    sum2 += x * x;
    max_abs = std::max(max_abs, std::abs(x));
  }
  const double sigma = std::sqrt(sum2 / parts);
  EXPECT_NEAR(sigma, v.gyro_bias_dps / 3, 0.1 * v.gyro_bias_dps / 3);  // tolerance read as 3 sigma
  EXPECT_LT(max_abs, 4.5 * v.gyro_bias_dps / 3);
}

TEST(Sensors, BatterySensorReadsTheTerminalVoltage) {
  sim::World world(sim::default_vehicle(), {});
  place_in_air(world.plant(), 0);
  world.plant().set_engines({700, 700, 700, 700});
  world.advance_to(500000);
  const double volts = world.plant().battery_volts();
  const sim::VehicleParams& v = world.plant().vehicle();
  double sum = 0;
  for (int i = 0; i < 1000; ++i) sum += world.sample().battery_mv;
  // Readings are floored to the ADC step: on average half a step low.
  EXPECT_NEAR(sum / 1000, volts * 1000 - v.battery_sense_lsb_mv / 2, 3);
  EXPECT_LT(volts, world.plant().battery().open_circuit_volts() - 0.2);  // the sensor sees the sag
}

// Magnitude spectrum of `x` sampled at `rate_hz` at frequency `f` (one DFT bin, Hann window).
double amplitude_at(const std::vector<double>& x, double rate_hz, double f) {
  std::complex<double> sum = 0;
  const double n = static_cast<double>(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const double t = static_cast<double>(i);
    const double hann = 0.5 - 0.5 * std::cos(2 * kPi * t / n);
    sum += hann * x[i] * std::polar(1.0, -2 * kPi * f * t / rate_hz);
  }
  return std::abs(sum) / (n / 4);  // the Hann window's coherent gain is 1/2
}

// The strongest line of the spectrum between 2 Hz and the Nyquist frequency, 0.25 Hz steps.
double strongest_line(const std::vector<double>& x, double rate_hz) {
  double best_f = 0, best = 0;
  for (double f = 2; f < rate_hz / 2; f += 0.25) {
    const double a = amplitude_at(x, rate_hz, f);
    if (a > best) {
      best = a;
      best_f = f;
    }
  }
  return best_f;
}

std::vector<double> accel_x_at_speed(double speed, uint32_t sample_hz, double seconds) {
  sim::World world(sim::default_vehicle(), {.seed = 3});
  place_in_air(world.plant(), speed);
  std::vector<double> x;
  const uint64_t period = 1000000 / sample_hz;
  for (uint64_t t = 0; t < static_cast<uint64_t>(seconds * 1e6); t += period) {
    world.advance_to(t);
    x.push_back(world.sample().imu.accel[0]);
  }
  return x;
}

TEST(Sensors, VibrationPeaksAtTheMotorFrequencyAndItsHarmonics) {
  const double speed = sim::default_vehicle().hover_speed();
  const double f1 = speed / (2 * kPi);  // about 66 Hz, the report's 65 Hz
  const std::vector<double> x = accel_x_at_speed(speed, 1000, 2.0);
  // Which harmonic is strongest depends on how the four rotors' imbalances happen to add up (the
  // seed); that the strongest line is one of them does not.
  const double strongest = strongest_line(x, 1000);
  const double harmonic = std::round(strongest / f1);
  EXPECT_GE(harmonic, 1);
  EXPECT_LE(harmonic, 3);
  EXPECT_NEAR(strongest, harmonic * f1, 0.5);
  const double floor = amplitude_at(x, 1000, 0.5 * (f1 + 2 * f1));  // between two lines
  for (int h = 1; h <= 3; ++h) EXPECT_GT(amplitude_at(x, 1000, h * f1), 10 * floor) << "harmonic " << h;
}

TEST(Sensors, VibrationAboveNyquistAliasesAsOnTheRealBoard) {
  // At 600 rad/s (95.5 Hz) the third harmonic, 286.5 Hz, is above the 250 Hz Nyquist frequency
  // of a 500 Hz control loop: it shows up at 500 - 286.5 = 213.5 Hz.
  const double f3 = 3 * 600 / (2 * kPi);
  const std::vector<double> x = accel_x_at_speed(600, 500, 4.0);
  const double alias = 500 - f3;
  const double floor = amplitude_at(x, 500, alias - 8);
  EXPECT_GT(amplitude_at(x, 500, alias), 10 * floor);
}

TEST(Sensors, SameSeedSameFlightOtherSeedOtherNoise) {
  auto fly = [](uint64_t seed) {
    sim::World world(sim::default_vehicle(), {.seed = seed});
    std::vector<int> trace;
    world.plant().set_engines({600, 560, 540, 580});
    for (uint64_t t = 1000; t <= 2000000; t += 1000) {
      world.advance_to(t);
      const sim::SensorReading r = world.sample();
      for (size_t a = 0; a < 3; ++a) {
        trace.push_back(r.imu.gyro[a]);
        trace.push_back(r.imu.accel[a]);
      }
      trace.push_back(r.battery_mv);
    }
    const sim::PlantState& s = world.plant().state();
    return std::make_pair(trace, std::vector<double>{s.position.x, s.position.y, s.position.z, s.attitude.w,
                                                     s.attitude.x, s.attitude.y, s.attitude.z});
  };
  const auto a = fly(42), b = fly(42), c = fly(43);
  EXPECT_EQ(a.first, b.first);
  EXPECT_EQ(a.second, b.second);  // bit for bit
  EXPECT_NE(a.first, c.first);
  EXPECT_EQ(a.second, c.second);  // the seed moves the sensors, not the physics
}

TEST(Sensors, RandomIsTheSameEverywhere) {
  // Pinned values: a change of generator or seeding (or a library's help) shows up here.
  sim::Random r(1);
  EXPECT_EQ(r.next(), 0xB3F2AF6D0FC710C5ull);
  sim::Random n(7);
  double sum = 0, sum2 = 0;
  for (int i = 0; i < 100000; ++i) {
    const double x = n.normal();
    sum += x;
    sum2 += x * x;
  }
  EXPECT_NEAR(sum / 1e5, 0, 0.01);
  EXPECT_NEAR(sum2 / 1e5, 1, 0.015);
}

}  // namespace
