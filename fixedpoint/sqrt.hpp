// Square root of a Q number in the same format, correctly rounded: the result is the exact
// square root rounded to the nearest lsb (max error 0.5 lsb; ties cannot occur). Negative
// inputs give 0.
#pragma once

#include <fixedpoint/detail/divide.hpp>
#include <fixedpoint/detail/raw.hpp>
#include <fixedpoint/q.hpp>

namespace fx {
namespace detail {

template <typename U>
struct RootAndRemainder {
  U root, remainder;  // root = floor(sqrt(n)), remainder = n - root^2
};

// Seeds for a root from above: of[k] = ceil(sqrt((k + 1) 2^Shift)), at or above the root of every
// n < (k + 1) 2^Shift, so a caller indexes the table with n >> Shift. In T to keep the table small.
template <typename T, uint32_t Count, int Shift>
struct RootSeeds {
  T of[Count];
};
template <typename T, uint32_t Count, int Shift>
constexpr RootSeeds<T, Count, Shift> make_root_seeds() {
  RootSeeds<T, Count, Shift> t{};
  for (uint32_t k = 0; k < Count; ++k) {
    uint32_t r = 0;
    while (r * r < (k + 1) << Shift) ++r;
    t.of[k] = static_cast<T>(r);
  }
  return t;
}
template <typename T, uint32_t Count, int Shift>
inline constexpr RootSeeds<T, Count, Shift> kRootSeeds = make_root_seeds<T, Count, Shift>();

// floor(sqrt(n)) for n > 0 from a seed x at or above it: Steps Newton (Heron) steps with one 32-bit
// division each, and a check that takes back the last units (as many steps as the seed's
// closeness needs: two from 25 % high, one from 1 %). From above, integer Newton never passes the
// root: floor((x + floor(n / x)) / 2) = floor((x + n / x) / 2) >= floor(sqrt(n)) (AM-GM). x > n / x
// is x^2 > n without x^2 overflowing at the top of the range.
template <int Steps>
constexpr uint32_t root_from_above(uint32_t n, uint32_t x) {
  for (int step = 0; step < Steps; ++step) x = (x + n / x) >> 1;
  while (x > n / x) --x;
  return x;
}

// floor(sqrt(n)) and what remains, for every 32-bit n (the schoolbook method, one result bit
// per step, costs RV32IM about 110 instructions): a seed from n's top 5-6 bits, at most 25 % high
// below n = 64 and 3 % high above, finished from above. Exact for every n (checked once by hand
// over all 2^32; tests/fixedpoint/sqrt_test.cpp checks every root's edges).
[[gnu::noinline]] constexpr RootAndRemainder<uint32_t> isqrt(uint32_t n) {
  if (n == 0) return {0, 0};
  // n = m 4^h + rest with m in [16, 64), or m = n below 64.
  const int length = bit_length(n);
  const int h = length > 6 ? (length - 5) >> 1 : 0;
  const uint32_t m = n >> (2 * h);
  // ceil(16 sqrt(m + 1)) in 1/16 units, scaled by 2^h.
  const uint32_t x = root_from_above<2>(n, ((static_cast<uint32_t>(kRootSeeds<uint8_t, 64, 8>.of[m]) << h) >> 4) + 1);
  return {x, n - x * x};
}

// floor(sqrt(n)) for n < 2^62 (what Q<F, int32_t> needs). The schoolbook method on 64 bits
// would cost ~600 instructions on RV32, so: the top 32 significant bits m = n / 4^s give the
// root's top 16 bits m0 = isqrt(m) in 32-bit arithmetic, one Newton step r = m0 2^s + (n - m0^2
// 4^s) / (m0 2^(s+1)) adds the rest with a single 32-bit divide, and a check of r^2 against n
// takes back the one unit it may be high. Why one unit down and never up: the exact step
// r* = m0 2^s + (rem0 2^(s-1) + low / 2^(s+1)) / m0 is a tangent step, so r* >= sqrt(n), and it
// overshoots by (sqrt(n) - m0 2^s)^2 / (2 m0 2^s) < 4^s / (2 m0 2^s) <= 1/2 (m0 >= 2^15,
// s <= 15); the code's two truncations compose to one, floor(floor(x) / m0) = floor(x / m0), so
// root = floor(r*), which lies in [floor(sqrt(n)), floor(sqrt(n)) + 1]. Everything but the check
// is 32-bit: the root is below 2^31 and the bits below m, fewer than 2^30.
constexpr uint32_t root_below_2_pow_62(uint64_t n) {
  const uint32_t high = static_cast<uint32_t>(n >> 32);
  if (high == 0) return isqrt(static_cast<uint32_t>(n)).root;
  const int s = (bit_length(high) + 1) / 2;  // 1 <= s <= 15 for n < 2^62
  const uint32_t m = static_cast<uint32_t>(n >> (2 * s));
  const uint32_t low = static_cast<uint32_t>(n) & ((1u << (2 * s)) - 1u);
  const auto [m0, rem0] = isqrt(m);  // m in [2^30, 2^32): m0 in [2^15, 2^16), rem0 <= 2 m0
  // (n - (m0 2^s)^2) / (2 m0 2^s) = (rem0 2^s + low / 2^s) / (2 m0); halved to fit 32 bits.
  const uint32_t numerator = (rem0 << (s - 1)) + (low >> (s + 1));
  uint32_t root = (m0 << s) + numerator / m0;
  if (static_cast<uint64_t>(root) * root > n) --root;
  return root;
}

// floor(sqrt(n)) and what remains, for n < 2^62. Out of line: inlined into each caller it costs
// the QR's image kilobytes, for the few instructions of a call.
[[gnu::noinline]] constexpr RootAndRemainder<uint64_t> isqrt(uint64_t n) {
  const uint32_t root = root_below_2_pow_62(n);
  return {root, n - static_cast<uint64_t>(root) * root};
}

}  // namespace detail

template <int F, typename R>
constexpr Q<F, R> sqrt(Q<F, R> x) {
  using U = typename detail::RawTraits<R>::UProduct;
  if (x.raw() <= 0) return Q<F, R>{};
  if constexpr (sizeof(R) == 4 && F <= 29) {
    // sqrt(raw / 2^F) * 2^F = sqrt(raw 2^F), rounded: with k = floor(sqrt(4 raw 2^F)) =
    // floor(2 sqrt(raw 2^F)), the rounded root is (k + 1) / 2 (the root's first fractional bit
    // decides; ties cannot occur), and 4 raw 2^F < 2^62 keeps the whole root in 32 bits.
    const uint32_t k = detail::root_below_2_pow_62(static_cast<uint64_t>(x.raw()) << (F + 2));
    return Q<F, R>::from_raw(static_cast<R>((k + 1) >> 1));
  } else {
    // sqrt(raw / 2^F) * 2^F = sqrt(raw * 2^F): the integer root of a number twice as wide.
    const auto [root, remainder] = detail::isqrt(static_cast<U>(x.raw()) << F);
    // n lies between root^2 and (root + 1)^2 and is nearer the upper one when n - root^2
    // exceeds root + 1/2; both sides are integers.
    return Q<F, R>::from_raw(static_cast<R>(remainder > root ? root + 1 : root));
  }
}

}  // namespace fx
