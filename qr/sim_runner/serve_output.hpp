// Serve mode's way out to the console: the QR's bytes that have reached the console's end of the
// simulated line, written to the pty (or stdout) without ever waiting for the reader.
//
// A console that has closed its port, or never reads, must not stop the world: a blocking write
// into a full pty (about 17 kB, some 9 s of telemetry) held the simulation still, a vehicle landing
// from 30 m hung in the air. Here the bytes are gathered into whole frames (the message table gives
// each type's length), written while the descriptor takes them, and when it takes no more the
// queue holds at most kQueueBytes: a newer frame then pushes the oldest whole frames out, counted.
// A frame already partly written is always finished first, so the reader never gets half a frame
// followed by another (its parser would find its way anyway, on the 'M' of the next).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <deque>

#include <common/frame.hpp>

namespace qrsim {

class ServeOutput {
 public:
  // About 44 ms of the line's bytes: a console that reads at all empties it long before.
  static constexpr size_t kQueueBytes = 512;

  // A byte the QR sent, arrived at the console's end of the line.
  void put(uint8_t byte);
  // Writes what `fd` takes now, never waiting. When it fails for another reason than being full
  // (EPIPE: the reader of stdout has gone) the queue is dropped, counted, as a wire with nobody at
  // its end loses what it carries.
  void write_to(int fd);
  // The QR has stopped: a frame it left unfinished is queued as far as it goes.
  void finish();

  size_t queued_bytes() const { return queued_bytes_; }
  uint64_t frames_dropped() const { return frames_dropped_; }
  uint64_t bytes_dropped() const { return bytes_dropped_; }
  uint64_t frames_written() const { return frames_written_; }

 private:
  // A frame, or a byte that starts none (only a damaged stream has those).
  struct Unit {
    uint8_t bytes[wire::kMaxFrameBytes];
    uint8_t size;
  };
  void queue(const Unit& unit);
  void drop(size_t index);

  std::deque<Unit> units_;
  size_t queued_bytes_ = 0;
  uint8_t head_written_ = 0;    // bytes of units_.front() already written
  Unit partial_{{}, 0};         // the frame being gathered
  uint8_t partial_length_ = 0;  // its length, once its type byte is in (0 before)
  uint64_t frames_dropped_ = 0;
  uint64_t bytes_dropped_ = 0;
  uint64_t frames_written_ = 0;
};

}  // namespace qrsim
