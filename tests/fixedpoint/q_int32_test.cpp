// Q<F, int32_t> against the exact reference, for formats from integer (F = 0) to pure fraction
// (F = 31): every pair of edge values (extremes, powers of two and their neighbours) plus
// 100 000 random pairs from a fixed seed per operation.
#include <gtest/gtest.h>
#include <fixedpoint/q.hpp>

#include <cstdio>
#include <functional>

#include "reference.hpp"

namespace {

using fxtest::i128;

constexpr int kRandomPairs = 100000;

// Runs Check::run<Q>() for each int32 format, from integer to pure fraction.
template <typename Check>
void for_each_format() {
  Check::template run<fx::Q<0>>();
  Check::template run<fx::Q<1>>();
  Check::template run<fx::Q<16>>();
  Check::template run<fx::Q<30>>();
  Check::template run<fx::Q<31>>();
}

// Calls check(a, b) on every edge pair and on random pairs, until the first failure.
template <typename Q>
void for_pairs(uint64_t seed, const std::function<void(Q, Q)>& check) {
  SCOPED_TRACE(::testing::Message() << "in Q<" << Q::frac_bits << ">");
  const auto edges = fxtest::edge_raws<int32_t>();
  for (int32_t a : edges) {
    for (int32_t b : edges) {
      check(Q::from_raw(a), Q::from_raw(b));
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  fxtest::RawSource<int32_t> source(seed);
  for (int i = 0; i < kRandomPairs; ++i) {
    check(Q::from_raw(source.next()), Q::from_raw(source.next()));
    if (::testing::Test::HasFatalFailure()) return;
  }
}

struct AddAndSubtractWrapOrSaturate {
  template <typename Q>
  static void run() {
    for_pairs<Q>(1, [](Q a, Q b) {
      const i128 sum = i128{a.raw()} + b.raw(), difference = i128{a.raw()} - b.raw();
      ASSERT_EQ((a + b).raw(), fxtest::wrapped<int32_t>(sum)) << a.raw() << " + " << b.raw();
      ASSERT_EQ((a - b).raw(), fxtest::wrapped<int32_t>(difference)) << a.raw() << " - " << b.raw();
      ASSERT_EQ(add_sat(a, b).raw(), fxtest::saturated<int32_t>(sum)) << a.raw() << " + " << b.raw();
      ASSERT_EQ(sub_sat(a, b).raw(), fxtest::saturated<int32_t>(difference)) << a.raw() << " - " << b.raw();
      Q c = a;
      c += b;
      ASSERT_EQ(c, a + b);
      c -= b;
      ASSERT_EQ(c, a);
    });
  }
};
TEST(QInt32, AddAndSubtractWrapOrSaturate) { for_each_format<AddAndSubtractWrapOrSaturate>(); }

struct MultiplyRoundsHalfUpThenWrapsOrSaturates {
  template <typename Q>
  static void run() {
    for_pairs<Q>(2, [](Q a, Q b) {
      const i128 exact = fxtest::round_half_up_shift(i128{a.raw()} * b.raw(), Q::frac_bits);
      ASSERT_EQ((a * b).raw(), fxtest::wrapped<int32_t>(exact)) << a.raw() << " * " << b.raw();
      ASSERT_EQ(mul_sat(a, b).raw(), fxtest::saturated<int32_t>(exact)) << a.raw() << " * " << b.raw();
      Q c = a;
      c *= b;
      ASSERT_EQ(c, a * b);
    });
  }
};
TEST(QInt32, MultiplyRoundsHalfUpThenWrapsOrSaturates) { for_each_format<MultiplyRoundsHalfUpThenWrapsOrSaturates>(); }

struct DivideRoundsHalfUpAndSaturatesIncludingByZero {
  template <typename Q>
  static void run() {
    for_pairs<Q>(3, [](Q a, Q b) {
      const int32_t expected = b.raw() == 0 ? (a.raw() > 0   ? INT32_MAX
                                               : a.raw() < 0 ? INT32_MIN
                                                             : 0)
                                            : fxtest::saturated<int32_t>(
                                                  fxtest::round_half_up_div(i128{a.raw()} << Q::frac_bits, b.raw()));
      ASSERT_EQ((a / b).raw(), expected) << a.raw() << " / " << b.raw();
      ASSERT_EQ(div_sat(a, b).raw(), expected) << a.raw() << " / " << b.raw();
      Q c = a;
      c /= b;
      ASSERT_EQ(c.raw(), expected);
    });
  }
};
TEST(QInt32, DivideRoundsHalfUpAndSaturatesIncludingByZero) {
  for_each_format<DivideRoundsHalfUpAndSaturatesIncludingByZero>();
}

// Quotients exactly half-way between two raws, where only the rounding rule decides (random
// pairs almost never land there): a 2^16 = (q + 1/2) d with d = 2^17 t, a = t (2q + 1), of both
// signs, and the same for whole numbers (Q<0>: a = q d + d / 2). Positive halves go up, negative
// ones towards zero (half up: -2.5 -> -2).
TEST(QInt32, DivideRoundsExactHalvesUp) {
  fxtest::RawSource<int32_t> source(6);
  int checked = 0;
  for (int i = 0; i < 200000; ++i) {
    const uint32_t t = 1u + static_cast<uint32_t>(source.next()) % 16383u;                      // d = 2^17 t < 2^31
    const uint32_t q = static_cast<uint32_t>(source.next()) % (0x7FFFFFFFu / (2 * t + 1) / 2);  // a fits
    const int32_t a = static_cast<int32_t>(t * (2 * q + 1)), d = static_cast<int32_t>(t << 17);
    using Q16 = fx::Q<16>;
    ASSERT_EQ((Q16::from_raw(a) / Q16::from_raw(d)).raw(), static_cast<int32_t>(q + 1)) << a << " / " << d;
    ASSERT_EQ((Q16::from_raw(-a) / Q16::from_raw(d)).raw(), -static_cast<int32_t>(q)) << -a << " / " << d;
    ASSERT_EQ((Q16::from_raw(a) / Q16::from_raw(-d)).raw(), -static_cast<int32_t>(q)) << a << " / " << -d;
    const uint32_t whole_d = 2u * (1u + static_cast<uint32_t>(source.next()) % 0x3FFFFFFEu);
    const uint32_t whole_q = static_cast<uint32_t>(source.next()) % ((0x7FFFFFFFu - whole_d / 2) / whole_d + 1);
    const int32_t whole_a = static_cast<int32_t>(whole_q * whole_d + whole_d / 2);
    using Q0 = fx::Q<0>;
    ASSERT_EQ((Q0::from_raw(whole_a) / Q0::from_raw(static_cast<int32_t>(whole_d))).raw(),
              static_cast<int32_t>(whole_q + 1));
    ASSERT_EQ((Q0::from_raw(-whole_a) / Q0::from_raw(static_cast<int32_t>(whole_d))).raw(),
              -static_cast<int32_t>(whole_q));
    checked += 5;
  }
  std::printf("  %d exact halves rounded\n", checked);
}

struct TimesIntegerWrapsOrSaturates {
  template <typename Q>
  static void run() {
    for_pairs<Q>(4, [](Q a, Q b) {
      const int32_t n = b.raw();
      const i128 exact = i128{a.raw()} * n;
      ASSERT_EQ((a * n).raw(), fxtest::wrapped<int32_t>(exact)) << a.raw() << " * " << n;
      ASSERT_EQ((n * a).raw(), fxtest::wrapped<int32_t>(exact)) << n << " * " << a.raw();
      ASSERT_EQ(mul_sat(a, n).raw(), fxtest::saturated<int32_t>(exact)) << a.raw() << " * " << n;
    });
  }
};
TEST(QInt32, TimesIntegerWrapsOrSaturates) { for_each_format<TimesIntegerWrapsOrSaturates>(); }

struct NegateAbsShiftCompare {
  template <typename Q>
  static void run() {
    for_pairs<Q>(5, [](Q a, Q b) {
      const i128 x = a.raw();
      ASSERT_EQ((-a).raw(), fxtest::wrapped<int32_t>(-x));
      ASSERT_EQ(neg_sat(a).raw(), fxtest::saturated<int32_t>(-x));
      ASSERT_EQ(abs_sat(a).raw(), fxtest::saturated<int32_t>(x < 0 ? -x : x));
      const int n = static_cast<int>(static_cast<uint32_t>(b.raw()) % 36) - 2;  // -2 .. 33
      const int k = std::clamp(n, 0, 32);
      ASSERT_EQ((a << n).raw(), fxtest::wrapped<int32_t>(x << k)) << a.raw() << " << " << n;
      ASSERT_EQ(shl_sat(a, n).raw(), fxtest::saturated<int32_t>(x << k)) << a.raw() << " << " << n;
      ASSERT_EQ((a >> n).raw(), static_cast<int32_t>(fxtest::floor_div(x, i128{1} << std::min(k, 31))))
          << a.raw() << " >> " << n;
      ASSERT_EQ(a == b, a.raw() == b.raw());
      ASSERT_EQ(a != b, a.raw() != b.raw());
      ASSERT_EQ(a < b, a.raw() < b.raw());
      ASSERT_EQ(a <= b, a.raw() <= b.raw());
      ASSERT_EQ(a > b, a.raw() > b.raw());
      ASSERT_EQ(a >= b, a.raw() >= b.raw());
    });
  }
};
TEST(QInt32, NegateAbsShiftCompare) { for_each_format<NegateAbsShiftCompare>(); }

struct IntegersInSaturatingAndOutRounded {
  template <typename Q>
  static void run() {
    for_pairs<Q>(6, [](Q a, Q b) {
      const int32_t n = b.raw();
      ASSERT_EQ(Q::from_int(n).raw(), fxtest::saturated<int32_t>(i128{n} << Q::frac_bits)) << n;
      ASSERT_EQ(a.to_int(), static_cast<int32_t>(fxtest::round_half_up_shift(a.raw(), Q::frac_bits))) << a.raw();
    });
  }
};
TEST(QInt32, IntegersInSaturatingAndOutRounded) { for_each_format<IntegersInSaturatingAndOutRounded>(); }

}  // namespace
