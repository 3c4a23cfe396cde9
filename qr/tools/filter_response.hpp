// Frequency response of a designed filter, on the host: H(e^jw) = B(e^-jw) / A(e^-jw) for the
// coefficients as designed (double) or as quantised (integers of a Q format), and the analytic
// Butterworth magnitude the bilinear design must reproduce:
//   |H(f)|^2 = 1 / (1 + (tan(pi f / fs) / tan(pi fc / fs))^(2N))
// (the analogue Butterworth response at the pre-warped frequency; -3.01 dB at fc).
#pragma once

#include <cmath>
#include <complex>
#include <numbers>

#include <qr/core/chain/butterworth_design.hpp>

namespace qr::chain {

struct Response {
  double gain_db;
  double phase_deg;
};

inline Response response_of(const double (&b)[3], const double (&a)[3], double f_hz, double fs_hz) {
  const double w = 2 * std::numbers::pi * f_hz / fs_hz;
  const std::complex<double> z1 = std::polar(1.0, -w), z2 = z1 * z1;
  const std::complex<double> h = (b[0] + b[1] * z1 + b[2] * z2) / (a[0] + a[1] * z1 + a[2] * z2);
  return {20 * std::log10(std::abs(h)), std::arg(h) * 180 / std::numbers::pi};
}

inline Response response_of(const ButterworthDesign& d, double f_hz, double fs_hz) {
  return response_of(d.b, d.a, f_hz, fs_hz);
}

inline Response response_of(const QuantisedDesign& q, double f_hz, double fs_hz) {
  double b[3], a[3];
  for (int i = 0; i < 3; ++i) {
    b[i] = std::ldexp(static_cast<double>(q.b[i]), -q.frac_bits);
    a[i] = std::ldexp(static_cast<double>(q.a[i]), -q.frac_bits);
  }
  return response_of(b, a, f_hz, fs_hz);
}

inline double analytic_butterworth_gain_db(int order, double fc_hz, double fs_hz, double f_hz) {
  const double ratio = std::tan(std::numbers::pi * f_hz / fs_hz) / std::tan(std::numbers::pi * fc_hz / fs_hz);
  return -10 * std::log10(1 + std::pow(ratio, 2 * order));
}

}  // namespace qr::chain
