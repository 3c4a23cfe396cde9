// An I2C bus as the sensor drivers see it: one transfer at a time, started by one tick and
// collected by a later one, so that no task waits on the wire.
//
// A transfer is what an I2C master does between a START and a STOP: the 7-bit address with the
// write bit, `write_count` bytes (a register address, and data to write), then, when
// `read_count` > 0, a repeated START, the address with the read bit, and `read_count` bytes read
// (the master acknowledges every byte but the last). Every byte the master sends is acknowledged
// by the device; an address nobody acknowledges or a refused byte ends the transfer with a NACK.
// The bus' own faults: SDA held low by a device (stuck), and nothing that a master can then do
// but clock it free (the bus' owner's business, counted as a failed transfer here).
//
// A bus is any class with (the `I2cBus` concept below):
//
//   bool begin(const I2cTransfer&)   start a transfer; false when one is still in progress
//   I2cResult poll(I2cReply&)        `pending` while it runs; then its result, once, with the
//                                    bytes read in the reply; `idle` when nothing was started
//
// Its time on the wire follows from its bits (I2C-bus specification, NXP UM10204: each byte is
// 8 bits and an acknowledge bit; START, repeated START and STOP are about one bit time each):
// `transfer_bits()` and `transfer_time_ns()`. At 400 kHz the MPU-6050's 14 data bytes read after
// a one-byte register address take 156 bits, 390 us: a third of a 1 kHz control period if a
// task waited for it.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace drivers {

inline constexpr uint8_t kI2cMaxWrite = 8;  // a register address and up to 7 data bytes
inline constexpr uint8_t kI2cMaxRead = 32;  // the longest read a driver here makes at once

struct I2cTransfer {
  uint8_t address = 0;  // 7-bit device address
  uint8_t write[kI2cMaxWrite] = {};
  uint8_t write_count = 0;
  uint8_t read_count = 0;  // 0: write only
};

enum class I2cResult : uint8_t {
  idle,          // nothing started (or its result already collected)
  pending,       // still on the wire
  ok,            // every byte acknowledged; the reply holds what was read
  address_nack,  // nobody answered the address
  data_nack,     // the device refused a byte written
  bus_stuck,     // SDA held low: the transfer could not start or finish
};

struct I2cReply {
  uint8_t data[kI2cMaxRead] = {};
  uint8_t count = 0;
};

template <class B>
concept I2cBus = requires(B& bus, const I2cTransfer& transfer, I2cReply& reply) {
  static_cast<bool>(bus.begin(transfer));
  static_cast<I2cResult>(bus.poll(reply));
};

// Helpers to build the common transfers.
constexpr I2cTransfer write_register(uint8_t address, uint8_t reg, uint8_t value) {
  I2cTransfer t;
  t.address = address;
  t.write[0] = reg;
  t.write[1] = value;
  t.write_count = 2;
  return t;
}

constexpr I2cTransfer read_registers(uint8_t address, uint8_t first_reg, uint8_t count) {
  I2cTransfer t;
  t.address = address;
  t.write[0] = first_reg;
  t.write_count = 1;
  t.read_count = count;
  return t;
}

// A command byte alone (the MS5611 takes its commands so).
constexpr I2cTransfer write_command(uint8_t address, uint8_t command) {
  I2cTransfer t;
  t.address = address;
  t.write[0] = command;
  t.write_count = 1;
  return t;
}

// The bits a transfer puts on the wire: START, address + R/W and its acknowledge, each byte
// written with its acknowledge; for a read a repeated START, the address again, each byte read
// with the master's acknowledge; STOP.
constexpr uint32_t transfer_bits(const I2cTransfer& t) {
  constexpr uint32_t kByte = 9;  // 8 data bits and the acknowledge
  uint32_t bits = 1 + kByte + kByte * t.write_count;
  if (t.read_count > 0) bits += 1 + kByte + kByte * t.read_count;
  return bits + 1;
}

// Its time at a bus clock of `hz` (100 000 or 400 000), rounded up to the nanosecond.
constexpr uint32_t transfer_time_ns(const I2cTransfer& t, uint32_t hz) {
  return static_cast<uint32_t>((static_cast<uint64_t>(transfer_bits(t)) * 1000000000u + hz - 1) / hz);
}

}  // namespace drivers
