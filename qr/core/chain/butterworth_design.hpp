// Butterworth low-pass design, 1st and 2nd order, by the bilinear transform with the cut-off
// pre-warped, so the digital filter is -3.01 dB exactly at fc. One implementation serves the
// compile-time table the firmware flies with (butterworth_table.hpp), the host tool qrfilter and
// the tests.
//
// Convention: H(z) = (b0 + b1 z^-1 + b2 z^-2) / (1 + a1 z^-1 + a2 z^-2), that is
// y = b.x - a1 y1 - a2 y2, the convention of fixedpoint/iir.hpp.
//
// Analogue prototypes with wc = 1 and k = tan(pi fc / fs) (the pre-warped cut-off over 2 fs):
//   order 1: H(s) = 1 / (1 + s)            b0 = b1 = k / (1 + k),  a1 = (k - 1) / (k + 1)
//   order 2: H(s) = 1 / (1 + sqrt2 s + s^2)
//            D = 1 + sqrt2 k + k^2,  b0 = b2 = k^2 / D,  b1 = 2 k^2 / D,
//            a1 = 2 (k^2 - 1) / D,  a2 = (1 - sqrt2 k + k^2) / D
#pragma once

#include <stdint.h>

#include <qr/core/chain/design_math.hpp>

namespace qr::chain {

struct ButterworthDesign {
  int order = 0;            // 1 or 2; 0 means "no design" (bad arguments)
  double b[3] = {0, 0, 0};  // b[2] is 0 for order 1
  double a[3] = {1, 0, 0};  // a[0] is always 1, a[2] is 0 for order 1
  constexpr bool valid() const { return order != 0; }
};

// order 1 or 2, 0 < fc < fs / 2; anything else gives an invalid (order 0) design.
constexpr ButterworthDesign design_butterworth(int order, double fc_hz, double fs_hz) {
  ButterworthDesign d;
  if ((order != 1 && order != 2) || !(fs_hz > 0) || !(fc_hz > 0) || !(fc_hz < fs_hz / 2)) return d;
  const double k = design::tan_first_quadrant(design::kPi * fc_hz / fs_hz);
  d.order = order;
  if (order == 1) {
    d.b[0] = d.b[1] = k / (1 + k);
    d.a[1] = (k - 1) / (k + 1);
  } else {
    const double den = 1 + design::kSqrt2 * k + k * k;
    d.b[0] = d.b[2] = k * k / den;
    d.b[1] = 2 * k * k / den;
    d.a[1] = 2 * (k * k - 1) / den;
    d.a[2] = (1 - design::kSqrt2 * k + k * k) / den;
  }
  return d;
}

// The coefficients as the integers of a Q<frac_bits> format. a1, a2 and the outer b's are rounded
// half up; the middle b is then chosen so that sum(b) = sum(a) exactly, which makes the DC gain
// of the quantised filter exactly 1 (a low-pass at rest must read what the sensor reads). The
// price is at most a couple of lsb on that one coefficient: its zero pair at z = -1 moves off
// by about 2^-frac_bits, leaving the gain at fs/2 below -170 dB for 30 bits.
struct QuantisedDesign {
  int order = 0;
  int frac_bits = 0;
  int64_t b[3] = {0, 0, 0};
  int64_t a[3] = {0, 0, 0};  // a[0] = 2^frac_bits
  // Whether every coefficient fits a signed 32-bit raw (what fx::Q<frac_bits> stores).
  constexpr bool fits_int32() const {
    for (int i = 0; i < 3; ++i) {
      if (b[i] < INT32_MIN || b[i] > INT32_MAX || a[i] < INT32_MIN || a[i] > INT32_MAX) return false;
    }
    return true;
  }
};

constexpr QuantisedDesign quantise(const ButterworthDesign& d, int frac_bits) {
  QuantisedDesign q;
  if (!d.valid() || frac_bits < 0 || frac_bits > 30) return q;
  q.order = d.order;
  q.frac_bits = frac_bits;
  const double scale = design::pow2(frac_bits);
  q.a[0] = int64_t{1} << frac_bits;
  q.a[1] = design::round_half_up(d.a[1] * scale);
  q.a[2] = design::round_half_up(d.a[2] * scale);
  q.b[0] = design::round_half_up(d.b[0] * scale);
  q.b[2] = design::round_half_up(d.b[2] * scale);
  // The middle tap (b1 for order 2, b1 for order 1 too) closes sum(b) = sum(a).
  q.b[1] = q.a[0] + q.a[1] + q.a[2] - q.b[0] - q.b[2];
  return q;
}

}  // namespace qr::chain
