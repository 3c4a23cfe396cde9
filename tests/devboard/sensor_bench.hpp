// The sensor stage's cost on the devboard (qr/core/sensor_stage.hpp): both drivers stepped a tick,
// the MPU-6050's burst and the MS5611's conversions, over a bus whose chips answer at once, as
// the bench board answers everything: the instructions are the drivers' own, and the bus time a
// tick spends at 400 kHz follows from the transfers begun (transfer_time_ns), as on any board.
//
// The chips here are the least that lets both drivers start and stream: an MPU-6050 register file
// (WHO_AM_I 0x68, configuration written and read back, a level sample in its data registers, a
// self-test it passes: tests/support/mpu6050_self_test_chip.hpp, its response a compile-time
// constant, so the bench's loop is built as it was) and an MS5611 that answers the datasheet's
// example (its PROM with a good CRC, its D1 and D2). What they do over time (conversion delays,
// start-up) is the simulator's models' business (sim/).
#pragma once

#include <stdint.h>

#include <common/drivers/i2c.hpp>
#include <common/drivers/mpu6050.hpp>
#include <common/drivers/ms5611.hpp>
#include <qr/boards/rv32virt/devboard.hpp>
#include <qr/core/sensor_stage.hpp>
#include <tests/support/mpu6050_self_test_chip.hpp>

namespace sensor_bench {

// An answer for each transfer, ready by the next tick.
class ChipsAtOnce {
 public:
  static constexpr uint8_t kChannels = 2;

  // The MPU at rest, level: 1 g up on Z at AFS_SEL 1, 36.53 °C, no rotation.
  ChipsAtOnce() {
    namespace m = drivers::mpu6050;
    mpu_regs_[m::kPwrMgmt1] = m::kPwrMgmt1Reset;
    mpu_regs_[m::kWhoAmI] = m::kIdentity;
    mpu_regs_[m::kAccelXoutH + 4] = 0x20;  // ACCEL_ZOUT = 8192
    for (uint8_t i = 0; i < m::kTrimRegisters; ++i) mpu_regs_[m::kSelfTestX + i] = test_support::kMpu6050Trim[i];
  }

  bool begin(uint8_t channel, const drivers::I2cTransfer& t) { return queue_.begin(channel, t); }
  drivers::I2cResult poll(uint8_t channel, drivers::I2cReply& reply) { return queue_.poll(channel, reply); }

  // Between ticks, outside what is measured (a board's I2C interrupt would do it while the tick
  // runs): the transfers begun, answered in order; their time on the wire at 400 kHz.
  uint32_t serve() {
    uint32_t ns = 0;
    uint8_t c = 0;
    drivers::I2cTransfer t;
    while (queue_.next(c, t)) {
      drivers::I2cReply reply;
      answer(t, reply);
      queue_.finish(c, drivers::I2cResult::ok, reply);
      ns += drivers::transfer_time_ns(t, drivers::kMs5611BusHz);
    }
    return ns;
  }

