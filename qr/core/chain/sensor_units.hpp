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

 private:
  // Accel's raw value of one count as a power of two, 2^shift (Q<27>: 2^27 / 8192 = 2^14), or
  // -1 where it is none (floating point, or a scale that is not a power of two).
  static constexpr int accel_shift() {
    static_assert(kCountsPerGInt == sensor::kAccelCountsPerG, "a whole number of counts per g");
    if constexpr (fx::is_q<Accel>) {
      for (int shift = 0; shift <= Accel::frac_bits; ++shift) {
        if ((int64_t{1} << (Accel::frac_bits - shift)) == kCountsPerGInt) return shift;
      }
    }
    return -1;
  }

 public:

  template <int Frac = 0>
  static constexpr Rate rate_of(int32_t counts) {
    return product<Rate>(N::template fixed<Frac>(counts), kRadPerSecPerCount);
  }
  template <int Frac = 0>
  static constexpr Accel accel_of(int32_t counts) {
    if constexpr (accel_shift() >= Frac) {
      // 1 / 8192 g per count is a power of two, so the product is counts shifted left: no bit
      // is dropped, nothing is rounded, and both wrap modulo 2^32 alike. One shift where GCC
      // makes five of the 64-bit product's (SensorUnits.AccelShiftIsTheProduct checks every count).
      return Accel::from_raw(fx::detail::shl_wrap(counts, accel_shift() - Frac));
    } else {
      return product<Accel>(N::template fixed<Frac>(counts), kGPerCount);
    }
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
