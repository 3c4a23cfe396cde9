#include <tune/margins.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <vector>

namespace tune {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

constexpr int kPoints = 3000;
constexpr double kLowHz = 0.01;
constexpr double kDeg = 180 / std::numbers::pi;

struct Point {
  double log_omega, log_gain, phase_deg;  // phase unwrapped
};

}  // namespace

Margins margins_of(const std::function<std::complex<double>(double)>& loop, double sample_hz) {
  const double lo = std::log(2 * std::numbers::pi * kLowHz), hi = std::log(std::numbers::pi * sample_hz * 0.9995);
  std::vector<Point> sweep;
  sweep.reserve(kPoints);
  double previous = 0;
  for (int k = 0; k < kPoints; ++k) {
    const double u = lo + (hi - lo) * k / (kPoints - 1);
    const std::complex<double> l = loop(std::exp(u));
    double phase = std::arg(l) * kDeg;
    if (k > 0) phase += 360 * std::round((previous - phase) / 360);
    previous = phase;
    sweep.push_back({u, std::log(std::abs(l)), phase});
  }
  Margins m{kInfinity, kInfinity, 0};
  for (std::size_t k = 1; k < sweep.size(); ++k) {
    const Point& a = sweep[k - 1];
    const Point& b = sweep[k];
    if ((a.log_gain > 0) != (b.log_gain > 0)) {  // |L| crosses 1
      const double t = a.log_gain / (a.log_gain - b.log_gain);
      const double phase = a.phase_deg + t * (b.phase_deg - a.phase_deg);
      const double pm = std::remainder(phase + 180, 360);
      if (pm < m.phase_margin_deg) {
        m.phase_margin_deg = pm;
        m.crossover_hz = std::exp(a.log_omega + t * (b.log_omega - a.log_omega)) / (2 * std::numbers::pi);
      }
    }
    // The phase crosses -180 + 360 n between a and b.
    const double na = std::floor((a.phase_deg + 180) / 360), nb = std::floor((b.phase_deg + 180) / 360);
    if (na != nb) {
      const double target = 360 * std::max(na, nb) - 180;
      const double t = (target - a.phase_deg) / (b.phase_deg - a.phase_deg);
      const double log_gain = a.log_gain + t * (b.log_gain - a.log_gain);
      if (log_gain < 0) m.gain_margin_db = std::min(m.gain_margin_db, -20 * log_gain / std::log(10.0));
    }
  }
  return m;
}

}  // namespace tune
