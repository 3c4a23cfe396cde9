// The devboard's end of the sensor link (common/sensor_link.hpp, docs/devboard.md): frames in
// from the virtio console, the latest sensors frame kept until the board takes it as its kick,
// engine frames out.
#pragma once

#include <stdint.h>

#include <common/sensor_link.hpp>
#include <qr/boards/rv32virt/virtio_console.hpp>

namespace rv32virt {

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

 private:
  VirtioConsole console_;
  simlink::LinkParser parser_{simlink::LinkEnd::qr};
  simlink::SensorFrame pending_;
  bool have_pending_ = false;
};

}  // namespace rv32virt
