// Shared by the chain's tests: run-time values into Q formats (the library makes Q only from
// integers or compile-time constants), and a largest-error tracker that prints the measured
// figure next to the bound it is checked against.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include <fixedpoint/q.hpp>

namespace qr::chain::test {

template <class Q>
Q quantise(double v) {
  return Q::from_raw(static_cast<typename Q::raw_type>(std::llround(std::ldexp(v, Q::frac_bits))));
}

template <class T>
double as_double(T v) {
  if constexpr (fx::is_q<T>) {
    return v.to_double();
  } else {
    return static_cast<double>(v);
  }
}

class MaxError {
 public:
  explicit MaxError(std::string what) : what_(std::move(what)) {}
  void add(double error, double at) {
    if (std::isnan(error) || std::fabs(error) > max_) {
      max_ = std::fabs(error);
      at_ = at;
    }
  }
  double max() const { return max_; }
  void print(double bound, const char* unit = "") const {
    std::printf("  %s: max error %.3e%s at %.6g (bound %.3e%s)\n", what_.c_str(), max_, unit, at_, bound, unit);
  }

 private:
  std::string what_;
  double max_ = 0;
  double at_ = 0;
};

}  // namespace qr::chain::test

#include <qr/core/board.hpp>
#include <qr/core/sensor_scale.hpp>

namespace qr::chain::test {

inline int16_t counts(double v) {
  const long r = std::lround(v);
  return static_cast<int16_t>(r > 32767 ? 32767 : r < -32768 ? -32768 : r);
}

// What the sensors read for a vehicle at rest in the air at this attitude (hovering: the specific
// force is gravity's reaction), turning at these body rates, plus raw offsets in counts.
inline SensorSample sample_at(double roll, double pitch, double p = 0, double q = 0, double r = 0,
                              const double (&gyro_offset)[3] = {0, 0, 0}, const double (&accel_offset)[3] = {0, 0, 0}) {
  SensorSample s;
  const double g = sensor::kAccelCountsPerG, c = sensor::kGyroCountsPerRadPerSec;
  s.accel[0] = counts(g * std::sin(pitch) + accel_offset[0]);
  s.accel[1] = counts(-g * std::sin(roll) * std::cos(pitch) + accel_offset[1]);
  s.accel[2] = counts(-g * std::cos(roll) * std::cos(pitch) + accel_offset[2]);
  s.gyro[0] = counts(c * p + gyro_offset[0]);
  s.gyro[1] = counts(c * q + gyro_offset[1]);
  s.gyro[2] = counts(c * r + gyro_offset[2]);
  s.battery_mv = 11800;
  return s;
}

}  // namespace qr::chain::test
