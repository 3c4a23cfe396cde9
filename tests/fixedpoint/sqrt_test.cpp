// fx::sqrt is correctly rounded: the result equals the exact square root rounded to the
// nearest lsb, checked with integers (no ties exist), and so is within 0.5 lsb of sqrtl.
// Every value of three int16 formats; edges, random raws and the neighbourhoods of perfect
// squares for int32 formats from Q<0> to Q<31>.
#include <gtest/gtest.h>
#include <fixedpoint/sqrt.hpp>

#include <cmath>
#include <cstdio>

#include "max_error.hpp"
#include "reference.hpp"

namespace {

using u128 = unsigned __int128;

// round(sqrt(n)) by integers: r = floor(sqrt(n)), then up when sqrt(n) >= r + 1/2, i.e.
// 4n >= (2r + 1)^2.
u128 rounded_root(u128 n) {
  auto r = static_cast<u128>(sqrtl(static_cast<long double>(n)));
  while (r * r > n) --r;
  while ((r + 1) * (r + 1) <= n) ++r;
  return 4 * n >= (2 * r + 1) * (2 * r + 1) ? r + 1 : r;
}

template <typename Q>
void expect_correctly_rounded(Q x, fxtest::MaxError& lsb_error) {
  const auto got = fx::sqrt(x).raw();
  if (x.raw() <= 0) {
    ASSERT_EQ(got, 0) << x.raw();
    return;
  }
  const u128 n = static_cast<u128>(x.raw()) << Q::frac_bits;
  ASSERT_EQ(static_cast<u128>(got), rounded_root(n)) << "sqrt of raw " << x.raw() << " in Q" << Q::frac_bits;
  const long double exact = sqrtl(static_cast<long double>(n));
  lsb_error.add(fabsl(static_cast<long double>(got) - exact), fxtest::value(x));
}

template <typename Q>
void sweep_all(const char* name) {
  fxtest::MaxError lsb(name);
  for (int32_t raw = INT16_MIN; raw <= INT16_MAX; ++raw)
    expect_correctly_rounded(Q::from_raw(static_cast<int16_t>(raw)), lsb);
  lsb.print(0.5L);
  EXPECT_LE(lsb.max(), 0.5L);
}

template <typename Q>
void sweep_int32(const char* name, uint64_t seed) {
  fxtest::MaxError lsb(name);
  for (int32_t raw : fxtest::edge_raws<int32_t>()) expect_correctly_rounded(Q::from_raw(raw), lsb);
  fxtest::RawSource<int32_t> source(seed);
  for (int i = 0; i < 200000; ++i) expect_correctly_rounded(Q::from_raw(source.next()), lsb);
  // Radicands n = raw * 2^F just either side of r^2 and of (r + 1/2)^2, where rounding flips.
  for (int64_t r = 1; r < (int64_t{1} << 31); r = r * 9 / 8 + 1) {
    for (const int64_t n : {r * r, r * r + r}) {
      for (int64_t d = -2; d <= 2; ++d) {
        const int64_t raw = ((n >> Q::frac_bits) + d);
        if (raw >= 0 && raw <= INT32_MAX) expect_correctly_rounded(Q::from_raw(static_cast<int32_t>(raw)), lsb);
      }
    }
  }
  lsb.print(0.5L);
  EXPECT_LE(lsb.max(), 0.5L);
}

TEST(Sqrt, CorrectlyRoundedOnEveryInt16Value) {
  sweep_all<fx::Q<8, int16_t>>("Q<8, int16_t> in lsb");
  sweep_all<fx::Q<0, int16_t>>("Q<0, int16_t> in lsb");
  sweep_all<fx::Q<15, int16_t>>("Q<15, int16_t> in lsb");
}

TEST(Sqrt, CorrectlyRoundedOnInt32Formats) {
  sweep_int32<fx::Q<0>>("Q<0> in lsb", 1);
  sweep_int32<fx::Q<1>>("Q<1> in lsb", 2);
  sweep_int32<fx::Q<16>>("Q<16> in lsb", 3);
  sweep_int32<fx::Q<30>>("Q<30> in lsb", 4);
  sweep_int32<fx::Q<31>>("Q<31> in lsb", 5);
}

TEST(Sqrt, KnownValuesAndLimits) {
  static_assert(fx::sqrt(fx::Q<16>(2.25)) == fx::Q<16>(1.5));  // usable in constant expressions
  EXPECT_EQ(fx::sqrt(fx::Q<16>(4.0)), fx::Q<16>(2.0));
  EXPECT_EQ(fx::sqrt(fx::Q<16>(2.0)), fx::Q<16>(1.4142135623730951));
  EXPECT_EQ(fx::sqrt(fx::Q<16>(-1.0)), fx::Q<16>());
  EXPECT_EQ(fx::sqrt(fx::Q<16>::min()), fx::Q<16>());
  EXPECT_EQ(fx::sqrt(fx::Q<31>::max()), fx::Q<31>::max());  // sqrt of just below 1 stays below 1
  EXPECT_EQ(fx::sqrt(fx::Q<0>::max()), fx::Q<0>::from_raw(46341));
}

// The integer root under every Q root: exact at both edges of every root's run of inputs, r^2
// and (r + 1)^2 - 1, for every r of the 32-bit range, and on every input below 2^20. (The whole
// 2^32 range was checked once by hand: 25 s of an optimised build.)
TEST(Sqrt, IntegerRootExactAtEveryEdge) {
  uint64_t checked = 0;
  const auto expect_root = [&checked](uint32_t n, uint32_t root) {
    const auto r = fx::detail::isqrt(n);
    ASSERT_EQ(r.root, root) << "n = " << n;
    ASSERT_EQ(r.remainder, n - root * root) << "n = " << n;
    ++checked;
  };
  for (uint32_t r = 0; r < 65536; ++r) {
    expect_root(r * r, r);
    expect_root(r == 65535 ? 0xFFFFFFFFu : (r + 1) * (r + 1) - 1, r);
  }
  for (uint32_t n = 0, r = 0; n < (1u << 20); ++n) {
    if ((r + 1) * (r + 1) == n) ++r;
    expect_root(n, r);
  }
  std::printf("  integer root exact on %llu inputs\n", static_cast<unsigned long long>(checked));
}

}  // namespace
