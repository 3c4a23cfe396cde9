// Tracks the largest error of a function over a sweep, where it occurred, and prints it, so a
// test run shows the measured figure next to the documented bound it asserts.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace fxtest {

class MaxError {
 public:
  explicit MaxError(std::string what) : what_(std::move(what)) {}

  void add(long double error, long double at) {
    if (std::isnan(error) || error > max_) {
      max_ = error;
      at_ = at;
    }
  }
  void add(double error, double at) { add(static_cast<long double>(error), static_cast<long double>(at)); }
  long double max() const { return max_; }
  long double at() const { return at_; }

  // Prints "what: max error E at X (bound B)".
  void print(long double bound) const {
    std::printf("  %s: max error %.3Le at %.12Lg (bound %.3Le)\n", what_.c_str(), max_, at_, bound);
  }
  void print(double bound) const { print(static_cast<long double>(bound)); }

 private:
  std::string what_;
  long double max_ = 0;
  long double at_ = 0;
};

}  // namespace fxtest
