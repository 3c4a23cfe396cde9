// One direction of the QR's serial line at 115200 baud, 8N1: ten bit times per byte, so a byte
// takes 86.8 µs and the line moves 11.52 bytes per ms. The sender's bytes wait in its transmit
// buffer and go out one after the other; each reaches the far end when its last bit has, and
// not before. Time is in nanoseconds of simulated time (the 0.0005 % a whole-ns byte time is
// off by does not matter over any flight).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <deque>

#include <common/link_timing.hpp>

namespace qrsim {

inline constexpr uint32_t kBaud = wire::kLineBaud;
inline constexpr uint64_t kByteTimeNs = wire::kLineByteTimeNs;  // 86 806 ns

class SerialLine {
 public:
  // `capacity`: bytes the sender's transmit buffer holds (not yet fully on the wire).
  explicit SerialLine(size_t capacity) : capacity_(capacity) {}

  // The sender queues one byte at `now_ns`; false when its transmit buffer is full.
  bool send(uint8_t byte, uint64_t now_ns);
  // The receiver takes the next byte that has fully arrived by `now_ns`.
  bool receive(uint64_t now_ns, uint8_t& byte);
  // When the byte receive() would give next was queued by the sender (to time-stamp frames).
  bool next_sent_at(uint64_t& sent_ns) const;
  // When the byte receive() gave last had fully arrived, and when it was queued: a frame's times
  // to the byte, though the receiver takes bytes only once a control period.
  uint64_t last_taken_arrived_ns() const { return taken_arrived_ns_; }
  uint64_t last_taken_sent_ns() const { return taken_sent_ns_; }
  // When the byte send() queued last will have fully arrived (0 before any).
  uint64_t busy_until_ns() const { return line_free_ns_; }

  size_t in_flight(uint64_t now_ns) const;       // queued, not yet arrived
  bool empty() const { return bytes_.empty(); }  // nothing queued or waiting to be taken
  uint64_t bytes_sent() const { return bytes_sent_; }
  uint64_t bytes_refused() const { return bytes_refused_; }

 private:
  struct Byte {
    uint8_t value;
    uint64_t sent_ns;     // when the sender queued it
    uint64_t arrives_ns;  // when its stop bit is through
  };
  size_t capacity_;
  std::deque<Byte> bytes_;
  uint64_t line_free_ns_ = 0;  // when the last queued byte is through
  uint64_t bytes_sent_ = 0;
  uint64_t bytes_refused_ = 0;
  uint64_t taken_arrived_ns_ = 0;
  uint64_t taken_sent_ns_ = 0;
};

}  // namespace qrsim
