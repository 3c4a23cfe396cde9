// The wide accumulator: products exact for any pair of formats, sums exact, and one rounding
// when narrowing back. And the double/float overloads that let signal code be written once.
#include <gtest/gtest.h>
#include <fixedpoint/wide.hpp>

#include <utility>

#include "reference.hpp"

namespace {

using fx::Q;
using Q8s = Q<8, int16_t>;  // int16 formats by name, so that macros see one argument
using fxtest::i128;

template <typename A, typename B>
void expect_exact_products(uint64_t seed) {
  fxtest::RawSource<typename A::raw_type> as(seed);
  fxtest::RawSource<typename B::raw_type> bs(seed + 1);
  for (int i = 0; i < 100000; ++i) {
    const A a = A::from_raw(as.next());
    const B b = B::from_raw(bs.next());
    const auto w = fx::mul_wide(a, b);
    static_assert(decltype(w)::frac_bits == A::frac_bits + B::frac_bits);
    ASSERT_EQ(w.raw(), int64_t{a.raw()} * b.raw());
  }
}

TEST(Wide, ProductsAreExactForMixedFormats) {
  expect_exact_products<Q<30>, Q<16>>(1);
  expect_exact_products<Q<31>, Q<31>>(2);
  expect_exact_products<Q<0>, Q<0>>(3);
  expect_exact_products<Q8s, Q<14, int16_t>>(4);
  expect_exact_products<Q<15, int16_t>, Q<31>>(5);
  EXPECT_EQ(fx::mul_wide(Q<31>::min(), Q<31>::min()).raw(), int64_t{1} << 62);
  EXPECT_EQ(fx::mul_wide(Q<15, int16_t>::min(), Q<15, int16_t>::min()).raw(), int64_t{1} << 30);
}

TEST(Wide, SumsOfProductsNarrowWithOneRounding) {
  fxtest::RawSource<int32_t> source(7);
  int overflowed = 0;
  for (int i = 0; i < 100000; ++i) {
    Q<30> c[5];
    Q<16> x[5];
    i128 exact = 0;
    for (int k = 0; k < 5; ++k) {
      c[k] = Q<30>::from_raw(source.next());
      x[k] = Q<16>::from_raw(source.next());
      exact += (k < 3 ? 1 : -1) * (i128{c[k].raw()} * x[k].raw());
    }
    const auto acc = fx::mul_wide(c[0], x[0]) + fx::mul_wide(c[1], x[1]) + fx::mul_wide(c[2], x[2]) -
                     fx::mul_wide(c[3], x[3]) - fx::mul_wide(c[4], x[4]);
    const i128 rounded = fxtest::round_half_up_shift(exact, 30);
    // Wrapping loses nothing the wrapping narrow keeps: bits 29..61 survive modulo 2^64.
    ASSERT_EQ(fx::narrow<Q<16>>(acc).raw(), fxtest::wrapped<int32_t>(rounded));
    // Saturation needs the true sum, which a Wide holds when it fits 64 bits.
    if (exact != static_cast<int64_t>(exact)) {
      ++overflowed;
      continue;
    }
    ASSERT_EQ(fx::narrow_sat<Q<16>>(acc).raw(), fxtest::saturated<int32_t>(rounded));
    ASSERT_EQ(fx::narrow_sat<Q8s>(acc).raw(), fxtest::saturated<int16_t>(fxtest::round_half_up_shift(exact, 38)));
  }
  EXPECT_LT(overflowed, 1000);  // the random terms are full scale only now and then
}

// narrow_sat to a 32-bit raw with a right shift of 1..31 works on the two words of the sum
// (detail::narrow_sat_words): against the 128-bit reference at every shift, on the values where
// it could go wrong (the floor at the edges of int32 with and without the rounding bit, the high
// word at the edges of the fit test, the ends of int64) and on random sums.
template <int Shift>
void check_narrow_sat_words(fxtest::RawSource<int32_t>& source) {
  using To = Q<0>;
  const auto check = [](int64_t v) {
    const int32_t got = fx::narrow_sat<To>(fx::Wide<Shift>::from_raw(v)).raw();
    ASSERT_EQ(got, fxtest::saturated<int32_t>(fxtest::round_half_up_shift(i128{v}, Shift)))
        << "shift " << Shift << ", " << v;
  };
  const i128 half = i128{1} << (Shift - 1);
  for (const i128 floor : {i128{INT32_MAX}, i128{INT32_MAX} - 1, i128{INT32_MAX} + 1, i128{INT32_MIN},
                           i128{INT32_MIN} + 1, i128{INT32_MIN} - 1, i128{0}, i128{-1}}) {
    for (const i128 below : {i128{0}, half - 1, half, 2 * half - 1}) {
      check(static_cast<int64_t>(floor * 2 * half + below));
    }
  }
  for (const int64_t v : {INT64_MAX, INT64_MIN, INT64_MAX - 1, INT64_MIN + 1}) check(v);
  for (int i = 0; i < 20000; ++i) {
    // Full-scale high words now and then, else high words near the fit test's edges.
    const int32_t high = i % 2 == 0 ? source.next() : (source.next() >> (31 - Shift));
    const uint32_t low = static_cast<uint32_t>(source.next());
    check(static_cast<int64_t>((static_cast<uint64_t>(static_cast<uint32_t>(high)) << 32) | low));
  }
}

template <int... Shifts>
void check_narrow_sat_words_at(std::integer_sequence<int, Shifts...>) {
  fxtest::RawSource<int32_t> source(23);
  (check_narrow_sat_words<Shifts + 1>(source), ...);
}

TEST(Wide, NarrowSatOnTwoWordsIsTheSaturatedRounding) {
  check_narrow_sat_words_at(std::make_integer_sequence<int, 31>{});
}

TEST(Wide, NarrowingToMoreFractionalBitsIsExact) {
  const auto w = fx::Wide<4>::from_raw(-37);  // -2.3125
  EXPECT_EQ(fx::narrow<Q<16>>(w), Q<16>(-2.3125));
  EXPECT_EQ(fx::narrow_sat<Q<30>>(fx::Wide<4>::from_raw(40)), Q<30>::max());
  EXPECT_EQ(fx::narrow_sat<Q<30>>(fx::Wide<4>::from_raw(-40)), Q<30>::min());
  EXPECT_EQ(fx::narrow_sat<Q<30>>(fx::Wide<4>::from_raw(-32)), Q<30>::min());
}

TEST(Wide, NarrowRoundsHalfUp) {
  using W = fx::Wide<2>;
  EXPECT_EQ(fx::narrow<Q<0>>(W::from_raw(-6)).raw(), -1);  // -1.5
  EXPECT_EQ(fx::narrow<Q<0>>(W::from_raw(-2)).raw(), 0);   // -0.5
  EXPECT_EQ(fx::narrow<Q<0>>(W::from_raw(2)).raw(), 1);    // 0.5
  EXPECT_EQ(fx::narrow<Q<0>>(W::from_raw(-3)).raw(), -1);  // -0.75
}

TEST(Wide, SumsWrapModulo2To64AndNegate) {
  using W = fx::Wide<0>;
  EXPECT_EQ((W::from_raw(INT64_MAX) + W::from_raw(1)).raw(), INT64_MIN);
  EXPECT_EQ((W::from_raw(INT64_MIN) - W::from_raw(1)).raw(), INT64_MAX);
  EXPECT_EQ((-W::from_raw(INT64_MIN)).raw(), INT64_MIN);
  EXPECT_EQ((-W::from_raw(5)).raw(), -5);
  W acc;
  acc += W::from_raw(7);
  acc -= W::from_raw(9);
  EXPECT_EQ(acc, W::from_raw(-2));
  EXPECT_EQ(fx::Wide<46>::from_raw(int64_t{3} << 45).to_double(), 1.5);
}

// Written once over the number type, the way the filters and the estimator are.
template <typename T, typename C>
T weighted_difference(C a, T x, C b, T y) {
  return fx::narrow<T>(fx::mul_wide(a, x) - fx::mul_wide(b, y));
}

TEST(Wide, FloatingPointOverloadsArePlainArithmetic) {
  EXPECT_EQ(fx::mul_wide(1.5, -2.0), -3.0);
  EXPECT_EQ(fx::mul_wide(1.5f, -2.0f), -3.0f);
  static_assert(std::is_same_v<decltype(fx::mul_wide(1.0f, 1.0f)), float>);
  EXPECT_EQ(fx::narrow<double>(0.1), 0.1);
  EXPECT_EQ(fx::narrow<float>(0.1f), 0.1f);
  EXPECT_EQ(fx::narrow_sat<double>(1e300), 1e300);
  EXPECT_EQ(fx::narrow_sat<float>(-2.5f), -2.5f);

  EXPECT_EQ(weighted_difference(0.75, 2.0, 0.25, -4.0), 2.5);
  EXPECT_EQ(weighted_difference(0.75f, 2.0f, 0.25f, -4.0f), 2.5f);
  EXPECT_EQ(weighted_difference(Q<30>(0.75), Q<16>(2.0), Q<30>(0.25), Q<16>(-4.0)), Q<16>(2.5));
}

}  // namespace
