#include <sim/barometer.hpp>

#include <algorithm>
#include <cmath>

namespace sim {

double isa_pressure_pa(double metres) {
  return kIsaSeaLevelPa * std::pow(1.0 - kIsaLapseKPerM * metres / kIsaSeaLevelK, kIsaExponent);
}

double isa_altitude_m(double pascals) {
  return kIsaSeaLevelK / kIsaLapseKPerM * (1.0 - std::pow(pascals / kIsaSeaLevelPa, 1.0 / kIsaExponent));
}

Barometer::Barometer(const VehicleParams& v, const Random& random)
    : random_(random), noise_pa_(v.baro_noise_pa), temp_coeff_pa_per_k_(v.baro_temp_coeff_pa_per_k),
      warmup_k_(v.baro_warmup_k), warmup_tau_s_(v.baro_warmup_tau_s) {
  // The sensor's cycle is not tied to the IMU's kick: where it starts is part of the draw.
  phase_us_ = static_cast<uint64_t>(random_.uniform(0.0, static_cast<double>(kPeriodUs)));
  next_sample_us_ = phase_us_ + kPressureMidUs;
  next_publish_us_ = phase_us_ + kPeriodUs;
}

double Barometer::temperature_c(uint64_t now_us) const {
  const double t = static_cast<double>(now_us) * 1e-6;
  return kIsaSeaLevelK - 273.15 + warmup_k_ * (1.0 - std::exp(-t / warmup_tau_s_));
}

double Barometer::drift_pa(uint64_t now_us) const {
  return temp_coeff_pa_per_k_ * (temperature_c(now_us) - (kIsaSeaLevelK - 273.15));
}

double Barometer::sense_pa(uint64_t now_us, double altitude_m, double noise_scale) {
  return isa_pressure_pa(altitude_m) + drift_pa(now_us) + noise_pa_ * noise_scale * random_.normal();
}

void Barometer::step(uint64_t now_us, double altitude_m) {
  if (now_us >= next_sample_us_) {
    sampled_pa_ = sense_pa(now_us, altitude_m);
    next_sample_us_ += kPeriodUs;
  }
  if (now_us >= next_publish_us_) {
    // 24-bit ADC, compensated to 0.01 mbar; the datasheet's range is 10..1200 mbar.
    const double steps = std::nearbyint(sampled_pa_ / kResolutionPa) * kResolutionPa;
    published_pa_ = static_cast<int32_t>(std::clamp(steps, 1000.0, 120000.0));
    next_publish_us_ += kPeriodUs;
  }
}

}  // namespace sim
