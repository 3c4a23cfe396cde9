// Exact references for the fixed-point tests: integer arithmetic in __int128 and the rounding
// rule written out the slow, obvious way, so the library is checked against its definition
// rather than against a copy of itself.
#pragma once

#include <fixedpoint/q.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

namespace fxtest {

using i128 = __int128;

// A Q's value, exactly (long double holds 64 significant bits).
template <typename Q>
long double value(Q q) {
  return ldexpl(static_cast<long double>(q.raw()), -Q::frac_bits);
}

// floor(x / y) for any signs, y != 0.
inline i128 floor_div(i128 x, i128 y) {
  i128 q = x / y;
  if ((x % y != 0) && ((x < 0) != (y < 0))) --q;
  return q;
}

// The library's rounding rule: floor(x / 2^s + 1/2).
inline i128 round_half_up_shift(i128 x, int s) {
  if (s <= 0) return x * (i128{1} << -s);
  return floor_div(2 * x + (i128{1} << s), i128{1} << (s + 1));
}

// floor(n / d + 1/2), d != 0.
inline i128 round_half_up_div(i128 n, i128 d) { return floor_div(2 * n + d, 2 * d); }

template <typename Raw>
Raw saturated(i128 v) {
  if (v < std::numeric_limits<Raw>::min()) return std::numeric_limits<Raw>::min();
  if (v > std::numeric_limits<Raw>::max()) return std::numeric_limits<Raw>::max();
  return static_cast<Raw>(v);
}

template <typename Raw>
Raw wrapped(i128 v) {
  using U = std::make_unsigned_t<Raw>;
  return static_cast<Raw>(static_cast<U>(static_cast<unsigned __int128>(v)));
}

// Raw values that matter for any format: the extremes, around zero, around one, and powers of
// two either side; then uniform randoms, from a fixed seed.
template <typename Raw>
std::vector<Raw> edge_raws() {
  using L = std::numeric_limits<Raw>;
  std::vector<Raw> v{L::min(), static_cast<Raw>(L::min() + 1), L::max(), static_cast<Raw>(L::max() - 1), 0, 1, -1, 2,
                     -2};
  for (int b = 1; b < std::numeric_limits<Raw>::digits; ++b) {
    const auto p = static_cast<Raw>(Raw{1} << b);
    for (Raw d : {Raw{-1}, Raw{0}, Raw{1}}) {
      v.push_back(static_cast<Raw>(p + d));
      v.push_back(static_cast<Raw>(-p + d));
    }
  }
  return v;
}

template <typename Raw>
class RawSource {
 public:
  explicit RawSource(uint64_t seed) : rng_(seed) {}
  // Uniform over all raws half the time, else with a random number of significant bits, so
  // small magnitudes are as well covered as large ones.
  Raw next() {
    using U = std::make_unsigned_t<Raw>;
    const auto bits = static_cast<U>(rng_());
    if (rng_() & 1) return static_cast<Raw>(bits);
    const int drop = static_cast<int>(rng_() % std::numeric_limits<U>::digits);
    const auto small = static_cast<U>(bits >> drop);
    return static_cast<Raw>((rng_() & 1) ? static_cast<U>(U{0} - small) : small);
  }

 private:
  std::mt19937_64 rng_;
};

}  // namespace fxtest
