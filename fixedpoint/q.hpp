// Q-format fixed-point numbers: a signed integer `raw` standing for raw / 2^Frac.
//
// Rules, the same for every operation in the library (fixedpoint/README.md has the table):
// - Rounding is round half up: an exact result x becomes floor(x + 1/2 lsb). It is the cheapest
//   rounding to nearest in two's complement (a shift plus the first dropped bit), and biased
//   only at exact ties.
// - The plain operators (+ - * unary-, << , * int) wrap modulo 2^bits, like the integers they
//   are made of; the *_sat functions clamp to [min(), max()] instead. Pick per use: wrapping
//   is cheaper and exact when the format has headroom, saturation is for values from outside.
// - Division always saturates (its overflow is the common case: small divisors), and x / 0 is
//   max() for x > 0, min() for x < 0 and 0 for 0 / 0. It never traps.
// - Nothing converts implicitly: constants come from `Q<F>(0.25)`, which is consteval and
//   fails to compile when the value does not fit; other formats through fx::convert.
#pragma once

#include <fixedpoint/detail/divide.hpp>
#include <fixedpoint/detail/raw.hpp>

namespace fx {

template <int Frac, typename Raw = int32_t>
class Q {
  static_assert(detail::Storage<Raw>, "Q stores int16_t or int32_t");
  using Traits = detail::RawTraits<Raw>;
  static_assert(Frac >= 0 && Frac < Traits::bits, "Q<Frac, Raw>: 0 <= Frac < bits of Raw");

 public:
  using raw_type = Raw;
  static constexpr int frac_bits = Frac;
  static constexpr int int_bits = Traits::bits - 1 - Frac;  // not counting the sign

  constexpr Q() = default;

  // Compile-time constants only: a run-time double never reaches the target.
  consteval explicit Q(double value) : raw_(detail::constant_to_raw<Raw>(value, Frac)) {}

  static constexpr Q from_raw(Raw raw) {
    Q q;
    q.raw_ = raw;
    return q;
  }
  constexpr Raw raw() const { return raw_; }

  // Saturating: integers come from outside (counts, parameters) and must not wrap silently.
  static constexpr Q from_int(int32_t n) {
    return from_raw(detail::saturate<Raw>(static_cast<int64_t>(n) * (int64_t{1} << Frac)));
  }
  // Nearest integer, halves up.
  constexpr int32_t to_int() const { return static_cast<int32_t>(detail::round_shr(static_cast<int32_t>(raw_), Frac)); }

  // For host tests and tools; on the target it would pull in soft-float.
  constexpr double to_double() const { return static_cast<double>(raw_) * detail::pow2(-Frac); }

  static constexpr Q max() { return from_raw(Traits::max); }
  static constexpr Q min() { return from_raw(Traits::min); }

  // ---- wrapping arithmetic ----
  friend constexpr Q operator+(Q a, Q b) { return from_raw(detail::wrap<Raw>(word(a) + word(b))); }
  friend constexpr Q operator-(Q a, Q b) { return from_raw(detail::wrap<Raw>(word(a) - word(b))); }
  friend constexpr Q operator-(Q a) { return from_raw(detail::wrap<Raw>(Word{0} - word(a))); }
  friend constexpr Q operator*(Q a, Q b) { return from_raw(detail::wrap<Raw>(detail::round_shr(product(a, b), Frac))); }
  friend constexpr Q operator*(Q a, int32_t n) { return from_raw(detail::wrap<Raw>(static_cast<int64_t>(a.raw_) * n)); }
  friend constexpr Q operator*(int32_t n, Q a) { return a * n; }
  friend constexpr Q operator/(Q a, Q b) { return div_sat(a, b); }

  // Shifts scale by 2^n. n is clamped to [0, bits]: << by bits or more gives 0, >> by bits or
  // more gives floor, i.e. 0 or -lsb. >> floors (arithmetic shift); fx::convert rounds.
  friend constexpr Q operator<<(Q a, int n) {
    if (n <= 0) return a;
    if (n >= Traits::bits) return Q{};
    return from_raw(detail::wrap<Raw>(word(a) << n));
  }
  friend constexpr Q operator>>(Q a, int n) {
    if (n <= 0) return a;
    if (n >= Traits::bits) n = Traits::bits - 1;
    return from_raw(static_cast<Raw>(a.raw_ >> n));
  }

  friend constexpr Q& operator+=(Q& a, Q b) { return a = a + b; }
  friend constexpr Q& operator-=(Q& a, Q b) { return a = a - b; }
  friend constexpr Q& operator*=(Q& a, Q b) { return a = a * b; }
  friend constexpr Q& operator*=(Q& a, int32_t n) { return a = a * n; }
  friend constexpr Q& operator/=(Q& a, Q b) { return a = a / b; }
  friend constexpr Q& operator<<=(Q& a, int n) { return a = a << n; }
  friend constexpr Q& operator>>=(Q& a, int n) { return a = a >> n; }

