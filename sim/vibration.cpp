#include <sim/vibration.hpp>

#include <cmath>
#include <numbers>

namespace sim {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kG = 9.80665;
constexpr double kRadPerDeg = std::numbers::pi / 180;

}  // namespace

Vibration::Vibration(const VehicleParams& vehicle, Random random)
    : vehicle_(vehicle), rotors_(rotor_geometry(vehicle)) {
  for (auto& rotor : offsets_) {
    for (Offsets& o : rotor) {
      o.accel_xy = random.uniform(0, kTwoPi);
      o.accel_z = random.uniform(0, kTwoPi);
      o.gyro = {random.uniform(0, kTwoPi), random.uniform(0, kTwoPi), random.uniform(0, kTwoPi)};
    }
  }
}

VibrationSample Vibration::at(const std::array<double, kRotorCount>& speed,
                              const std::array<double, kRotorCount>& phase, double low_pass_hz) const {
  const VehicleParams& v = vehicle_;
  const double accel_amp[kVibrationHarmonics] = {v.vibration_accel_g.x, v.vibration_accel_g.y, v.vibration_accel_g.z};
  const double gyro_amp[kVibrationHarmonics] = {v.vibration_gyro_dps.x, v.vibration_gyro_dps.y, v.vibration_gyro_dps.z};
  VibrationSample out;
  for (size_t i = 0; i < kRotorCount; ++i) {
    const double relative = speed[i] / v.vibration_ref_speed;
    const double growth = relative * relative;
    for (size_t h = 0; h < kVibrationHarmonics; ++h) {
      const double n = static_cast<double>(h + 1);
      double gain = growth;
      if (low_pass_hz > 0) {
        const double f = n * speed[i] / kTwoPi;
        gain /= std::sqrt(1 + (f / low_pass_hz) * (f / low_pass_hz));
      }
      const Offsets& o = offsets_[i][h];
      const double angle = n * phase[i];
      // The in-plane vector turns with the rotor: its sense follows the rotor's spin.
      const double a = accel_amp[h] * kG * gain;
      out.accel += Vec3{a * std::cos(angle + o.accel_xy), a * rotors_[i].spin * std::sin(angle + o.accel_xy),
                        a * v.vibration_accel_z_ratio * std::cos(angle + o.accel_z)};
      const double g = gyro_amp[h] * kRadPerDeg * gain;
      out.gyro += Vec3{g * std::cos(angle + o.gyro.x), g * std::cos(angle + o.gyro.y), g * std::cos(angle + o.gyro.z)};
    }
  }
  return out;
}

}  // namespace sim