 private:
  void answer(const drivers::I2cTransfer& t, drivers::I2cReply& reply) {
    reply.count = t.read_count;
    if (t.address == drivers::mpu6050::kAddressAd0Low) {
      mpu(t, reply);
    } else {
      ms5611(t, reply);
    }
  }
  void mpu(const drivers::I2cTransfer& t, drivers::I2cReply& reply) {
    namespace m = drivers::mpu6050;
    const uint8_t reg = t.write[0];
    for (uint8_t i = 1; i < t.write_count; ++i) mpu_regs_[(reg + i - 1) & 0x7F] = t.write[i];
    if ((mpu_regs_[m::kPwrMgmt1] & m::kDeviceReset) != 0) mpu_regs_[m::kPwrMgmt1] = m::kPwrMgmt1Reset;
    for (uint8_t i = 0; i < t.read_count; ++i) {
      reply.data[i] = test_support::mpu6050_read(mpu_regs_, static_cast<uint8_t>((reg + i) & 0x7F),
                                                 test_support::kHealthyMpu6050Response.counts);
    }
  }
  void ms5611(const drivers::I2cTransfer& t, drivers::I2cReply& reply) {
    const uint8_t command = t.write[0];
    if ((command & 0xF0) == drivers::kMs5611ConvertD1 || (command & 0xF0) == drivers::kMs5611ConvertD2) {
      converted_ = (command & 0xF0) == drivers::kMs5611ConvertD1 ? kD1 : kD2;
    } else if (command == drivers::kMs5611AdcRead && t.read_count == drivers::kMs5611AdcBytes) {
      reply.data[0] = static_cast<uint8_t>(converted_ >> 16);
      reply.data[1] = static_cast<uint8_t>(converted_ >> 8);
      reply.data[2] = static_cast<uint8_t>(converted_);
    } else if (command >= drivers::kMs5611PromRead && t.read_count == 2) {
      const uint16_t word = kProm.word[((command - drivers::kMs5611PromRead) / 2) & 7];
      reply.data[0] = static_cast<uint8_t>(word >> 8);
      reply.data[1] = static_cast<uint8_t>(word);
    }
  }

  // The MS5611 datasheet's example (MEAS MS5611-01BA03, "Pressure and temperature calculation").
  static constexpr uint32_t kD1 = 9085466, kD2 = 8569150;
  static constexpr drivers::Ms5611Prom kProm = drivers::ms5611_prom_with_crc(
      drivers::Ms5611Prom{{0, 40127, 36924, 23317, 23282, 33464, 28312, 0}});

  drivers::I2cQueue<kChannels> queue_;
  uint8_t mpu_regs_[128] = {};
  uint32_t converted_ = 0;
};

struct Board {
  using I2cBus = ChipsAtOnce;
  I2cBus& i2c() { return bus; }
  bool sensors_on_i2c() const { return true; }
  uint16_t battery_mv() const { return 12000; }
  qr::SensorSample read_sensors() const { return {}; }
  uint32_t cycles() const { return rv32virt::instret(); }
  ChipsAtOnce bus;
};

struct Figures {
  uint32_t instr_mean = 0, instr_max = 0;  // the stage's instructions per tick
  uint32_t bus_us_mean = 0, bus_us_max = 0;
  uint32_t imu_samples = 0, baro_readings = 0, faults = 0;
};

// A second of start-up, then `ticks` of streaming, one tick a control period.
inline Figures measure(uint32_t ticks) {
  static Board board;
  static qr::SensorStage<Board> stage;
  uint32_t now_us = 0;
  for (uint32_t i = 0; i < qr::kControlHz; ++i, now_us += qr::kPeriodUs) {
    stage.read(board, now_us);
    board.bus.serve();
  }
  const uint32_t samples_before = stage.imu().samples(), readings_before = stage.barometer().readings();
  Figures f;
  uint64_t bus_ns = 0, instr = 0;
  for (uint32_t i = 0; i < ticks; ++i, now_us += qr::kPeriodUs) {
    const uint32_t a = rv32virt::instret();
    stage.read(board, now_us);
    const uint32_t n = rv32virt::instret() - a;
    const uint32_t ns = board.bus.serve();
    instr += n;
    bus_ns += ns;
    if (n > f.instr_max) f.instr_max = n;
    if (ns / 1000u > f.bus_us_max) f.bus_us_max = ns / 1000u;
  }
  f.instr_mean = static_cast<uint32_t>(instr / ticks);
  f.bus_us_mean = static_cast<uint32_t>(bus_ns / ticks / 1000u);
  f.imu_samples = stage.imu().samples() - samples_before;
  f.baro_readings = stage.barometer().readings() - readings_before;
  f.faults = stage.imu().total_faults() + stage.barometer().total_faults();
  return f;
}

}  // namespace sensor_bench
