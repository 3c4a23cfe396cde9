// The gyro low-pass the loops see the rate through, as a model: a second-order Butterworth at the
// filter_cutoff_hz parameter, run at the control rate. It restates the firmware's design
// (qr/core/chain/butterworth_design.hpp: bilinear transform with the cut-off pre-warped) in
// double, because tune/ may not include qr/; tests/tune holds the two against each other.
#pragma once

#include <complex>

namespace tune {

// H(z) = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2). A cut-off of 0 (no filter) or at or
// above half the sample rate gives the identity.
struct Lowpass {
  double b0 = 1, b1 = 0, b2 = 0, a1 = 0, a2 = 0;

  std::complex<double> response(std::complex<double> z) const;
};

Lowpass butterworth_lowpass(double cutoff_hz, double sample_hz);

// One filter's state. The first sample settles it on itself (as the firmware's filters start), so
// a record does not begin with a transient from zero.
class LowpassRun {
 public:
  explicit LowpassRun(const Lowpass& filter) : f_(filter) {}
  double step(double x);

 private:
  Lowpass f_;
  double x1_ = 0, x2_ = 0, y1_ = 0, y2_ = 0;
  bool started_ = false;
};

}  // namespace tune
