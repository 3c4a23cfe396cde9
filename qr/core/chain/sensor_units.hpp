// Raw sensor counts to the chain's units and back: gyro counts to rad/s, accelerometer counts to g
// (qr/core/sensor_scale.hpp, docs/conventions.md). Counts may carry fractional bits (the
// calibration's averages do), hence the Frac parameter.
#pragma once

#include <stdint.h>

#include <common/units.hpp>
#include <qr/core/chain/numeric.hpp>
#include <qr/core/sensor_scale.hpp>

namespace qr::chain {

template <class N>
struct SensorUnits {
  using Rate = typename N::Rate;
  using Accel = typename N::Accel;
  using Scale = typename N::Scale;
  using CountScale = typename N::CountScale;

  // 1 / 3752.9 is 2.66e-4 rad/s per count, quantised to 1 ppm in Q<31>; 1 / 8192 is exact.
  static constexpr Scale kRadPerSecPerCount = Scale(1.0 / sensor::kGyroCountsPerRadPerSec);
  static constexpr Scale kGPerCount = Scale(1.0 / sensor::kAccelCountsPerG);
  static constexpr CountScale kCountsPerRadPerSec = CountScale(sensor::kGyroCountsPerRadPerSec);
  static constexpr CountScale kCountsPerG = CountScale(sensor::kAccelCountsPerG);
  static constexpr int32_t kCountsPerGInt = static_cast<int32_t>(sensor::kAccelCountsPerG);
  static constexpr int32_t kMillion = 1000000;

 private:
  // counts x scale in T's format, as product() computes it: narrow() of the exact product. Where
  // the scale's raw is a whole number of T's lsb (no bit of the product falls below T's lsb),
  // there is nothing to round, and the product is counts x that number, which wraps modulo 2^32
  // as narrow() does: one 32-bit multiply where GCC makes five instructions of the 64-bit
  // product. True of both scales for raw counts: 1/8192 g is 2^14 lsb of Q<27>, and the gyro's
  // 572224 / 2^31 rad/s is 35764 lsb of Q<27> (SensorUnits.ScalingByAWholeNumberIsTheProduct
  // checks every count, and the calibration's sums).
  template <class T, int Frac, class S>
  static constexpr T scaled(int32_t counts, S scale) {
    if constexpr (fx::is_q<T>) {
      constexpr int kShift = S::frac_bits + Frac - T::frac_bits;  // what narrow() shifts away
      if constexpr (kShift >= 0 && kShift < 31) {
        if (scale.raw() % (int32_t{1} << kShift) == 0) {
          const uint32_t lsbs = static_cast<uint32_t>(scale.raw() >> kShift);
          return T::from_raw(static_cast<int32_t>(static_cast<uint32_t>(counts) * lsbs));
        }
      }
    }
    return product<T>(N::template fixed<Frac>(counts), scale);
  }

 public:
  template <int Frac = 0>
  static constexpr Rate rate_of(int32_t counts) {
    return scaled<Rate, Frac>(counts, kRadPerSecPerCount);
  }

  // The rate of one count on a gyro axis that reads `ppm` parts per million more than nominal
  // (parameters gyro_scale_{x,y,z}_ppm): the nominal scale / (1 + ppm 1e-6), rounded to Rate's
  // lsb. In Q<27> the nominal is 35764 lsb, so the rounding is 14 ppm at most; 0 ppm gives the
  // nominal exactly (GyroScale.ZeroPpmIsTheNominalScaleBitForBit), so a default vehicle computes
  // what it did without the correction.
  static constexpr Rate rate_per_count(int32_t ppm) {
    using Gain = typename N::Coefficient;  // 1e6 / (1e6 + ppm) lies in [0.9, 1.12)
    return product<Rate>(kRadPerSecPerCount, N::template ratio<Gain>(kMillion, kMillion + ppm));
  }
  // counts (with Frac fractional bits) x the rate of one count: product()'s result. With whole
  // counts the Q product needs no rounding and cannot wrap (32768 counts x under 2^16 lsb), so
  // it is one 32-bit multiply, as scaled() makes of a constant scale.
  template <int Frac = 0>
  static constexpr Rate rate_of(int32_t counts, Rate per_count) {
    if constexpr (fx::is_q<Rate> && Frac == 0) {
      return Rate::from_raw(
          static_cast<int32_t>(static_cast<uint32_t>(counts) * static_cast<uint32_t>(per_count.raw())));
    } else {
      return product<Rate>(N::template fixed<Frac>(counts), per_count);
    }
  }
  template <int Frac = 0>
  static constexpr Accel accel_of(int32_t counts) {
    return scaled<Accel, Frac>(counts, kGPerCount);
  }
  // Back to counts (for the sensor log: filtered values in the sensor's own units), saturated.
  static constexpr int16_t gyro_counts(Rate r) {
    return wire::saturate_i16(N::round_to_int(fx::mul_wide(r, kCountsPerRadPerSec)));
  }
  static constexpr int16_t accel_counts(Accel a) {
    return wire::saturate_i16(N::round_to_int(fx::mul_wide(a, kCountsPerG)));
  }
};

}  // namespace qr::chain
