// An MS5611-class barometer (the GY-86 board's): pressure from the altitude by the standard
// atmosphere, the sensor's noise at its oversampling ratio, a slow temperature drift, and the
// timing of its conversions. Figures from the MS5611-01BA03 datasheet (MEAS / TE Connectivity),
// "Operating range and performance" and "ADC conversion time":
//
//   OSR                      256    512    1024   2048   4096
//   pressure resolution RMS  0.065  0.042  0.027  0.018  0.012 mbar (1 mbar = 100 Pa)
//   temperature resol. RMS   0.012  0.008  0.005  0.003  0.002 °C
//   conversion time, max     0.60   1.17   2.28   4.54   9.04 ms
//
// The board runs OSR 4096: a pressure conversion (D1) and a temperature conversion (D2) take
// 2 x 9.04 = 18.1 ms, so a compensated reading comes every 20 ms. Between readings the board
// reports the last one. The pressure a reading reports is the one at the middle of its D1
// conversion, 4.5 ms after the cycle starts; it is published at the end of the cycle, 15.5 ms
// later. The sensor's output is in 0.01 mbar = 1 Pa steps.
//
// Standard atmosphere (troposphere, below 11 km): p = p0 (1 - L h / T0)^(g0 M / (R L)), with
// p0 = 101325 Pa, T0 = 288.15 K, L = 0.0065 K/m, g0 M / (R L) = 5.25588 (ICAO Doc 7488/3,
// Manual of the ICAO Standard Atmosphere, 1993; the same as the U.S. Standard Atmosphere 1976,
// NOAA-S/T 76-1562). The ground is at ISA sea level.
//
// Temperature: the board warms from the ambient (ISA 15 °C) by baro_warmup_k with time constant
// baro_warmup_tau_s after power-up (regulators and the sensor's own current; our estimate), and the
// compensated pressure keeps a residual of baro_temp_coeff_pa_per_k per kelvin of that warming
// (our estimate: the datasheet specifies the error band over temperature, not the slope left after
// its second-order compensation). That is the slow drift a height estimate cannot tell from a climb.
#pragma once

#include <stdint.h>

#include <sim/random.hpp>
#include <sim/vehicle.hpp>

namespace sim {

inline constexpr double kIsaSeaLevelPa = 101325.0;
inline constexpr double kIsaSeaLevelK = 288.15;
inline constexpr double kIsaLapseKPerM = 0.0065;
inline constexpr double kIsaExponent = 5.25588;  // g0 M / (R L)

// ISA pressure at geopotential altitude `metres` (troposphere), and its inverse.
double isa_pressure_pa(double metres);
double isa_altitude_m(double pascals);

class Barometer {
 public:
  static constexpr uint64_t kPeriodUs = 20000;      // one D1 + D2 cycle at OSR 4096, rounded up
  static constexpr uint64_t kPressureMidUs = 4520;  // middle of the D1 conversion (9.04 ms / 2)
  static constexpr double kResolutionPa = 1.0;      // output step, 0.01 mbar

  Barometer(const VehicleParams& vehicle, const Random& random);

  // Called at every physics step with the time and the board's altitude above sea level: takes
  // the pressure at the middle of each D1 conversion and publishes it at the end of the cycle.
  void step(uint64_t now_us, double altitude_m);

  // What the sensing element senses at `now_us` at `altitude_m`, Pa: the ISA pressure, the warm-up
  // drift and one draw of the noise, scaled by `noise_scale` (1: baro_noise_pa, the RMS at OSR 4096).
  // step() takes its readings through it; the register-level model (sim/ms5611_model.hpp) converts
  // what it returns, at the OSR its driver asked for.
  double sense_pa(uint64_t now_us, double altitude_m, double noise_scale = 1.0);

  // The last published reading, Pa (what the board reports); 0 before the first.
  int32_t pressure_pa() const { return published_pa_; }
  // The board's temperature now, °C, and the pressure error it adds, Pa.
  double temperature_c(uint64_t now_us) const;
  double drift_pa(uint64_t now_us) const;
  double noise_sigma_pa() const { return noise_pa_; }
  // Where in its cycle the barometer started (drawn from the seed): readings are published at
  // phase + k * kPeriodUs.
  uint64_t phase_us() const { return phase_us_; }
  // The next instant step() does something (takes or publishes a reading): a coarse physics
  // step must not stride across it, or the reading would be taken at the wrong altitude/time.
  uint64_t next_event_us() const { return next_sample_us_ < next_publish_us_ ? next_sample_us_ : next_publish_us_; }

 private:
  Random random_;
  double noise_pa_;
  double temp_coeff_pa_per_k_;
  double warmup_k_;
  double warmup_tau_s_;
  uint64_t phase_us_;
  uint64_t next_sample_us_;   // next D1 midpoint
  uint64_t next_publish_us_;  // end of the cycle that sample belongs to
  double sampled_pa_ = 0;
  int32_t published_pa_ = 0;
};

}  // namespace sim
