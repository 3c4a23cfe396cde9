// The devboard's end of the sensor link (common/sensor_link.hpp, docs/devboard.md): frames in
// from the virtio console, the latest sensors frame kept until the board takes it as its kick,
// engine frames out; and the sensors' I2C bus carried over it (LinkI2cBus).
#pragma once

#include <stdint.h>

#include <common/drivers/i2c.hpp>
#include <common/sensor_link.hpp>
#include <qr/boards/rv32virt/virtio_console.hpp>

namespace rv32virt {

class SensorLinkPort;

// The board's I2C bus when its sensors are the simulator's chips (drivers::I2cSharedBus, a channel
// per driver, as qr/core/sensor_stage.hpp wants): a transfer begun goes to the simulator at once
// (an i2c_begin frame), and its end comes back before a later kick (i2c_done). The simulator is
// the wire: it runs the transfers in the order begun, so each end is that of the oldest transfer
// still out, and I2cQueue keeps the book as for any wire.
class LinkI2cBus {
 public:
  static constexpr uint8_t kChannels = 2;

  explicit LinkI2cBus(SensorLinkPort& port) : port_(port) {}
  bool begin(uint8_t channel, const drivers::I2cTransfer& transfer);
  drivers::I2cResult poll(uint8_t channel, drivers::I2cReply& reply) { return queue_.poll(channel, reply); }
  // The simulator's i2c_done frame.
  void done(const simlink::I2cDoneFrame& frame);

 private:
  SensorLinkPort& port_;
  drivers::I2cQueue<kChannels> queue_;
};

class SensorLinkPort {
 public:
  // False when QEMU was started without the link (the devboard on its own).
  bool start() { return console_.start(); }

  // Every byte received since the last call through the parser.
  void poll();

  // The waiting sensors frame, once the ground bytes it counts have all
  // come in through the UART (`ground_received`, bytes so far), so they are in the receive ring
  // before the tick that should see them runs.
  // The frame stays valid until the next poll(): in lock-step none comes before the answer.
  const simlink::SensorFrame* take_kick(uint32_t ground_received);

  void send_engines(const simlink::EngineFrame& frame);
  void send_i2c(const simlink::I2cBeginFrame& frame);
  LinkI2cBus& i2c() { return i2c_; }

 private:
  VirtioConsole console_;
  simlink::LinkParser parser_{simlink::LinkEnd::qr};
  simlink::SensorFrame pending_;
  bool have_pending_ = false;
  LinkI2cBus i2c_{*this};
};

static_assert(drivers::I2cSharedBus<LinkI2cBus>);

}  // namespace rv32virt
