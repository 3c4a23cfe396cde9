// The barometer model (sim/barometer.hpp) against the standard atmosphere and the MS5611
// datasheet's figures at OSR 4096: pressure of a height, noise, a new reading every 20 ms held in
// between, the conversion's delay, the warm-up drift, seeds; and vehicle files from before it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <sim/barometer.hpp>
#include <sim/world.hpp>

namespace {

// ISA table values (ICAO Doc 7488/3): 89874.6 Pa at 1000 m, 54019.9 Pa at 5000 m.
TEST(Barometer, StandardAtmosphere) {
  EXPECT_DOUBLE_EQ(sim::isa_pressure_pa(0), 101325.0);
  EXPECT_NEAR(sim::isa_pressure_pa(1000), 89874.6, 0.5);
  EXPECT_NEAR(sim::isa_pressure_pa(5000), 54019.9, 0.5);
  for (double h : {-100.0, 0.0, 1.5, 300.0, 4000.0}) EXPECT_NEAR(sim::isa_altitude_m(sim::isa_pressure_pa(h)), h, 1e-6);
  // Near the ground 1 m is 12.0 Pa: 1 Pa, the sensor's step, is 8.3 cm.
  EXPECT_NEAR(sim::isa_pressure_pa(0) - sim::isa_pressure_pa(1), 12.01, 0.01);
}

sim::VehicleParams quiet(double noise_pa, double drift_pa_per_k) {
  sim::VehicleParams v = sim::default_vehicle();
  v.baro_noise_pa = noise_pa;
  v.baro_temp_coeff_pa_per_k = drift_pa_per_k;
  return v;
}

// Steps a barometer through `seconds` at the physics rate at a fixed altitude; returns the
// reading at each step.
std::vector<int32_t> readings(sim::Barometer& b, double altitude, double seconds, uint64_t from_us = 0) {
  std::vector<int32_t> out;
  for (uint64_t t = from_us; t < from_us + static_cast<uint64_t>(seconds * 1e6); t += 125) {
    b.step(t, altitude);
    out.push_back(b.pressure_pa());
  }
  return out;
}

TEST(Barometer, ANewReadingEveryTwentyMillisecondsHeldInBetween) {
  sim::Barometer b(quiet(1.2, 0), sim::Random(1).stream(4));
  const std::vector<int32_t> r = readings(b, 0, 2.0);
  int changes = 0;
  size_t first = 0, last_change = 0;
  for (size_t i = 1; i < r.size(); ++i) {
    if (r[i] != r[i - 1]) {
      if (changes == 0) first = i;
      // Readings are apart by whole cycles (a cycle may repeat a value: noise is rounded to 1 Pa).
      if (changes > 0) EXPECT_EQ((i - last_change) % 160, 0u) << i;
      ++changes;
      last_change = i;
    }
  }
  EXPECT_EQ(r[0], 0) << "nothing before the first conversion is done";
  EXPECT_LE(first * 125, sim::Barometer::kPeriodUs + b.phase_us() + 125);
  EXPECT_GT(changes, 40) << "about 100 readings in 2 s, most of them different";
  EXPECT_LE(changes, 101);
}

TEST(Barometer, NoiseIsTheDatasheetsAtOsr4096) {
  sim::Barometer b(quiet(1.2, 0), sim::Random(2).stream(4));
  double sum = 0, sum2 = 0;
  int n = 0;
  for (uint64_t t = 0; t < 200'000'000; t += sim::Barometer::kPeriodUs) {  // 10000 readings
    b.step(t, 0);
    if (t < sim::Barometer::kPeriodUs * 2) continue;
    const double x = b.pressure_pa();
    sum += x;
    sum2 += x * x;
    ++n;
  }
  const double mean = sum / n, sigma = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 101325, 0.1);
  // 0.012 mbar RMS, plus the 1 Pa output step's own 0.29 Pa: sqrt(1.2^2 + 1/12) = 1.23.
  EXPECT_NEAR(sigma, 1.23, 0.05);
}

// A climb is seen 15.5 ms late: the reading published at the end of a cycle is the pressure at
// the middle of its D1 conversion.
TEST(Barometer, ReadingIsThePressureAtTheMiddleOfItsConversion) {
  sim::Barometer b(quiet(0, 0), sim::Random(3).stream(4));
  // Climb at 10 m/s: the reading published at time t is the pressure at t - 15.48 ms.
  for (uint64_t t = 0; t < 1'000'000; t += 125) {
    const int32_t before = b.pressure_pa();
    b.step(t, 10.0 * static_cast<double>(t) * 1e-6);
    if (b.pressure_pa() != before && t > 100'000) {
      const double sampled_at = (static_cast<double>(t) - 15480.0) * 1e-6;
      EXPECT_NEAR(b.pressure_pa(), sim::isa_pressure_pa(10.0 * sampled_at), 0.5 + 10.0 * 12.0 * 125e-6) << t;
    }
  }
}

TEST(Barometer, WarmUpDriftsSlowly) {
  sim::Barometer b(quiet(0, 0.5), sim::Random(4).stream(4));
  EXPECT_DOUBLE_EQ(b.drift_pa(0), 0);
  EXPECT_NEAR(b.temperature_c(0), 15.0, 1e-9);
  EXPECT_NEAR(b.drift_pa(120'000'000), 0.5 * 5 * (1 - std::exp(-1.0)), 1e-9);
  EXPECT_NEAR(b.temperature_c(1'000'000'000), 20.0, 0.01);
}

TEST(Barometer, TheWorldsBarometerFollowsTheVehicleAndTheSeed) {
  sim::World a(sim::default_vehicle(), {.seed = 5}), same(sim::default_vehicle(), {.seed = 5}),
      other(sim::default_vehicle(), {.seed = 6});
  a.advance_to(500'000);
  same.advance_to(500'000);
  other.advance_to(500'000);
  EXPECT_EQ(a.sample().pressure_pa, same.sample().pressure_pa);
  EXPECT_NEAR(a.sample().pressure_pa, 101325, 6) << "resting on the ground, at ISA sea level";
  EXPECT_NE(a.barometer().phase_us(), other.barometer().phase_us());
}

// Vehicle files written before the barometer load, with the datasheet's defaults.
TEST(Barometer, VehicleFilesWithoutItLoad) {
  std::string text = sim::default_vehicle_text();
  text.resize(text.find("# --- Barometer"));
  sim::VehicleParams v;
  std::string error;
  ASSERT_TRUE(sim::parse_vehicle(text, v, error)) << error;
  EXPECT_EQ(v.baro_noise_pa, 1.2);
  ASSERT_TRUE(sim::parse_vehicle(text + "baro_noise_pa = 3\n", v, error)) << error;
  EXPECT_EQ(v.baro_noise_pa, 3);
  EXPECT_FALSE(sim::parse_vehicle(text + "baro_noise_pa = -1\n", v, error));
}

}  // namespace
