// A number of the chain's in decimal units: x in units of 10^-Digits (an angle in rad with
// Digits 4 is in 1e-4 rad), rounded to the nearest integer, halves up, saturated to int32.
// Written once for every number policy (Q formats in flight, double and float on the host), so
// a value reads the same whoever converts it: the observables' readers (by their table rows'
// scales, qr/core/observable_readers.hpp) and the chain's decimal read-outs for the replay, the
// chain checksum and tests (decimal_readouts.hpp).
#pragma once

#include <stdint.h>

#include <fixedpoint/wide.hpp>

namespace qr::chain {

constexpr int32_t power_of_ten(int digits) {
  int32_t p = 1;
  for (int i = 0; i < digits; ++i) p *= 10;
  return p;
}

// 10^Digits in the policy's whole-number type (Q<0> in flight): the factor of one exact product
// (a constant: Q<0>'s constructor is compile-time only).
template <class Num, int Digits>
inline constexpr auto kPowerOfTen = typename Num::template Fixed<0>(power_of_ten(Digits));

template <int Digits, class Num, class T>
constexpr int32_t in_decimal_units(T x) {
  static_assert(Digits >= 0 && Digits <= 6, "10^Digits must fit Q<0>'s 31 bits with room");
  return Num::round_to_int(fx::mul_wide(x, kPowerOfTen<Num, Digits>));
}

}  // namespace qr::chain
