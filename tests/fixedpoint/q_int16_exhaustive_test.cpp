// Q<8, int16_t> checked on its whole domain against the exact reference: every pair of raws
// for + - * and add_sat, sub_sat, mul_sat (2^32 pairs each); every value for the unary
// operations and shifts; every dividend against a set of divisors that covers the
// saturating ones (all |b| <= 64, the extremes, and 256 random others).
//
// 2^32 pairs a function is only affordable vectorised, so the pair sweep is compiled twice,
// for AVX2 and for the x86-64 baseline, picked at run time, and split over the CPU's threads.
#include <gtest/gtest.h>
#include <fixedpoint/q.hpp>

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "reference.hpp"

namespace {

using Q8 = fx::Q<8, int16_t>;
using fxtest::i128;

constexpr int32_t kRawMin = INT16_MIN;
constexpr int32_t kRawMax = INT16_MAX;

// Nonzero bits wherever an operation disagreed with the reference somewhere in a row.
struct RowDiff {
  int32_t add, sub, mul, add_sat, sub_sat, mul_sat;
};

int32_t clamp16(int32_t v) { return std::clamp(v, kRawMin, kRawMax); }

// Reference, in plain int32 so that it vectorises like the code under test: products of two
// int16 fit, and (p + 128) >> 8 is floor(p / 256 + 1/2).
[[gnu::always_inline]] inline RowDiff diff_row(int16_t a) {
  const Q8 qa = Q8::from_raw(a);
  RowDiff d{};
  for (int32_t bi = kRawMin; bi <= kRawMax; ++bi) {
    const auto b = static_cast<int16_t>(bi);
    const Q8 qb = Q8::from_raw(b);
    const int32_t sum = a + b, difference = a - b, product = (a * b + 128) >> 8;
    d.add |= (qa + qb).raw() ^ static_cast<int16_t>(sum);
    d.sub |= (qa - qb).raw() ^ static_cast<int16_t>(difference);
    d.mul |= (qa * qb).raw() ^ static_cast<int16_t>(product);
    d.add_sat |= add_sat(qa, qb).raw() ^ clamp16(sum);
    d.sub_sat |= sub_sat(qa, qb).raw() ^ clamp16(difference);
    d.mul_sat |= mul_sat(qa, qb).raw() ^ clamp16(product);
  }
  return d;
}

[[gnu::target("avx2")]] RowDiff diff_row_avx2(int16_t a) { return diff_row(a); }
RowDiff diff_row_baseline(int16_t a) { return diff_row(a); }

TEST(QInt16Exhaustive, AllPairsAddSubMulAndSaturating) {
  const bool avx2 = __builtin_cpu_supports("avx2");
  const unsigned workers = std::max(1u, std::thread::hardware_concurrency());
  std::vector<RowDiff> rows(65536);
  std::atomic<int32_t> next{kRawMin};
  std::vector<std::thread> pool;
  for (unsigned w = 0; w < workers; ++w) {
    pool.emplace_back([&] {
      for (int32_t a = next++; a <= kRawMax; a = next++) {
        const auto a16 = static_cast<int16_t>(a);
        rows[static_cast<size_t>(a - kRawMin)] = avx2 ? diff_row_avx2(a16) : diff_row_baseline(a16);
      }
    });
  }
  for (auto& t : pool) t.join();

  int failing_rows = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    const RowDiff& d = rows[i];
    if ((d.add | d.sub | d.mul | d.add_sat | d.sub_sat | d.mul_sat) == 0) continue;
    if (++failing_rows > 5) break;
    ADD_FAILURE() << "a = " << (static_cast<int32_t>(i) + kRawMin) << ": add " << d.add << " sub " << d.sub << " mul "
                  << d.mul << " add_sat " << d.add_sat << " sub_sat " << d.sub_sat << " mul_sat " << d.mul_sat
                  << " (nonzero = some b differs)";
  }
}

TEST(QInt16Exhaustive, UnaryOperationsOnEveryValue) {
  for (int32_t a = kRawMin; a <= kRawMax; ++a) {
    const Q8 q = Q8::from_raw(static_cast<int16_t>(a));
    ASSERT_EQ((-q).raw(), fxtest::wrapped<int16_t>(-a)) << a;
    ASSERT_EQ(neg_sat(q).raw(), fxtest::saturated<int16_t>(-a)) << a;
    ASSERT_EQ(abs_sat(q).raw(), fxtest::saturated<int16_t>(a < 0 ? -a : a)) << a;
    ASSERT_EQ(q.to_int(), static_cast<int32_t>(fxtest::round_half_up_shift(a, 8))) << a;
  }
}

TEST(QInt16Exhaustive, ShiftsOfEveryValueByEveryCount) {
  for (int32_t a = kRawMin; a <= kRawMax; ++a) {
    const Q8 q = Q8::from_raw(static_cast<int16_t>(a));
    for (int n = -2; n <= 18; ++n) {
      const int k = std::clamp(n, 0, 16);
      const i128 shifted = i128{a} * (i128{1} << k);
      ASSERT_EQ((q << n).raw(), fxtest::wrapped<int16_t>(shifted)) << a << " << " << n;
      ASSERT_EQ(shl_sat(q, n).raw(), fxtest::saturated<int16_t>(shifted)) << a << " << " << n;
      ASSERT_EQ((q >> n).raw(), static_cast<int16_t>(fxtest::floor_div(a, i128{1} << std::min(k, 15))))
          << a << " >> " << n;
    }
  }
}

TEST(QInt16Exhaustive, TimesIntegerForEveryValue) {
  const int32_t factors[] = {0, 1, -1, 2, -2, 3, -7, 100, -129, 255, 256, 32767, -32768, 65537, INT32_MAX, INT32_MIN};
  for (int32_t a = kRawMin; a <= kRawMax; ++a) {
    const Q8 q = Q8::from_raw(static_cast<int16_t>(a));
    for (int32_t n : factors) {
      const i128 exact = i128{a} * n;
      ASSERT_EQ((q * n).raw(), fxtest::wrapped<int16_t>(exact)) << a << " * " << n;
      ASSERT_EQ((n * q).raw(), fxtest::wrapped<int16_t>(exact)) << n << " * " << a;
      ASSERT_EQ(mul_sat(q, n).raw(), fxtest::saturated<int16_t>(exact)) << a << " * " << n;
    }
  }
}

TEST(QInt16Exhaustive, DivisionOfEveryValueBySaturatingAndOrdinaryDivisors) {
  std::vector<int32_t> divisors;
  for (int32_t b = -64; b <= 64; ++b) divisors.push_back(b);
  for (int32_t b : {kRawMin, kRawMin + 1, kRawMax, kRawMax - 1, 256, -256, 255, 257}) divisors.push_back(b);
  fxtest::RawSource<int16_t> source(16);
  for (int i = 0; i < 256; ++i) divisors.push_back(source.next());

  for (int32_t a = kRawMin; a <= kRawMax; ++a) {
    const Q8 qa = Q8::from_raw(static_cast<int16_t>(a));
    for (int32_t b : divisors) {
      const Q8 qb = Q8::from_raw(static_cast<int16_t>(b));
      const int16_t expected = b == 0 ? (a > 0   ? kRawMax
                                         : a < 0 ? kRawMin
                                                 : 0)
                                      : fxtest::saturated<int16_t>(fxtest::round_half_up_div(i128{a} << 8, b));
      ASSERT_EQ((qa / qb).raw(), expected) << a << " / " << b;
      ASSERT_EQ(div_sat(qa, qb).raw(), expected) << a << " / " << b;
    }
  }
}

}  // namespace
