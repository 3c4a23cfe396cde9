// The MPU-6050's self-test (RM 4.1; PS 6.1, 6.2), the arithmetic of it: the factory trim each
// axis' code in SELF_TEST_X..A stands for, and the verdict on a response. The driver
// (mpu6050.hpp) takes the samples; this file only judges them.
//
// With an axis' self-test bit set the chip moves its proof mass electrostatically, and the output
// shifts by the self-test response STR = output with self-test on - output with it off. At the
// factory the part recorded, per axis, a 5-bit code of its own response (RM 4.1):
//
//   SELF_TEST_X (0x0D)  bits 7:5 XA_TEST[4:2]  bits 4:0 XG_TEST
//   SELF_TEST_Y (0x0E)  bits 7:5 YA_TEST[4:2]  bits 4:0 YG_TEST
//   SELF_TEST_Z (0x0F)  bits 7:5 ZA_TEST[4:2]  bits 4:0 ZG_TEST
//   SELF_TEST_A (0x10)  bits 5:4 XA_TEST[1:0]  bits 3:2 YA_TEST[1:0]  bits 1:0 ZA_TEST[1:0]
//
// and the factory trim FT, in counts at the self-test's full scales (gyro ±250 °/s, FS_SEL 0;
// accelerometer ±8 g, AFS_SEL 2), is for a code c of 1..31 (RM 4.1):
//
//   gyro   FT = 25 * 131 * 1.046^(c - 1)                      (negative for the Y axis)
//   accel  FT = 4096 * 0.34 * (0.92 / 0.34)^((c - 1) / 30)    (30 = 2^5 - 2)
//
// and 0 for c = 0. The part passes when (STR - FT) / FT is within ±14 % on every axis (PS 6.1 and
// 6.2, "Self test response: -14 to +14 %, change from factory trim"). A code of 0 says the part
// recorded no trim: with FT 0 the change cannot be formed, so the axis does not pass; a part that
// cannot show it is healthy is not flown.
//
// No floating point in common/, not even in constexpr (the freestanding rules' test reads the
// sources for the word): the tables are computed at compile time in 28-bit fixed point, the
// accelerometer's 30th root by bisection. Their every entry is the formula rounded to the nearest
// count (Mpu6050SelfTest.TrimTablesAreTheFormulasRounded, computed in double).
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace drivers {
namespace mpu6050 {

inline constexpr uint8_t kSelfTestX = 0x0D;  // 13, first of the four trim registers
inline constexpr uint8_t kTrimRegisters = 4;
inline constexpr uint8_t kSelfTestBits = 0xE0;            // X_ST, Y_ST, Z_ST: bits 7:5 of GYRO_CONFIG, ACCEL_CONFIG
inline constexpr uint8_t kSelfTestGyroFullScale = 0;      // FS_SEL 0, ±250 °/s (RM 4.1)
inline constexpr uint8_t kSelfTestAccelFullScale = 2;     // AFS_SEL 2, ±8 g (RM 4.1)
inline constexpr uint8_t kTrimCodes = 32;                 // 5 bits: 0 (no trim) and 1..31
inline constexpr int32_t kSelfTestTolerancePercent = 14;  // PS 6.1, 6.2

// Axes in the order of the data registers: accelerometer x, y, z, then gyroscope x, y, z.
inline constexpr uint8_t kSelfTestAxes = 6;

namespace trim_math {

// Fixed point with 28 fraction bits. Every number here stays under 4 (2^30), so a product of two
// is under 2^60 and fits in 64 bits.
inline constexpr uint64_t kOne = uint64_t{1} << 28;

constexpr uint64_t product(uint64_t a, uint64_t b) { return (a * b + kOne / 2) >> 28; }

// x^n, stopped once past `limit` (what it returns is then above `limit`, and nothing overflows).
constexpr uint64_t power_until(uint64_t x, int n, uint64_t limit) {
  uint64_t p = kOne;
  for (int i = 0; i < n && p <= limit; ++i) p = product(p, x);
  return p;
}

// The n-th root of x >= 1: the largest r with r^n <= x, by bisection between 1 and x.
constexpr uint64_t root(uint64_t x, int n) {
  uint64_t low = kOne, high = x;
  while (low < high) {
    const uint64_t mid = (low + high + 1) / 2;
    if (power_until(mid, n, x) <= x) {
      low = mid;
    } else {
      high = mid - 1;
    }
  }
  return low;
}

// base_numerator / base_denominator * step^(code - 1), rounded to a count; 0 for code 0.
constexpr uint16_t geometric_trim(uint64_t base_numerator, uint64_t base_denominator, uint64_t step, uint8_t code) {
  if (code == 0) return 0;
  uint64_t p = kOne;
  for (uint8_t i = 1; i < code; ++i) p = product(p, step);
  const uint64_t scale = base_denominator * kOne;
  return static_cast<uint16_t>((base_numerator * p + scale / 2) / scale);
}

// 1.046 and (0.92 / 0.34)^(1 / 30), RM 4.1's steps from one code to the next.
inline constexpr uint64_t kGyroStep = (1046 * kOne + 500) / 1000;
inline constexpr uint64_t kAccelStep = root((92 * kOne + 17) / 34, 30);

struct TrimTable {
  uint16_t counts[kTrimCodes];
};

constexpr TrimTable gyro_table() {
  TrimTable t{};
  for (uint8_t c = 0; c < kTrimCodes; ++c) t.counts[c] = geometric_trim(25 * 131, 1, kGyroStep, c);
  return t;
}

constexpr TrimTable accel_table() {
  TrimTable t{};
  for (uint8_t c = 0; c < kTrimCodes; ++c) t.counts[c] = geometric_trim(4096 * 34, 100, kAccelStep, c);
  return t;
}

}  // namespace trim_math

// The factory trim's size in counts by code (RM 4.1), gyroscope at ±250 °/s, accelerometer at ±8 g.
inline constexpr trim_math::TrimTable kGyroTrim = trim_math::gyro_table();
inline constexpr trim_math::TrimTable kAccelTrim = trim_math::accel_table();
static_assert(kGyroTrim.counts[0] == 0 && kGyroTrim.counts[1] == 3275 && kAccelTrim.counts[1] == 1393);
static_assert(kAccelTrim.counts[31] == 3768, "4096 * 0.92 at code 31: the root is right");

// The gyroscope's Y axis responds the other way (RM 4.1: FT[Yg] = -25 * 131 * 1.046^(YG_TEST - 1)).
inline constexpr int8_t kTrimSign[kSelfTestAxes] = {1, 1, 1, 1, -1, 1};

// Each axis' code from the four trim registers, in the data's order.
constexpr void trim_codes(const uint8_t (&regs)[kTrimRegisters], uint8_t (&codes)[kSelfTestAxes]) {
  for (uint8_t axis = 0; axis < 3; ++axis) {
    const uint8_t low_bits_shift = static_cast<uint8_t>(4 - 2 * axis);  // X 5:4, Y 3:2, Z 1:0 of SELF_TEST_A
    codes[axis] = static_cast<uint8_t>(((regs[axis] >> 5) << 2) | ((regs[3] >> low_bits_shift) & 0x03));
    codes[3 + axis] = static_cast<uint8_t>(regs[axis] & 0x1F);
  }
}

// The factory trim of each axis, signed, in counts at the self-test's full scales.
constexpr void factory_trim(const uint8_t (&regs)[kTrimRegisters], int32_t (&trim)[kSelfTestAxes]) {
  uint8_t codes[kSelfTestAxes] = {};
  trim_codes(regs, codes);
  for (uint8_t axis = 0; axis < kSelfTestAxes; ++axis) {
    const trim_math::TrimTable& table = axis < 3 ? kAccelTrim : kGyroTrim;
    trim[axis] = kTrimSign[axis] * int32_t{table.counts[codes[axis]]};
  }
}

// One axis: the sum of `samples` responses (on - off) against the trim. (STR - FT) / FT within
// ±14 % is |sum - samples * FT| * 100 <= 14 * samples * |FT|, in integers (in 64 bits: 255
// differences of 16-bit outputs, times 100, pass 2^31).
constexpr bool self_test_passes(int32_t response_sum, uint8_t samples, int32_t trim) {
  if (trim == 0) return false;
  const int64_t expected = int64_t{samples} * trim;
  const int64_t change = response_sum - expected;
  const int64_t allowed = kSelfTestTolerancePercent * (expected < 0 ? -expected : expected);
  return 100 * (change < 0 ? -change : change) <= allowed;
}

// The axes that fail, a bit each in the data's order (bit 0 accelerometer x .. bit 5 gyroscope z).
constexpr uint8_t self_test_failures(const int32_t (&response_sums)[kSelfTestAxes], uint8_t samples,
                                     const uint8_t (&trim_registers)[kTrimRegisters]) {
  int32_t trim[kSelfTestAxes] = {};
  factory_trim(trim_registers, trim);
  uint8_t failed = 0;
  for (uint8_t axis = 0; axis < kSelfTestAxes; ++axis) {
    if (!self_test_passes(response_sums[axis], samples, trim[axis])) failed |= static_cast<uint8_t>(1u << axis);
  }
  return failed;
}

}  // namespace mpu6050
}  // namespace drivers
