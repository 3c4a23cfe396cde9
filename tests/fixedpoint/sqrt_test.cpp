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

// The wide root under the Q<F, int32_t> roots: exact at both edges of a root's run of inputs, r^2
// and (r + 1)^2 - 1, for every r below 2^20, every r around a power of two, and 2^20 spread over
// the rest of its range (roots below 2^31: inputs below 2^62).
TEST(Sqrt, WideRootExactAtTheEdges) {
  uint64_t checked = 0;
  const auto expect_edges = [&checked](uint64_t r) {
    const uint64_t square = r * r, next_square = (r + 1) * (r + 1);
    ASSERT_EQ(fx::detail::root_below_2_pow_62(square), r) << "n = " << square;
    if (next_square - 1 < (uint64_t{1} << 62)) {
      ASSERT_EQ(fx::detail::root_below_2_pow_62(next_square - 1), r) << "n = " << next_square - 1;
      const auto wide = fx::detail::isqrt(next_square - 1);
      ASSERT_EQ(wide.root, r);
      ASSERT_EQ(wide.remainder, 2 * r);
    }
    checked += 2;
  };
  for (uint64_t r = 0; r < (1u << 20); ++r) expect_edges(r);
  for (int b = 20; b <= 31; ++b) {
    for (uint64_t d = 0; d < 64; ++d) {
      expect_edges((uint64_t{1} << b) - 1 - d);
      if (b < 31) expect_edges((uint64_t{1} << b) + d);
    }
  }
  for (uint64_t r = 1u << 20, step = ((uint64_t{1} << 31) - r) >> 20; r < (uint64_t{1} << 31); r += step + (r & 7)) {
    expect_edges(r);
  }
  std::printf("  wide root exact on %llu inputs\n", static_cast<unsigned long long>(checked));
}

// Between the edges: random n of every width, against the root's definition r^2 <= n < (r + 1)^2.
TEST(Sqrt, WideRootExactOnRandomInputsOfEveryWidth) {
  uint64_t state = 0x9E3779B97F4A7C15u;
  for (int i = 0; i < 1 << 20; ++i) {
    state = state * 6364136223846793005u + 1442695040888963407u;
    const int width = 1 + i % 62;
    const uint64_t n = (state >> 2) >> (62 - width);
    const uint64_t r = fx::detail::root_below_2_pow_62(n);
    ASSERT_LE(r * r, n) << "n = " << n;
    ASSERT_GT((r + 1) * (r + 1), n) << "n = " << n;
  }
}

}  // namespace
