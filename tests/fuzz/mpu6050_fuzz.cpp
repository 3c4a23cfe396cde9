// Fuzz target: the MPU-6050 driver (common/drivers/mpu6050.hpp) stepped over a bus whose every
// answer the input may spoil. The bus holds a chip's registers and answers as the chip would, so
// the driver gets through its start-up and streams; each step's input byte then picks the result
// of the transfer begun (ok, a NACK, stuck, pending, a value outside the enumeration), whether the
// begin is refused, bytes of the reply flipped or cut short, and how much time passes (one tick,
// or a jump through the waits). The first bytes pick the configuration, valid or not. Checks,
// beyond what ASan and UBSan catch: every transfer is one the chip's protocol allows, at the
// configured address; a refused configuration never touches the bus; at most one transfer a step,
// never more than the burst's 390 us at 400 kHz; the counters only grow; and a healthy driver is
// streaming, with a sample whose temperature is inside the chip's range.
#include <stddef.h>
#include <stdint.h>

#include <common/drivers/mpu6050.hpp>

#include <tests/support/mpu6050_self_test_chip.hpp>

#include "fuzz_checks.hpp"

namespace {

using fuzz::require;
namespace reg = drivers::mpu6050;

struct Input {
  const uint8_t* data;
  size_t size;
  size_t at = 0;
  uint8_t next() { return at < size ? data[at++] : 0; }
  bool done() const { return at >= size; }
};

struct FuzzBus {
  Input* input = nullptr;
  uint8_t address = reg::kAddressAd0Low;
  uint8_t regs[128] = {};
  bool in_flight = false;
  int pending = 0;
  drivers::I2cResult result = drivers::I2cResult::idle;
  drivers::I2cReply reply;
  uint32_t begins_this_step = 0;
  uint32_t begins = 0;
  uint8_t control = 0;  // this step's byte

  // A part that passes its self-test, unless the input spoils its samples.
  FuzzBus() {
    regs[reg::kPwrMgmt1] = reg::kPwrMgmt1Reset;
    regs[reg::kWhoAmI] = reg::kIdentity;
    regs[reg::kAccelXoutH + 5] = 1;  // a sample that is not all zeros, at 36.53 °C
    for (uint8_t i = 0; i < reg::kTrimRegisters; ++i) regs[reg::kSelfTestX + i] = test_support::kMpu6050Trim[i];
  }

  bool begin(const drivers::I2cTransfer& t) {
    ++begins_this_step;
    ++begins;
    require(t.address == address);
    require(t.write_count >= 1 && t.write_count <= drivers::kI2cMaxWrite);
    require(t.read_count <= drivers::kI2cMaxRead);
    // A read is a register address and the bytes read; a write sends no read.
    require(t.read_count == 0 || t.write_count == 1);
    if ((control & 0x08) != 0 || in_flight) return false;
    in_flight = true;
    pending = (control & 0x10) != 0 ? (control >> 5) : 0;
    const uint8_t pick = control & 0x07;
    result = pick < 4 ? drivers::I2cResult::ok : static_cast<drivers::I2cResult>(pick - 1);  // NACKs, stuck, 6
    if ((control & 0xE0) == 0xE0) result = static_cast<drivers::I2cResult>(input->next());   // anything
    reply = drivers::I2cReply{};
    const uint8_t first = t.write[0];
    for (uint8_t i = 1; i < t.write_count; ++i) {
      const uint8_t r = static_cast<uint8_t>((first + i - 1) & 0x7F);
      if (r == reg::kPwrMgmt1 && (t.write[i] & reg::kDeviceReset) != 0) {
        regs[reg::kPwrMgmt1] = reg::kPwrMgmt1Reset;
      } else {
        regs[r] = t.write[i];
      }
    }
    for (uint8_t i = 0; i < t.read_count; ++i) {
      reply.data[i] = test_support::mpu6050_read(regs, static_cast<uint8_t>((first + i) & 0x7F),
                                                 test_support::kHealthyMpu6050Response.counts);
    }
    reply.count = t.read_count;
    if (pick == 1) reply.data[input->next() % drivers::kI2cMaxRead] ^= input->next();  // a byte spoiled
    if (pick == 2) reply.count = input->next();                                        // any length
    if (pick == 3) {  // new data in the chip's registers for the next read
      for (uint8_t r = reg::kAccelXoutH; r <= reg::kGyroZoutL; ++r) regs[r] = input->next();
    }
    return true;
  }

  drivers::I2cResult poll(drivers::I2cReply& out) {
    if (!in_flight) return drivers::I2cResult::idle;
    if (pending > 0) {
      --pending;
      return drivers::I2cResult::pending;
    }
    in_flight = false;
    out = reply;
    return result;
  }
};

drivers::Mpu6050Config config_from(Input& in) {
  drivers::Mpu6050Config config;
  const uint8_t shape = in.next();
  if ((shape & 0x01) != 0) config.sample_rate_divider = in.next();
  if ((shape & 0x02) != 0) config.dlpf = static_cast<uint8_t>(in.next() % 9);
  if ((shape & 0x04) != 0) config.gyro_full_scale = static_cast<uint8_t>(in.next() % 5);
  if ((shape & 0x08) != 0) config.accel_full_scale = static_cast<uint8_t>(in.next() % 5);
  if ((shape & 0x10) != 0) config.address = in.next();
  if ((shape & 0x20) != 0) {
    for (int i = 0; i < 3; ++i) {
      config.chip_to_body.chip_axis[i] = static_cast<uint8_t>(in.next() % 4);
      config.chip_to_body.sign[i] = static_cast<int8_t>(in.next());
    }
  }
  return config;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Input in{data, size};
  const drivers::Mpu6050Config config = config_from(in);
  drivers::Mpu6050 mpu(config);
  FuzzBus bus;
  bus.input = &in;
  bus.address = config.address;
  uint32_t now_us = static_cast<uint32_t>(in.next()) << 24;  // start anywhere, the wrap included
  uint32_t faults = 0;
  uint32_t lost = 0;
  uint32_t restarts = 0;
  while (!in.done()) {
    bus.control = in.next();
    bus.begins_this_step = 0;
    mpu.step(bus, now_us);
    require(bus.begins_this_step <= 1);
    require(mpu.bus_time_ns_this_tick(400000) <= 390000u);
    require((mpu.bus_bits_this_tick() == 0) == (mpu.bus_time_ns_this_tick(400000) == 0));
    require(mpu.total_faults() >= faults && mpu.lost_count() >= lost && mpu.restart_count() >= restarts);
    require(mpu.lost_count() <= mpu.restart_count());
    faults = mpu.total_faults();
    lost = mpu.lost_count();
    restarts = mpu.restart_count();
    if (mpu.healthy()) {
      require(mpu.phase() == drivers::Mpu6050Phase::streaming && mpu.samples() > 0);
      require(mpu.sample().temperature >= reg::kTempMinCounts && mpu.sample().temperature <= reg::kTempMaxCounts);
    }
    // Mostly one 1 ms tick; now and then a jump, so the 100 ms waits pass within a short input.
    const uint8_t time = in.next();
    now_us += (time & 0x80) != 0 ? static_cast<uint32_t>(time & 0x7F) * 4000u : 1000u;
  }
  require(drivers::valid(config) || (bus.begins == 0 && mpu.phase() == drivers::Mpu6050Phase::refused));
  return 0;
}
