// Square root of a Q number in the same format, correctly rounded: the result is the exact
// square root rounded to the nearest lsb (max error 0.5 lsb; ties cannot occur). Negative
// inputs give 0.
#pragma once

#include <fixedpoint/detail/raw.hpp>
#include <fixedpoint/q.hpp>

namespace fx {
namespace detail {

template <typename U>
struct RootAndRemainder {
  U root, remainder;  // root = floor(sqrt(n)), remainder = n - root^2
};

// One result bit per step, the schoolbook method in base 2: no multiply, no divide.
constexpr RootAndRemainder<uint32_t> isqrt(uint32_t n) {
  uint32_t root = 0;
  uint32_t bit = 1u << 30;
  while (bit > n) bit >>= 2;
  while (bit != 0) {
    if (n >= root + bit) {
      n -= root + bit;
      root = (root >> 1) + bit;
    } else {
      root >>= 1;
    }
    bit >>= 2;
  }
  return {root, n};
}

constexpr int bit_length(uint32_t v) {
  int n = 0;
  for (int step = 16; step > 0; step >>= 1) {
    if ((v >> step) != 0) {
      v >>= step;
      n += step;
    }
  }
  return n + static_cast<int>(v);
}

// For n < 2^62 (what Q<F, int32_t> needs). The schoolbook method on 64 bits would cost ~600
// instructions on RV32, so: the top 32 significant bits m = n / 4^s give the root's top 16
// bits m0 = isqrt(m) in 32-bit arithmetic, one Newton step r = m0 2^s + (n - m0^2 4^s) / (m0
// 2^(s+1)) adds the rest with a single 32-bit divide, and a check of r^2 against n corrects
// the last unit. (The Newton step from below overshoots by less than 2^s / (2 m0) <= 1/2 and
// the truncations undershoot by less than one, so one correction step each way suffices.)
constexpr RootAndRemainder<uint64_t> isqrt(uint64_t n) {
  const uint32_t high = static_cast<uint32_t>(n >> 32);
  if (high == 0) {
    const auto r = isqrt(static_cast<uint32_t>(n));
    return {r.root, r.remainder};
  }
  const int s = (bit_length(high) + 1) / 2;  // 1 <= s <= 15 for n < 2^62
  const uint32_t m = static_cast<uint32_t>(n >> (2 * s));
  const uint64_t low = n - (static_cast<uint64_t>(m) << (2 * s));
  const auto [m0, rem0] = isqrt(m);  // m in [2^30, 2^32): m0 in [2^15, 2^16), rem0 <= 2 m0
  // (n - (m0 2^s)^2) / (2 m0 2^s) = (rem0 2^s + low / 2^s) / (2 m0); halved to fit 32 bits.
  const uint32_t numerator = (rem0 << (s - 1)) + static_cast<uint32_t>(low >> (s + 1));
  uint64_t root = (static_cast<uint64_t>(m0) << s) + numerator / m0;
  uint64_t square = root * root;
  if (square > n) {
    --root;
    square = root * root;
  } else if (n - square > 2 * root) {  // (root + 1)^2 = square + 2 root + 1 <= n
    square += 2 * root + 1;
    ++root;
  }
  return {root, n - square};
}

}  // namespace detail

template <int F, typename R>
constexpr Q<F, R> sqrt(Q<F, R> x) {
  using U = typename detail::RawTraits<R>::UProduct;
  if (x.raw() <= 0) return Q<F, R>{};
  // sqrt(raw / 2^F) * 2^F = sqrt(raw * 2^F): the integer root of a number twice as wide.
  const auto [root, remainder] = detail::isqrt(static_cast<U>(x.raw()) << F);
  // n lies between root^2 and (root + 1)^2 and is nearer the upper one when n - root^2
  // exceeds root + 1/2; both sides are integers.
  return Q<F, R>::from_raw(static_cast<R>(remainder > root ? root + 1 : root));
}

}  // namespace fx