  // ---- saturating arithmetic ----
  friend constexpr Q add_sat(Q a, Q b) {
    return from_raw(detail::saturate<Raw>(static_cast<Product>(a.raw_) + b.raw_));
  }
  friend constexpr Q sub_sat(Q a, Q b) {
    return from_raw(detail::saturate<Raw>(static_cast<Product>(a.raw_) - b.raw_));
  }
  friend constexpr Q neg_sat(Q a) { return from_raw(detail::saturate<Raw>(-static_cast<Product>(a.raw_))); }
  friend constexpr Q abs_sat(Q a) { return a.raw_ < 0 ? neg_sat(a) : a; }
  friend constexpr Q mul_sat(Q a, Q b) {
    return from_raw(detail::saturate<Raw>(detail::round_shr(product(a, b), Frac)));
  }
  friend constexpr Q mul_sat(Q a, int32_t n) {
    // |raw * n| <= 2^62: exact in int64 for either storage.
    return from_raw(detail::saturate<Raw>(static_cast<int64_t>(a.raw_) * n));
  }
  friend constexpr Q shl_sat(Q a, int n) {
    if (n <= 0 || a.raw_ == 0) return a;
    if (n >= Traits::bits) return a.raw_ < 0 ? min() : max();
    if (a.raw_ > (Traits::max >> n)) return max();
    if (a.raw_ < (Traits::min >> n)) return min();
    return from_raw(detail::wrap<Raw>(word(a) << n));
  }

  // a / b rounded half up, saturated; see the top of the file for b == 0.
  friend constexpr Q div_sat(Q a, Q b) {
    using U = typename Traits::UProduct;
    if (b.raw_ == 0) return a.raw_ > 0 ? max() : a.raw_ < 0 ? min() : Q{};
    const bool negative = (a.raw_ < 0) != (b.raw_ < 0);
    constexpr U kMaxMagnitude = static_cast<U>(Traits::max);
    if constexpr (sizeof(Raw) == 4) {
      // On magnitudes, n / d = q + r / d, rounded half up: q + 1 when r >= d / 2 for a positive
      // quotient, when r > d / 2 for a negative one (away from zero only past the half). A
      // quotient of 2^32 or more saturates, so the division needs only 32 bits of quotient.
      const uint64_t n = static_cast<uint64_t>(detail::magnitude<U>(a.raw_)) << Frac;
      const uint32_t d = static_cast<uint32_t>(detail::magnitude<U>(b.raw_));
      if ((n >> 32) >= d) return negative ? min() : max();
      const auto [q, r] = detail::divide_below(n, d);
      const uint32_t limit = static_cast<uint32_t>(kMaxMagnitude) + (negative ? 1u : 0u);
      if (q > limit) return negative ? min() : max();
      const uint32_t rounded = q + ((negative ? r > d - r : r >= d - r) ? 1u : 0u);  // <= 2^31 + 1
      if (rounded > limit) return negative ? min() : max();
      return from_raw(detail::wrap<Raw>(negative ? 0u - rounded : rounded));
    } else {
      // n / d with n = a * 2^Frac, rounded on magnitudes: half up is floor((2|n| + |d|) / 2|d|)
      // for a positive quotient and -floor((2|n| + |d| - 1) / 2|d|) for a negative one. Both fit:
      // 2|n| <= 2^(2 bits - 1) and |d| <= 2^(bits - 1).
      const U n = detail::magnitude<U>(a.raw_) << Frac;
      const U d = detail::magnitude<U>(b.raw_);
      const U q = (2 * n + d - static_cast<U>(negative)) / (2 * d);
      if (negative) return q > kMaxMagnitude + 1 ? min() : from_raw(detail::wrap<Raw>(U{0} - q));
      return q > kMaxMagnitude ? max() : from_raw(static_cast<Raw>(q));
    }
  }

  // ---- comparisons ----
  friend constexpr bool operator==(Q a, Q b) { return a.raw_ == b.raw_; }
  friend constexpr bool operator!=(Q a, Q b) { return a.raw_ != b.raw_; }
  friend constexpr bool operator<(Q a, Q b) { return a.raw_ < b.raw_; }
  friend constexpr bool operator<=(Q a, Q b) { return a.raw_ <= b.raw_; }
  friend constexpr bool operator>(Q a, Q b) { return a.raw_ > b.raw_; }
  friend constexpr bool operator>=(Q a, Q b) { return a.raw_ >= b.raw_; }

 private:
  using Word = typename Traits::Word;
  using Product = typename Traits::Product;

  static constexpr Word word(Q a) { return static_cast<Word>(a.raw_); }
  static constexpr Product product(Q a, Q b) { return static_cast<Product>(a.raw_) * static_cast<Product>(b.raw_); }

  Raw raw_ = 0;
};

template <typename T>
inline constexpr bool is_q = false;
template <int Frac, typename Raw>
inline constexpr bool is_q<Q<Frac, Raw>> = true;

}  // namespace fx
