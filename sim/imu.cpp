#include <sim/imu.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sim {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180;
constexpr double kGyroCountsPerRadS = kGyroCountsPerDps / kRadPerDeg;
constexpr double kAccelCountsPerMps2 = kAccelCountsPerG / kStandardGravity;

// Datasheet tolerances are read as 3 sigma of a normal spread over parts.
Vec3 draw(Random& random, const Vec3& three_sigma) {
  return {random.normal() * three_sigma.x / 3, random.normal() * three_sigma.y / 3,
          random.normal() * three_sigma.z / 3};
}

}  // namespace

int16_t to_counts(double value, double counts_per_unit) {
  const double counts = std::nearbyint(value * counts_per_unit);
  return static_cast<int16_t>(std::clamp(counts, -32768.0, 32767.0));
}

Imu::Imu(const VehicleParams& v, const Random& random)
    : random_(random), bandwidth_hz_(v.imu_bandwidth_hz),
      gyro_sigma_(v.gyro_noise_dps_rthz * std::sqrt(v.imu_bandwidth_hz) * kRadPerDeg),
      accel_sigma_(v.accel_noise_ug_rthz * 1e-6 * kStandardGravity * std::sqrt(v.imu_bandwidth_hz)) {
  const double g = v.gyro_bias_dps * kRadPerDeg;
  gyro_bias_ = draw(random_, {g, g, g});
  const double xy = v.accel_bias_xy_mg * 1e-3 * kStandardGravity, z = v.accel_bias_z_mg * 1e-3 * kStandardGravity;
  accel_bias_ = draw(random_, {xy, xy, z});
  const double s = v.scale_error;
  gyro_scale_ = Vec3{1, 1, 1} + draw(random_, {s, s, s});
  accel_scale_ = Vec3{1, 1, 1} + draw(random_, {s, s, s});
}

ImuSense Imu::sense(const Vec3& rate, const Vec3& specific_force, const VibrationSample& vibration) {
  std::array<double, 3> gyro{}, accel{};
  for (int axis = 0; axis < 3; ++axis) {
    const size_t a = static_cast<size_t>(axis);
    gyro[a] = gyro_scale_[axis] * (rate[axis] + vibration.gyro[axis]) + gyro_bias_[axis] +
              gyro_sigma_ * random_.normal();
    accel[a] = accel_scale_[axis] * (specific_force[axis] + vibration.accel[axis]) + accel_bias_[axis] +
               accel_sigma_ * random_.normal();
  }
  return {{gyro[0], gyro[1], gyro[2]}, {accel[0], accel[1], accel[2]}};
}

ImuReading Imu::sample(const Vec3& rate, const Vec3& specific_force, const VibrationSample& vibration) {
  const ImuSense sensed = sense(rate, specific_force, vibration);
  ImuReading out;
  for (int axis = 0; axis < 3; ++axis) {
    const size_t a = static_cast<size_t>(axis);
    out.gyro[a] = to_counts(sensed.rate[axis], kGyroCountsPerRadS);
    out.accel[a] = to_counts(sensed.specific_force[axis], kAccelCountsPerMps2);
  }
  return out;
}

}  // namespace sim
