// Two chips on one I2C wire, as little of each as the drivers need (common/drivers/mpu6050.hpp,
// ms5611.hpp), for the tests of a shared bus and of the core's sensor stage.
#pragma once

#include <stdint.h>

#include <algorithm>

#include <common/drivers/i2c.hpp>
#include <common/drivers/mpu6050.hpp>
#include <common/drivers/ms5611.hpp>
#include <tests/support/mpu6050_self_test_chip.hpp>

namespace test {

using drivers::I2cReply;
using drivers::I2cResult;
using drivers::I2cTransfer;

// Two chips on the wire, as little of each as the drivers need: an MPU-6050 register file that
// keeps what is written and reads the identity and a resting sample, and passes its self-test
// (tests/support/mpu6050_self_test_chip.hpp); an MS5611 with the datasheet's PROM and its example
// D1 and D2.
struct TwoChips {
  // The data registers: accelerometer x, y, z, temperature, gyroscope x, y, z (big-endian).
  void set_data(const int16_t (&values)[7]) {
    for (int i = 0; i < 7; ++i) {
      mpu[drivers::mpu6050::kAccelXoutH + 2 * i] = static_cast<uint8_t>(static_cast<uint16_t>(values[i]) >> 8);
      mpu[drivers::mpu6050::kAccelXoutH + 2 * i + 1] = static_cast<uint8_t>(values[i]);
    }
  }

  // Every transfer the wire has queued, answered in the order begun; the bus time they took.
  template <class Queue>
  uint64_t run_wire(Queue& bus) {
    uint64_t ns = 0;
    uint8_t channel = 0;
    I2cTransfer t;
    while (bus.next(channel, t)) {
      I2cReply reply;
      const I2cResult result = run(t, reply);
      bus.finish(channel, result, reply);
      ns += drivers::transfer_time_ns(t, 400000);
    }
    return ns;
  }

  uint8_t mpu[128] = {};
  uint8_t ms5611_command = 0;
  drivers::Ms5611Prom prom;

  TwoChips() {
    mpu[drivers::mpu6050::kWhoAmI] = drivers::mpu6050::kIdentity;
    const uint8_t data[14] = {0, 10, 0, 20, 0x20, 0, 0xF0, 0xB0, 0, 3, 0, 4, 0, 5};
    std::copy(data, data + 14, mpu + drivers::mpu6050::kAccelXoutH);
    std::copy(test_support::kMpu6050Trim, test_support::kMpu6050Trim + drivers::mpu6050::kTrimRegisters,
              mpu + drivers::mpu6050::kSelfTestX);
    const uint16_t c[8] = {0, 40127, 36924, 23317, 23282, 33464, 28312, 0};
    std::copy(c, c + 8, prom.word);
    prom = drivers::ms5611_prom_with_crc(prom);
  }

  I2cResult run(const I2cTransfer& t, I2cReply& reply) {
    reply = I2cReply{};
    if (t.address == drivers::mpu6050::kAddressAd0Low) {
      const uint8_t reg = t.write[0];
      for (uint8_t i = 1; i < t.write_count; ++i) {
        if (reg + i - 1 != drivers::mpu6050::kPwrMgmt1 || t.write[i] != drivers::mpu6050::kDeviceReset)
          mpu[reg + i - 1] = t.write[i];
      }
      for (uint8_t i = 0; i < t.read_count; ++i) {
        reply.data[i] = test_support::mpu6050_read(mpu, static_cast<uint8_t>(reg + i),
                                                   test_support::kHealthyMpu6050Response.counts);
      }
      reply.count = t.read_count;
      return I2cResult::ok;
    }
    if (t.address != drivers::kMs5611AddressCsbLow) return I2cResult::address_nack;
    const uint8_t command = t.write[0];
    if (t.read_count == 0) {
      ms5611_command = command;
      return I2cResult::ok;
    }
    reply.count = t.read_count;
    if (command >= drivers::kMs5611PromRead) {
      const uint16_t w = prom.word[(command - drivers::kMs5611PromRead) / 2];
      reply.data[0] = static_cast<uint8_t>(w >> 8);
      reply.data[1] = static_cast<uint8_t>(w);
      return I2cResult::ok;
    }
    const uint32_t code = ms5611_command >= drivers::kMs5611ConvertD2 ? 8569150u : 9085466u;
    reply.data[0] = static_cast<uint8_t>(code >> 16);
    reply.data[1] = static_cast<uint8_t>(code >> 8);
    reply.data[2] = static_cast<uint8_t>(code);
    return I2cResult::ok;
  }
};


}  // namespace test
