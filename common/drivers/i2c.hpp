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

// ---- Several drivers on one wire ----
//
// On an IN4073-class board the MPU-6050 and the MS5611 share one bus. A tick's MPU burst (390 us at
// 400 kHz) and an MS5611 transfer (at most 142.5 us, its ADC read) fit in a 1 ms period back to
// back, so the bus must hold more than one transfer a tick. A shared bus has channels, one per
// driver, each holding one transfer at a time as an I2cBus does; the wire runs the transfers begun
// back to back, in the order they were begun (the `I2cSharedBus` concept):
//
//   static constexpr uint8_t kChannels
//   bool begin(uint8_t channel, const I2cTransfer&)   false: that channel's transfer is still
//                                                     queued or on the wire (or no such channel)
//   I2cResult poll(uint8_t channel, I2cReply&)        as I2cBus's poll, for that channel alone
//
// A driver is handed an I2cChannel, the view of one channel, which is an I2cBus: it never learns
// that it shares the wire, and never sees another driver's result. I2cQueue is the book-keeping
// such a bus needs whatever moves the bits: each channel's transfer queued, on the wire, finished;
// the wire's side takes the oldest queued transfer when the wire is free (next()) and hands back
// its result (finish()). A board's I2C interrupt handler would do the wire's side; the simulator's
// bus does it in simulated time (qr/boards/sim/sim_i2c_bus.hpp).
template <class B>
concept I2cSharedBus = requires(B& bus, uint8_t channel, const I2cTransfer& transfer, I2cReply& reply) {
  {B::kChannels};
  static_cast<bool>(bus.begin(channel, transfer));
  static_cast<I2cResult>(bus.poll(channel, reply));
};

template <I2cSharedBus Bus>
class I2cChannel {
 public:
  constexpr I2cChannel(Bus& bus, uint8_t channel) : bus_(&bus), channel_(channel) {}
  bool begin(const I2cTransfer& transfer) { return bus_->begin(channel_, transfer); }
  I2cResult poll(I2cReply& reply) { return bus_->poll(channel_, reply); }
  uint8_t channel() const { return channel_; }

 private:
  Bus* bus_;
  uint8_t channel_;
};

template <uint8_t Channels>
class I2cQueue {
 public:
  static constexpr uint8_t kChannels = Channels;
  static_assert(Channels > 0, "a bus with no channel");

  // ---- the drivers' side (I2cSharedBus) ----
  bool begin(uint8_t channel, const I2cTransfer& transfer) {
    if (channel >= Channels) return false;
    Slot& s = slots_[channel];
    if (s.state == State::queued || s.state == State::on_wire) return false;
    s.transfer = transfer;
    s.state = State::queued;
    s.order = next_order_++;
    return true;
  }
  I2cResult poll(uint8_t channel, I2cReply& reply) {
    if (channel >= Channels) return I2cResult::idle;
    Slot& s = slots_[channel];
    switch (s.state) {
      case State::idle: return I2cResult::idle;
      case State::queued:
      case State::on_wire: return I2cResult::pending;
      case State::done: break;
    }
    s.state = State::idle;  // a result is given once
    reply = s.reply;
    return s.result;
  }

  // ---- the wire's side ----
  // The oldest transfer queued, now on the wire; false while one is on it or none is queued.
  bool next(uint8_t& channel, I2cTransfer& transfer) {
    if (on_wire()) return false;
    bool found = false;
    for (uint8_t c = 0; c < Channels; ++c) {
      if (slots_[c].state != State::queued) continue;
      // Wrap-safe "begun earlier".
      if (!found || static_cast<int32_t>(slots_[c].order - slots_[channel].order) < 0) channel = c;
      found = true;
    }
    if (!found) return false;
    slots_[channel].state = State::on_wire;
    transfer = slots_[channel].transfer;
    return true;
  }
  // The transfer on the wire ended so; ignored for a channel whose transfer is not on the wire.
  void finish(uint8_t channel, I2cResult result, const I2cReply& reply) {
    if (channel >= Channels || slots_[channel].state != State::on_wire) return;
    slots_[channel].state = State::done;
    slots_[channel].result = result;
    slots_[channel].reply = reply;
  }
  bool on_wire() const {
    for (const Slot& s : slots_) {
      if (s.state == State::on_wire) return true;
    }
    return false;
  }
  uint8_t queued() const {
    uint8_t n = 0;
    for (const Slot& s : slots_) n = static_cast<uint8_t>(n + (s.state == State::queued ? 1 : 0));
    return n;
  }

 private:
  enum class State : uint8_t { idle, queued, on_wire, done };
  struct Slot {
    I2cTransfer transfer;
    State state = State::idle;
    uint32_t order = 0;
    I2cResult result = I2cResult::idle;
    I2cReply reply;
  };
  Slot slots_[Channels];
  uint32_t next_order_ = 0;
};

static_assert(I2cSharedBus<I2cQueue<2>>);
static_assert(I2cBus<I2cChannel<I2cQueue<2>>>);

}  // namespace drivers
