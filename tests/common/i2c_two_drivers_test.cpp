// The MPU-6050 and the MS5611 drivers streaming together over one wire (common/drivers/i2c.hpp's
// I2cQueue), each through its own channel, within a 1 ms tick's bus time.
#include <gtest/gtest.h>

#include <common/drivers/i2c.hpp>
#include <common/drivers/mpu6050.hpp>
#include <common/drivers/ms5611.hpp>
#include <tests/common/i2c_two_chips.hpp>

#include <algorithm>

namespace {

using drivers::I2cChannel;
using drivers::I2cQueue;
using drivers::I2cReply;
using drivers::I2cResult;
using drivers::I2cTransfer;

TEST(I2cTwoDrivers, TheMpu6050AndTheMs5611StreamTogetherWithinATick) {
  I2cQueue<2> bus;
  I2cChannel<I2cQueue<2>> mpu_channel(bus, 0), baro_channel(bus, 1);
  drivers::Mpu6050 mpu;
  drivers::Ms5611 baro;
  test::TwoChips chips;
  uint64_t most_ns = 0;
  uint32_t samples_streaming = 0, ticks_streaming = 0;
  for (uint32_t tick = 0; tick < 2000; ++tick) {
    const uint32_t now_us = tick * 1000;
    mpu.step(mpu_channel, now_us);
    baro.step(baro_channel, now_us);
    if (mpu.phase() == drivers::Mpu6050Phase::streaming) {
      ++ticks_streaming;
      samples_streaming += mpu.fresh() ? 1 : 0;
    }
    // The wire: what the tick began, back to back, each answered by its chip before the next tick.
    most_ns = std::max(most_ns, chips.run_wire(bus));
  }
  EXPECT_EQ(mpu.total_faults(), 0u);
  EXPECT_EQ(baro.total_faults(), 0u);
  EXPECT_GT(ticks_streaming, 1500u);
  EXPECT_EQ(samples_streaming, ticks_streaming - 1) << "a sample every tick but the first";
  EXPECT_EQ(mpu.sample().accel[2], -8192);
  EXPECT_GE(baro.readings(), 2000u * 60 / 1000) << "about 67 pressures a second";
  EXPECT_EQ(baro.reading().pressure_pa, 100009);
  // The MPU's burst (390 us) and the MS5611's longest transfer, its ADC read (142.5 us), in one tick.
  EXPECT_EQ(most_ns, 390000u + 142500u);
  EXPECT_EQ(baro.bus_busy(), 0u) << "the shared bus never refused the barometer";
}

}  // namespace
