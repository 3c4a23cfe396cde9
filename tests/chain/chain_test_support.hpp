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
