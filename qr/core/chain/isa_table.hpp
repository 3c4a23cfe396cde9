// Metres per pascal of the standard atmosphere, for turning a barometer's pressure change into a
// height change near the pressure at calibration. ISA troposphere (ICAO Doc 7488/3, Manual of the
// ICAO Standard Atmosphere, 1993): h = T0 / L (1 - (p / p0)^(1/n)), with p0 = 101325 Pa,
// T0 = 288.15 K, L = 0.0065 K/m and n = g0 M / (R L) = 5.25588, so
//
//   dh/dp = -T0 / (L n p0) (p / p0)^(1/n - 1)        (-0.0833 m/Pa at sea level: 1 / (rho0 g0))
//
// The table holds |dh/dp| every 5 kPa from 30 to 120 kPa (the MS5611 reads 1 to 120 kPa; 30 kPa is
// 9 km up), computed at compile time; calibration interpolates it once, at the reference pressure,
// and the height is then linear in the pressure change. That linearisation is off by
// (1 - 1/n) dp / (2 p) of the height, 0.4 % per 100 m: 4 mm at 10 m, 0.4 m at 100 m.
#pragma once

#include <stdint.h>

namespace qr::chain::isa {

inline constexpr double kSeaLevelPa = 101325.0;
inline constexpr double kSeaLevelK = 288.15;
inline constexpr double kLapseKPerM = 0.0065;
inline constexpr double kExponent = 5.25588;  // g0 M / (R L)

inline constexpr int32_t kTableLowPa = 30000;
inline constexpr int32_t kTableStepPa = 5000;
inline constexpr int kTableSize = 19;  // 30, 35, ..., 120 kPa

namespace detail {

// ln x for x in (0.25, 1.5]: 2 atanh((x - 1) / (x + 1)), whose series converges fast there.
constexpr double ln(double x) {
  const double y = (x - 1) / (x + 1), y2 = y * y;
  double term = y, sum = 0;
  for (int k = 0; k < 40; ++k) {
    sum += term / (2 * k + 1);
    term *= y2;
  }
  return 2 * sum;
}

// e^x for |x| < 2: the Taylor series, 40 terms.
constexpr double exp(double x) {
  double term = 1, sum = 1;
  for (int k = 1; k < 40; ++k) {
    term *= x / k;
    sum += term;
  }
  return sum;
}

}  // namespace detail

// |dh/dp| in m/Pa at `pascals`, at compile time only (double).
constexpr double metres_per_pascal(double pascals) {
  const double ratio = pascals / kSeaLevelPa;
  return kSeaLevelK / (kLapseKPerM * kExponent * kSeaLevelPa) * detail::exp((1 / kExponent - 1) * detail::ln(ratio));
}

// The table in the number type T (a Q format or floating point); consteval, as the Q formats'
// constructors from double are.
template <class T>
struct Gradient {
  T at[kTableSize];
};
template <class T>
consteval Gradient<T> gradient_table() {
  Gradient<T> g{};
  for (int i = 0; i < kTableSize; ++i) g.at[i] = T(metres_per_pascal(kTableLowPa + i * kTableStepPa));
  return g;
}

}  // namespace qr::chain::isa
