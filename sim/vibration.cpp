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
  const auto phase = [&random] { return std::polar(1.0, random.uniform(0, kTwoPi)); };
  for (auto& rotor : offsets_) {
    for (Offsets& o : rotor) {
      o.accel_xy = phase();
      o.accel_z = phase();
      for (auto& g : o.gyro) g = phase();
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
    const std::complex<double> turn = std::polar(1.0, phase[i]);  // e^(i angle)
    std::complex<double> harmonic = 1;
    for (size_t h = 0; h < kVibrationHarmonics; ++h) {
      harmonic *= turn;  // e^(i n angle), n = h + 1
      double gain = growth;
      if (low_pass_hz > 0) {
        const double f = static_cast<double>(h + 1) * speed[i] / kTwoPi;
        gain /= std::sqrt(1 + (f / low_pass_hz) * (f / low_pass_hz));
      }
      const Offsets& o = offsets_[i][h];
      // The in-plane vector turns with the rotor: its sense follows the rotor's spin.
      const std::complex<double> xy = harmonic * o.accel_xy;
      const double a = accel_amp[h] * kG * gain;
      out.accel += Vec3{a * xy.real(), a * rotors_[i].spin * xy.imag(),
                        a * v.vibration_accel_z_ratio * (harmonic * o.accel_z).real()};
      const double g = gyro_amp[h] * kRadPerDeg * gain;
      out.gyro += Vec3{g * (harmonic * o.gyro[0]).real(), g * (harmonic * o.gyro[1]).real(),
                       g * (harmonic * o.gyro[2]).real()};
    }
  }
  return out;
}

}  // namespace sim
