// The devboard's ground UART held to the line's pace, both ways (docs/devboard.md, "The ground
// line").
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

// The receiving end of the same line: a byte is taken from the UART no sooner than one byte time
// after the one before it, as from a 16550 at 115200 baud with its 16-byte FIFO. QEMU fills the
// UART from the console's pty as fast as its main loop runs, and after the host has held QEMU up
// it hands over the whole backlog at once, faster than any line could; taken at the line's pace
// the backlog waits (nothing is lost) instead of overrunning the firmware's receive ring.
// A backlog is the host's doing, not the line's, and at the line's pace it would never shrink
// while the console sends at the full rate: every answer after it would be late by as much. So
// while one waits (`behind`), bytes are taken at twice the pace, 23 a period at 1 kHz, within
// the 32 the scheduler reads a tick, until it is gone.
class PacedReceiver {
 public:
  static constexpr uint32_t kFifoBytes = 16;  // the 16550's receive FIFO
  // Whether a byte may be taken at `now_ns`, at the line's pace or, `behind`, twice that; if so it
  // is counted as taken.
  bool take(uint64_t now_ns, bool behind);

 private:
  uint64_t next_ns_ = 0;  // the earliest time the next byte can have come down the line
};

}  // namespace rv32virt
