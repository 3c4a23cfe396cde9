// A fixed-size byte FIFO for serial lines: one side pushes, the other pops. No locks: on the QR
// the UART interrupt is the only pusher of the receive ring and the main loop the only popper.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace wire {

template <size_t Capacity>
class ByteRing {
  static_assert(Capacity > 0 && (Capacity & (Capacity - 1)) == 0, "capacity is a power of two");

 public:
  static constexpr size_t kCapacity = Capacity;

  size_t size() const { return static_cast<size_t>(head_ - tail_); }
  size_t space() const { return Capacity - size(); }
  bool empty() const { return head_ == tail_; }

  bool push(uint8_t byte) {
    if (space() == 0) return false;
    bytes_[head_ & kMask] = byte;
    ++head_;
    return true;
  }
  // All of `n` bytes or none: a frame is never half queued.
  bool push(const uint8_t* data, size_t n) {
    if (n > space()) return false;
    // Room for all was checked once: each byte is a copy, not another check (every frame the QR
    // sends comes this way).
    size_t head = head_;
    for (size_t i = 0; i < n; ++i) bytes_[head++ & kMask] = data[i];
    head_ = head;
    return true;
  }
  bool peek(uint8_t& byte) const {
    if (empty()) return false;
    byte = bytes_[tail_ & kMask];
    return true;
  }
  bool pop(uint8_t& byte) {
    if (!peek(byte)) return false;
    ++tail_;
    return true;
  }
  // Up to `max` bytes into `out`, oldest first; how many.
  size_t pop(uint8_t* out, size_t max) {
    size_t n = 0;
    for (; n < max && !empty(); ++n) out[n] = bytes_[tail_++ & kMask];
    return n;
  }
  void drop() {
    if (!empty()) ++tail_;
  }

 private:
  static constexpr size_t kMask = Capacity - 1;
  // Free-running counters: their difference is the fill level even after they wrap.
  size_t head_ = 0;
  size_t tail_ = 0;
  uint8_t bytes_[Capacity] = {};
};

}  // namespace wire
