// An MPU-6050-class IMU: 16-bit gyro at FS_SEL = 1 (±500 °/s, 65.5 LSB per °/s) and accelerometer
// at AFS_SEL = 1 (±4 g, 8192 LSB per g), body axes x forward, y right, z down, the accelerometer
// reading specific force (docs/conventions.md). On top of the truth: a turn-on bias and a scale
// error per axis (drawn once, within the datasheet's tolerances), white noise at the datasheet's
// densities over the low-pass bandwidth, the vibration, then rounding and saturation at full scale.
#pragma once

#include <stdint.h>

#include <array>

#include <sim/random.hpp>
#include <sim/vehicle.hpp>
#include <sim/vibration.hpp>

namespace sim {

// MPU-6050 product specification rev. 3.4, sections 6.1 and 6.2. The firmware's copy of these
// is qr/core/sensor_scale.hpp; a test keeps the two equal.
inline constexpr double kGyroCountsPerDps = 65.5;
inline constexpr double kAccelCountsPerG = 8192.0;
inline constexpr double kStandardGravity = 9.80665;

struct ImuReading {
  std::array<int16_t, 3> gyro{};   // counts, x y z
  std::array<int16_t, 3> accel{};  // counts, x y z
};

// What the part senses before its ADC, in physical units: the truth through this part's scale
// error and bias, with the vibration and one draw of the noise (what the register-level model,
// sim/mpu6050_model.hpp, converts at the full scale its driver chose).
struct ImuSense {
  Vec3 rate;            // rad/s
  Vec3 specific_force;  // m/s²
};

class Imu {
 public:
  Imu(const VehicleParams& vehicle, const Random& random);

  // One sample of body rate `rate` (rad/s) and specific force `specific_force` (m/s²), with the
  // vibration at that instant.
  ImuReading sample(const Vec3& rate, const Vec3& specific_force, const VibrationSample& vibration);
  // The same sample before the ADC (the same draws in the same order: sample() is sense() in counts
  // at FS_SEL = 1 and AFS_SEL = 1).
  ImuSense sense(const Vec3& rate, const Vec3& specific_force, const VibrationSample& vibration);

  // The errors drawn at turn-on, in physical units (what calibration has to remove).
  const Vec3& gyro_bias() const { return gyro_bias_; }    // rad/s
  const Vec3& accel_bias() const { return accel_bias_; }  // m/s²
  const Vec3& gyro_scale() const { return gyro_scale_; }  // factors, 1 + the sensitivity error
  double low_pass_hz() const { return bandwidth_hz_; }

  // Noise standard deviation of one sample, physical units.
  double gyro_noise_sigma() const { return gyro_sigma_; }    // rad/s
  double accel_noise_sigma() const { return accel_sigma_; }  // m/s²

 private:
  Random random_;
  double bandwidth_hz_;
  double gyro_sigma_;
  double accel_sigma_;
  Vec3 gyro_bias_;
  Vec3 accel_bias_;
  Vec3 gyro_scale_;
  Vec3 accel_scale_;
};

// Physical value -> counts: rounded to the nearest count, saturated at the 16-bit full scale.
int16_t to_counts(double value, double counts_per_unit);

}  // namespace sim
