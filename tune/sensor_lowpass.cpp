#include <tune/sensor_lowpass.hpp>

#include <cmath>
#include <numbers>

namespace tune {

std::complex<double> Lowpass::response(std::complex<double> z) const {
  const std::complex<double> zi = 1.0 / z;
  return (b0 + zi * (b1 + zi * b2)) / (1.0 + zi * (a1 + zi * a2));
}

Lowpass butterworth_lowpass(double cutoff_hz, double sample_hz) {
  if (!(cutoff_hz > 0) || !(cutoff_hz < sample_hz / 2)) return {};
  const double k = std::tan(std::numbers::pi * cutoff_hz / sample_hz);
  const double den = 1 + std::numbers::sqrt2 * k + k * k;
  Lowpass f;
  f.b0 = f.b2 = k * k / den;
  f.b1 = 2 * k * k / den;
  f.a1 = 2 * (k * k - 1) / den;
  f.a2 = (1 - std::numbers::sqrt2 * k + k * k) / den;
  return f;
}

double LowpassRun::step(double x) {
  if (!started_) {
    x1_ = x2_ = y1_ = y2_ = x;
    started_ = true;
    return x;
  }
  const double y = f_.b0 * x + f_.b1 * x1_ + f_.b2 * x2_ - f_.a1 * y1_ - f_.a2 * y2_;
  x2_ = x1_;
  x1_ = x;
  y2_ = y1_;
  y1_ = y;
  return y;
}

}  // namespace tune
