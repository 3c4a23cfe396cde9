// Integer facts and helpers behind Q and Wide. The freestanding build has no <type_traits> or
// <limits>, so the few we need are spelt out here, for the storage types we support only.
//
// Everything that could overflow a signed type goes through an unsigned or a wider type, so
// no operation of the library has undefined behaviour, whatever the operands.
#pragma once

#include <stdint.h>

#include <fixedpoint/design_constants.hpp>

namespace fx::detail {

template <typename A, typename B>
inline constexpr bool is_same = false;
template <typename A>
inline constexpr bool is_same<A, A> = true;

// Storage a Q may use. `Product` holds the exact product of two raws, `UProduct` its magnitude
// and a little more (division needs 2|n| + |d|), `Word` is an unsigned type at least as wide as
// int, so wrapping sums never pass through a promotion to signed int.
template <typename Raw>
struct RawTraits;  // not defined: any other storage type is a compile error

template <>
struct RawTraits<int16_t> {
  static constexpr int bits = 16;
  static constexpr int16_t min = INT16_MIN;
  static constexpr int16_t max = INT16_MAX;
  using Product = int32_t;
  using UProduct = uint32_t;
  using Word = uint32_t;
};

template <>
struct RawTraits<int32_t> {
  static constexpr int bits = 32;
  static constexpr int32_t min = INT32_MIN;
  static constexpr int32_t max = INT32_MAX;
  using Product = int64_t;
  using UProduct = uint64_t;
  using Word = uint32_t;
};

template <typename Raw>
concept Storage = requires {
  RawTraits<Raw>::bits;
};

template <typename V>
struct UnsignedOf;
template <>
struct UnsignedOf<int32_t> {
  using type = uint32_t;
};
template <>
struct UnsignedOf<int64_t> {
  using type = uint64_t;
};

// Two's-complement wrap into Raw (C++20 defines narrowing conversions as modular).
//
// On RV32 a 64-bit value wrapped to 32 bits goes on as a plain register: GCC (12) otherwise keeps
// tracking it as the 64-bit value it came from, and a later widening product of it (mul_wide of a
// narrowed sum, the filters' and estimator's usual step) is lowered as a 64 x 32 one, mulhu and a
// multiply per sign to correct it, where mul + mulh is the whole product. The empty asm statement
// only hides where the register came from; the value is the same, and constant evaluation and
// other targets take the plain conversion.
template <typename Raw, typename V>
constexpr Raw wrap(V v) {
#if defined(__riscv) && __riscv_xlen == 32
  if constexpr (sizeof(V) == 8 && sizeof(Raw) == 4) {
    if (!__builtin_is_constant_evaluated()) {
      Raw r = static_cast<Raw>(v);
      asm("" : "+r"(r));
      return r;
    }
  }
#endif
  return static_cast<Raw>(v);
}

// Clamp a signed value into Raw's range.
template <typename Raw, typename V>
constexpr Raw saturate(V v) {
  if (v < RawTraits<Raw>::min) return RawTraits<Raw>::min;
  if (v > RawTraits<Raw>::max) return RawTraits<Raw>::max;
  return static_cast<Raw>(v);
}

// v * 2^s, wrapping, for 0 <= s < bits(V). Through unsigned: shifting a negative value left is
// well defined in C++20, but the sanitizers of older compilers still flag it.
template <typename V>
constexpr V shl_wrap(V v, int s) {
  using U = typename UnsignedOf<V>::type;
  return static_cast<V>(static_cast<U>(v) << s);
}

// v / 2^s rounded half up (floor(v / 2^s + 1/2)), for 0 <= s < bits(V). Written as the floor
// plus the first dropped bit rather than (v + half) >> s: it cannot overflow, and on RV32 the
// bit costs two instructions where the 64-bit add of the half costs four.
template <typename V>
constexpr V round_shr(V v, int s) {
  if (s <= 0) return v;
  return static_cast<V>((v >> s) + ((v >> (s - 1)) & 1));
}

// Magnitude of a signed value as unsigned (|INT_MIN| included).
template <typename U, typename V>
constexpr U magnitude(V v) {
  return v < 0 ? static_cast<U>(U{0} - static_cast<U>(v)) : static_cast<U>(v);
}

using fx::pow2;

// Never defined: reaching a call to one of these while evaluating a constant is what turns a
// bad constant into a compile error, and its name is what the compiler prints.
void q_constant_is_out_of_range();
void q_constant_is_not_a_number();

// round(v * 2^frac) half up, for constants; a value the format cannot hold does not compile.
template <typename Raw>
consteval Raw constant_to_raw(double v, int frac) {
  if (v != v) q_constant_is_not_a_number();
  const double scaled = v * pow2(frac);
  if (!(scaled > -pow2(62) && scaled < pow2(62))) q_constant_is_out_of_range();
  int64_t floor = static_cast<int64_t>(scaled);  // truncates toward zero
  if (static_cast<double>(floor) > scaled) --floor;
  // scaled - floor is exact: both are within 2^62 and floor is scaled's integer part.
  const int64_t rounded = (scaled - static_cast<double>(floor) >= 0.5) ? floor + 1 : floor;
  if (rounded < RawTraits<Raw>::min || rounded > RawTraits<Raw>::max) q_constant_is_out_of_range();
  return static_cast<Raw>(rounded);
}

}  // namespace fx::detail
