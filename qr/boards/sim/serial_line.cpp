#include <qr/boards/sim/serial_line.hpp>

#include <algorithm>

namespace qrsim {

bool SerialLine::send(uint8_t byte, uint64_t now_ns) {
  if (in_flight(now_ns) >= capacity_) {
    ++bytes_refused_;
    return false;
  }
  line_free_ns_ = std::max(line_free_ns_, now_ns) + kByteTimeNs;
  bytes_.push_back({byte, now_ns, line_free_ns_});
  ++bytes_sent_;
  return true;
}

bool SerialLine::receive(uint64_t now_ns, uint8_t& byte) {
  if (bytes_.empty() || bytes_.front().arrives_ns > now_ns) return false;
  byte = bytes_.front().value;
  taken_arrived_ns_ = bytes_.front().arrives_ns;
  taken_sent_ns_ = bytes_.front().sent_ns;
  bytes_.pop_front();
  return true;
}

bool SerialLine::next_sent_at(uint64_t& sent_ns) const {
  if (bytes_.empty()) return false;
  sent_ns = bytes_.front().sent_ns;
  return true;
}

size_t SerialLine::in_flight(uint64_t now_ns) const {
  // Bytes already arrived but not yet taken by the receiver sit in its receive buffer, not in
  // the sender's transmit buffer. Those still on their way follow each other back to back (one
  // queued while an earlier one was on its way goes straight after it), the first of them less
  // than a byte time from arriving, so the time the line is busy until says how many there are.
  // Counted one by one, a console sending at the full rate into a simulator that had fallen
  // behind cost a walk over the whole backlog per byte, and the simulator fell further behind.
  if (line_free_ns_ <= now_ns) return 0;
  return static_cast<size_t>((line_free_ns_ - now_ns + kByteTimeNs - 1) / kByteTimeNs);
}

}  // namespace qrsim
