// The floating-point number policies of the signal chain on the host, over <cmath>:
// DoubleNumbers is the accuracy reference, FloatNumbers the float instantiation.
#pragma once

#include <climits>
#include <cmath>
#include <cstdint>

#include <qr/host/real_number_policy.hpp>

namespace qr::chain {

struct StdMath {
  static double ldexp(double x, int e) { return std::ldexp(x, e); }
  template <class R>
  static int32_t round_half_up(R x) {
    const double r = std::floor(static_cast<double>(x) + 0.5);
    if (!(r > static_cast<double>(INT32_MIN))) return INT32_MIN;
    if (!(r < static_cast<double>(INT32_MAX))) return INT32_MAX;
    return static_cast<int32_t>(r);
  }
  template <class R>
  static R sqrt(R x) {
    return std::sqrt(x);
  }
  template <class R>
  static R atan2(R y, R x) {
    return std::atan2(y, x);
  }
};

using DoubleNumbers = RealNumbers<double, StdMath>;
using FloatNumbers = RealNumbers<float, StdMath>;

}  // namespace qr::chain
