// A chip on an I2C bus as the simulator sees it: the register-level sensor models
// (mpu6050_model.hpp, ms5611_model.hpp) answer transfers through this, and the sim board adapts the
// firmware's bus to it. The wire itself (its time, a NACK burst, SDA held low) is the board's
// business, not the chip's: a model only says what the chip does with the bytes, and when.
//
// A transfer, as the I2C-bus specification (NXP UM10204) has a master do it: START, the 7-bit
// address with the write bit and `n` bytes written (a register address or a command, then data),
// then optionally a repeated START, the address with the read bit and `n` bytes read. The board
// calls write() for the first part and read() for the second, each with the instant the chip sees
// it (seconds on the simulator's clock; a model's timing, its start-up, reset and conversion times,
// is measured on it). A write of no bytes is an address probe.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace sim {

// How the chip answered. The firmware's driver tells the three apart (common/drivers/i2c.hpp's
// address_nack and data_nack), so a plain bool would not do.
enum class I2cAck : uint8_t {
  ack,           // the address and every byte written were acknowledged
  address_nack,  // the chip did not acknowledge its address (starting up, resetting)
  data_nack,     // the address was acknowledged, a byte written was refused
};

class I2cDevice {
 public:
  virtual ~I2cDevice() = default;

  virtual uint8_t address() const = 0;  // 7-bit
  // The address with the write bit, then `n` bytes.
  virtual I2cAck write(const uint8_t* bytes, size_t n, double t_s) = 0;
  // The address with the read bit, then `n` bytes clocked out of the chip into `out`. On a NACK
  // `out` holds 0xFF (nobody drives the pulled-up line).
  virtual I2cAck read(uint8_t* out, size_t n, double t_s) = 0;
};

}  // namespace sim
