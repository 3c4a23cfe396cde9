// Integer division and bit length on 32-bit words, for RV32IM, which divides 32 by 32 bits only:
// a 64-bit quotient through libgcc's __udivdi3 costs the Q<F, int32_t> division most of its
// instructions, where the quotient that does not saturate fits 32 bits.
#pragma once

#include <stdint.h>

namespace fx::detail {

// The number of significant bits of v (0 for 0): a binary search, five steps.
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

struct QuotientAndRemainder {
  uint32_t quotient, remainder;
};

// n / d for a 64-bit n whose high word is below d (so the quotient fits 32 bits), in 32-bit
// divisions: the schoolbook long division in base 2^16 with d normalised to its top bit, where
// each digit's estimate from the top halves is at most two too high (Knuth, TAOCP vol. 2,
// 4.3.1, algorithm D; the two-digit form is Hacker's Delight 2nd ed., figure 9-3, "divlu").
constexpr QuotientAndRemainder divide_below(uint64_t n, uint32_t d) {
  constexpr uint32_t kBase = 1u << 16;
  const int s = 32 - bit_length(d);  // d << s has its top bit set
  const uint32_t v = d << s;
  const uint32_t v1 = v >> 16, v0 = v & 0xFFFFu;
  const uint32_t high = static_cast<uint32_t>(n >> 32), low = static_cast<uint32_t>(n);
  // n << s: its top 32 bits (below v, since high < d) and the two 16-bit digits under them.
  const uint32_t top = s == 0 ? high : (high << s) | (low >> (32 - s));
  const uint32_t rest = low << s;
  const uint32_t u1 = rest >> 16, u0 = rest & 0xFFFFu;

  // One digit of the quotient from the 48 bits (top, u) with top < v: estimated from v's top
  // digit, then corrected down while it is too high.
  const auto digit = [v, v1, v0](uint32_t upper, uint32_t u, uint32_t& remainder) {
    uint32_t q = upper / v1;
    uint32_t r = upper - q * v1;
    while (q >= kBase || q * v0 > ((r << 16) | u)) {
      --q;
      r += v1;
      if (r >= kBase) break;
    }
    remainder = upper * kBase + u - q * v;  // modulo 2^32, exact since it is below v
    return q;
  };
  uint32_t r1 = 0, r0 = 0;
  const uint32_t q1 = digit(top, u1, r1);
  const uint32_t q0 = digit(r1, u0, r0);
  return {(q1 << 16) | q0, r0 >> s};
}

}  // namespace fx::detail
