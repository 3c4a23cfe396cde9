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

// The ground UART's transmitter at the line's pace. QEMU's 16550 passes a byte on the moment it
// is written, which a real line cannot: the board holds it to 115200 baud itself, as a transmit
// buffer of `kCapacity` bytes that drains one byte per kLineByteTimeNs of board time, the same
// model as the simulator's line (qr/boards/sim/serial_line.hpp), so both builds of the firmware
// see the same refusals. The bytes still in the buffer always follow each other back to back
// (one queued while the line was idle has gone by the time the next is queued after it), so the
// time the line is busy until says how many there are: no list of bytes is needed.
class PacedTransmitter {
 public:
  static constexpr uint32_t kCapacity = 32;
  // Whether a byte written at `now_ns` fits; if so it is counted as sent.
  bool accept(uint64_t now_ns);

 private:
  uint64_t line_free_ns_ = 0;  // when the last byte accepted is through
};

}  // namespace rv32virt
