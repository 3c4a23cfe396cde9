// Every entry point of the library on a fixed stream of operands, folded into one checksum.
// The host test (cross_check_test.cpp, clang on x86-64) and the devboard program
// (cross_check_rv32.cpp, GCC for RV32IM) must both arrive at kExpected: the same source gives
// bit-identical results on the two, which is what lets host tests and the simulator stand in
// for the flight computer. Freestanding, so that the devboard can build it.
#pragma once

#include <stdint.h>
#include <fixedpoint/fixedpoint.hpp>

namespace fxcheck {

// Recorded from the host run; a change means some result changed on that side.
inline constexpr uint32_t kExpected = 0x6DB17AF3;
inline constexpr uint32_t kSamples = 4000;

// FNV-1a over the raw bits.
struct Checksum {
  uint32_t h = 2166136261u;
  void add(uint32_t v) {
    for (int i = 0; i < 4; ++i) {
      h = (h ^ ((v >> (8 * i)) & 0xFFu)) * 16777619u;
    }
  }
  template <typename Q>
  void add(Q q) {
    add(static_cast<uint32_t>(static_cast<int32_t>(q.raw())));
  }
};

template <typename Q>
void arithmetic(Checksum& c, Q a, Q b, int32_t n) {
  const int shift = static_cast<int>(static_cast<uint32_t>(n) % 20u) - 2;
  c.add(a + b);
  c.add(a - b);
  c.add(a * b);
  c.add(a / b);
  c.add(-a);
  c.add(add_sat(a, b));
  c.add(sub_sat(a, b));
  c.add(mul_sat(a, b));
  c.add(neg_sat(a));
  c.add(abs_sat(a));
  c.add(a * n);
  c.add(mul_sat(a, n));
  c.add(a << shift);
  c.add(a >> shift);
  c.add(shl_sat(a, shift));
  c.add(Q::from_int(n >> 12));
  c.add(static_cast<uint32_t>(a.to_int()));
  c.add(static_cast<uint32_t>((a < b) | (a <= b) << 1 | (a == b) << 2 | (a != b) << 3 | (a > b) << 4 | (a >= b) << 5));
}

template <typename To, typename From>
void conversions(Checksum& c, From a) {
  c.add(fx::convert<To>(a));
  c.add(fx::convert_sat<To>(a));
}

inline uint32_t checksum() {
  using Q16 = fx::Q<16>;
  using Q30 = fx::Q<30>;
  using Q12s = fx::Q<12, int16_t>;
  Checksum c;
  uint32_t lcg = 12345;
  const auto next = [&lcg] {
    lcg = lcg * 1664525u + 1013904223u;
    // Mix magnitudes: shift a random amount so small values are as common as large ones.
    return static_cast<int32_t>(lcg) >> ((lcg >> 7) % 24u);
  };
  constexpr fx::Iir1Coefficients<Q30> c1{Q30(0.0863640270), Q30(0.0863640270), Q30(-0.8272719460)};
  constexpr fx::Iir2Coefficients<Q30> c2{Q30(0.0078202080), Q30(0.0156404161), Q30(0.0078202080), Q30(-1.7347257688),
                                         Q30(0.7660066009)};
  fx::Iir1State<Q16> s1;
  fx::Iir2State<Q16> s2;
  for (uint32_t i = 0; i < kSamples; ++i) {
    const int32_t ra = next(), rb = next(), n = next();
    const Q16 a = Q16::from_raw(ra), b = Q16::from_raw(rb);
    const Q12s sa = Q12s::from_raw(static_cast<int16_t>(ra)), sb = Q12s::from_raw(static_cast<int16_t>(rb));
    arithmetic(c, a, b, n);
    arithmetic(c, sa, sb, n);
    conversions<Q12s>(c, a);
    conversions<Q30>(c, a);
    conversions<fx::Q<0>>(c, a);
    conversions<Q16>(c, sa);
    conversions<fx::Q<15, int16_t>>(c, sa);
    const auto acc = fx::mul_wide(Q30::from_raw(rb), a) - fx::mul_wide(Q30::from_raw(ra), b);
    c.add(fx::narrow<Q16>(acc));
    c.add(fx::narrow_sat<Q16>(acc));
    c.add(fx::narrow_sat<Q12s>(fx::mul_wide(sa, sb) + fx::mul_wide(sb, sb)));
    c.add(fx::sqrt(a));
    c.add(fx::sqrt(sa));
    c.add(fx::atan2(a, b));
    c.add(fx::atan2<fx::Q<13, int16_t>>(sa, sb));
    c.add(fx::sin(a));
    c.add(fx::cos(a));
    c.add(fx::sin<fx::Q<14, int16_t>>(sa));
    c.add(fx::cos<fx::Q<14, int16_t>>(sb));
    const Q16 x = Q16::from_raw(ra >> 8);  // filter input within ±128, like a sensor signal
    c.add(fx::iir1_step(s1, c1, x));
    c.add(fx::iir2_step(s2, c2, x));
  }
  return c.h;
}

}  // namespace fxcheck
