// The self-test of the test benches' MPU-6050 register files (the driver's scripted bus, the two
// chips on one wire, the fuzz target's bus, the devboard's sensor bench): a part's factory trim in
// SELF_TEST_X..A and, on each axis whose self-test bit is set, its data shifted by a response
// (RM 4.1; common/drivers/mpu6050_self_test.hpp). Freestanding: the devboard's bench builds it for
// RV32 too. The simulator's chip is sim/mpu6050_model.hpp, with its own.
#pragma once

#include <stdint.h>

#include <common/drivers/mpu6050.hpp>

namespace test_support {

// A part of mid-range codes, each accelerometer code with bits in both its registers: gyroscope
// x, y, z 12, 17, 14; accelerometer x, y, z 18, 13, 15 (RM 4.1's layout, mpu6050_self_test.hpp).
inline constexpr uint8_t kMpu6050Trim[drivers::mpu6050::kTrimRegisters] = {
    (18 >> 2) << 5 | 12, (13 >> 2) << 5 | 17, (15 >> 2) << 5 | 14, (18 & 3) << 4 | (13 & 3) << 2 | (15 & 3)};

// The response of a healthy part: its factory trim, from the driver's table.
struct Mpu6050Response {
  int32_t counts[drivers::mpu6050::kSelfTestAxes];
};
constexpr Mpu6050Response healthy_mpu6050_response(const uint8_t (&trim)[drivers::mpu6050::kTrimRegisters]) {
  Mpu6050Response r{};
  drivers::mpu6050::factory_trim(trim, r.counts);
  return r;
}
inline constexpr Mpu6050Response kHealthyMpu6050Response = healthy_mpu6050_response(kMpu6050Trim);

// The byte a part whose register file is `regs` (0x00 .. 0x48 at least) reads at register `r`: a
// data register of an axis whose self-test bit is set is its value plus that axis' `response`
// (in the data's order, counts), saturated.
inline uint8_t mpu6050_read(const uint8_t* regs, uint8_t r,
                            const int32_t (&response)[drivers::mpu6050::kSelfTestAxes]) {
  namespace m = drivers::mpu6050;
  const bool accel = r >= m::kAccelXoutH && r < m::kTempOutH;
  const bool gyro = r >= m::kGyroXoutH && r <= m::kGyroZoutL;
  if (!accel && !gyro) return regs[r];
  const uint8_t first = accel ? m::kAccelXoutH : m::kGyroXoutH;
  const uint8_t axis = static_cast<uint8_t>((r - first) / 2);
  const uint8_t st_bit = static_cast<uint8_t>(0x80u >> axis);  // X_ST bit 7, Y_ST 6, Z_ST 5
  if ((regs[accel ? m::kAccelConfig : m::kGyroConfig] & st_bit) == 0) return regs[r];
  const uint8_t high = static_cast<uint8_t>(first + 2 * axis);
  int32_t word = static_cast<int16_t>(static_cast<uint16_t>(regs[high] << 8 | regs[high + 1]));
  word += response[(accel ? 0 : 3) + axis];
  word = word > 32767 ? 32767 : word < -32768 ? -32768 : word;
  const uint16_t bits = static_cast<uint16_t>(word);
  return r == high ? static_cast<uint8_t>(bits >> 8) : static_cast<uint8_t>(bits & 0xFF);
}

}  // namespace test_support
