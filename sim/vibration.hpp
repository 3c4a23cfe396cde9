// Motor vibration as the IMU feels it: each rotor's imbalance shakes the frame at the rotor's
// rotation frequency and its harmonics (the IN4073 report's FFT: 65, 130, 195 Hz at hover).
// Computed from the rotors' phases at the instant a sample is taken, so the sensor samples a
// continuous signal at the control rate and aliases it exactly as the real one does; nothing
// here is band-limited to the physics step.
#pragma once

#include <array>
#include <complex>

#include <sim/random.hpp>
#include <sim/rotor.hpp>
#include <sim/vehicle.hpp>

namespace sim {

inline constexpr int kVibrationHarmonics = 3;

struct VibrationSample {
  Vec3 accel;  // m/s², body axes
  Vec3 gyro;   // rad/s, body axes
};

class Vibration {
 public:
  // Each rotor and harmonic gets its own fixed phase offset (how the imbalance happens to sit
  // on that prop), drawn from `random`.
  Vibration(const VehicleParams& vehicle, Random random);  // a copy: drawing moves it

  // The vibration at rotor speeds `speed` (rad/s) and rotor angles `phase` (rad). Each rotor
  // adds, per harmonic h, an in-plane vector turning with the rotor (a rotating imbalance
  // force), a smaller vertical component, and rocking about all three axes, with amplitudes
  // growing as speed squared. `low_pass_hz` > 0 attenuates each line as the sensor's
  // first-order low-pass would.
  VibrationSample at(const std::array<double, kRotorCount>& speed, const std::array<double, kRotorCount>& phase,
                     double low_pass_hz) const;

 private:
  // Phase offsets as unit complex numbers: a harmonic's angle is then a product, not a cosine.
  struct Offsets {
    std::complex<double> accel_xy;
    std::complex<double> accel_z;
    std::complex<double> gyro[3];
  };
  VehicleParams vehicle_;
  std::array<RotorGeometry, kRotorCount> rotors_;
  std::array<std::array<Offsets, kVibrationHarmonics>, kRotorCount> offsets_;
};

}  // namespace sim
