// The IIR steps, one generic implementation instantiated for Q (signal Q<16>, coefficients
// Q<30>), double and float. The Q filter is compared with the double one run on the same
// quantised coefficients and the same inputs, so the only difference is narrow()'s rounding:
// at most 1/2 lsb per step, fed back through 1/A(z). The asserted bound follows from that:
//   |y_Q - y_double| <= 1/2 lsb * sum_n |h_A[n]|,  h_A the impulse response of 1/A(z),
// computed here for each filter, plus 1e-12 for the double reference's own rounding.
#include <gtest/gtest.h>
#include <fixedpoint/iir.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "max_error.hpp"

namespace {

using Signal = fx::Q<16>;
using Coefficient = fx::Q<30>;
constexpr double kLsb = 0x1p-16;

// Run-time values into Q for the test (the library only makes constants from doubles).
template <typename Q>
Q quantise(double v) {
  return Q::from_raw(static_cast<typename Q::raw_type>(std::llround(std::ldexp(v, Q::frac_bits))));
}

// Bilinear-transform low-pass designs, as a test fixture (the library takes coefficients as
// given). Returned already quantised to Q<30>; the double filter uses these exact values.
fx::Iir1Coefficients<Coefficient> lowpass1(double fc_over_fs) {
  const double k = std::tan(std::numbers::pi * fc_over_fs);
  return {quantise<Coefficient>(k / (1 + k)), quantise<Coefficient>(k / (1 + k)),
          quantise<Coefficient>((k - 1) / (k + 1))};
}

fx::Iir2Coefficients<Coefficient> butterworth2(double fc_over_fs) {
  const double k = std::tan(std::numbers::pi * fc_over_fs);
  const double n = 1 / (1 + std::numbers::sqrt2 * k + k * k);
  return {quantise<Coefficient>(k * k * n), quantise<Coefficient>(2 * k * k * n), quantise<Coefficient>(k * k * n),
          quantise<Coefficient>(2 * (k * k - 1) * n), quantise<Coefficient>((1 - std::numbers::sqrt2 * k + k * k) * n)};
}

template <typename C>
C as(Coefficient c) {
  return static_cast<C>(c.to_double());
}
template <typename C>
fx::Iir1Coefficients<C> as(const fx::Iir1Coefficients<Coefficient>& c) {
  return {as<C>(c.b0), as<C>(c.b1), as<C>(c.a1)};
}
template <typename C>
fx::Iir2Coefficients<C> as(const fx::Iir2Coefficients<Coefficient>& c) {
  return {as<C>(c.b0), as<C>(c.b1), as<C>(c.b2), as<C>(c.a1), as<C>(c.a2)};
}

// sum |h[n]| for h the impulse response of 1 / (1 + a1 z^-1 + a2 z^-2), until it has died out.
double feedback_gain(double a1, double a2) {
  double y1 = 0, y2 = 0, sum = 0;
  for (int n = 0; n < 1000000; ++n) {
    const double y = (n == 0 ? 1.0 : 0.0) - a1 * y1 - a2 * y2;
    sum += std::fabs(y);
    y2 = y1;
    y1 = y;
    if (n > 100 && std::fabs(y1) + std::fabs(y2) < 1e-18) break;
  }
  return sum;
}

// Inputs that exercise a low-pass: a step, a sine near the cut-off, and noise.
std::vector<Signal> test_input() {
  std::vector<Signal> x;
  for (int n = 0; n < 2000; ++n) x.push_back(Signal(1.0));
  for (int n = 0; n < 4000; ++n) x.push_back(quantise<Signal>(100 * std::sin(2 * std::numbers::pi * 0.02 * n)));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> noise(-500.0, 500.0);
  for (int n = 0; n < 20000; ++n) x.push_back(quantise<Signal>(noise(rng)));
  return x;
}

TEST(Iir, FirstOrderInQFollowsDoubleWithinTheRoundingBound) {
  for (const double fc : {0.003, 0.03, 0.2}) {
    const auto q = lowpass1(fc);
    const auto d = as<double>(q);
    const auto f = as<float>(q);
    const double bound = 0.5 * kLsb * feedback_gain(d.a1, 0.0) + 1e-12;
    fx::Iir1State<Signal> sq;
    fx::Iir1State<double> sd;
    fx::Iir1State<float> sf;
    fxtest::MaxError e("iir1 fc/fs = " + std::to_string(fc) + ", Q<16>/Q<30> vs double");
    double float_error = 0;
    for (const Signal x : test_input()) {
      const double yq = fx::iir1_step(sq, q, x).to_double();
      const double yd = fx::iir1_step(sd, d, x.to_double());
      const float yf = fx::iir1_step(sf, f, static_cast<float>(x.to_double()));
      e.add(std::fabs(yq - yd), yd);
      float_error = std::max(float_error, std::fabs(static_cast<double>(yf) - yd));
      ASSERT_EQ(sq.x1, x);
      ASSERT_EQ(sq.y1.to_double(), yq);
    }
    e.print(bound);
    EXPECT_LE(e.max(), bound);
    EXPECT_LE(float_error, 1e-3) << "float, a sanity check of the same code: 24-bit mantissa on values up to 500";
  }
}

TEST(Iir, SecondOrderInQFollowsDoubleWithinTheRoundingBound) {
  for (const double fc : {0.005, 0.03, 0.2}) {
    const auto q = butterworth2(fc);
    const auto d = as<double>(q);
    const auto f = as<float>(q);
    const double bound = 0.5 * kLsb * feedback_gain(d.a1, d.a2) + 1e-12;
    fx::Iir2State<Signal> sq;
    fx::Iir2State<double> sd;
    fx::Iir2State<float> sf;
    fxtest::MaxError e("iir2 fc/fs = " + std::to_string(fc) + ", Q<16>/Q<30> vs double");
    double float_error = 0;
    Signal previous_x, previous_y;
    for (const Signal x : test_input()) {
      const double yq = fx::iir2_step(sq, q, x).to_double();
      const double yd = fx::iir2_step(sd, d, x.to_double());
      const float yf = fx::iir2_step(sf, f, static_cast<float>(x.to_double()));
      e.add(std::fabs(yq - yd), yd);
      float_error = std::max(float_error, std::fabs(static_cast<double>(yf) - yd));
      ASSERT_EQ(sq.x1, x);
      ASSERT_EQ(sq.x2, previous_x);
      ASSERT_EQ(sq.y1.to_double(), yq);
      ASSERT_EQ(sq.y2, previous_y);
      previous_x = x;
      previous_y = sq.y1;
    }
    e.print(bound);
    EXPECT_LE(e.max(), bound);
    EXPECT_LE(float_error, 1e-2) << "float, a sanity check of the same code: 24-bit mantissa on values up to 500";
  }
}

TEST(Iir, LowPassSettlesToItsInputInQ) {
  auto q = butterworth2(0.03);
  fx::Iir2State<Signal> s;
  Signal y;
  for (int n = 0; n < 1000; ++n) y = fx::iir2_step(s, q, Signal(-3.25));
  // DC gain of the quantised coefficients is 1 to within 1e-8; the rest is rounding.
  EXPECT_NEAR(y.to_double(), -3.25, 0.5 * kLsb * feedback_gain(q.a1.to_double(), q.a2.to_double()));
}

TEST(Iir, StepsAreConstexpr) {
  constexpr auto settled = [] {
    constexpr fx::Iir1Coefficients<Coefficient> c{Coefficient(0.25), Coefficient(0.25), Coefficient(-0.5)};
    fx::Iir1State<Signal> s;
    Signal y;
    for (int n = 0; n < 100; ++n) y = fx::iir1_step(s, c, Signal(2.0));
    return y;
  }();
  static_assert(settled == Signal(2.0));
}

}  // namespace
