// The devboard's ground UART held to the line's pace (docs/devboard.md, "The sensor link").
#pragma once

#include <stdint.h>

namespace rv32virt {

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
