// What the QR has queued for the serial line: whole frames, in order, except that an answer to a
// request (ack, nack) goes in ahead of everything queued before it, at the first frame boundary:
// after the frame already on its way and any answers queued before it. So an answer waits for
// nothing but that frame and the board's transmit buffer, whatever telemetry, a log download or
// a stream has queued (docs/devboard.md, "The ground line": every request answered within two
// control periods). Through one plain queue an answer made during a download waited behind the
// parts past that bound.
//
// The line takes bytes as from a plain ring (peek, pop: nothing more per byte). The frames'
// sizes are kept so an answer can find the boundary; the answer's insertion moves the bytes
// behind it, a few hundred instructions at most and only when a request is answered.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/frame.hpp>

namespace qr {

class TransmitQueue {
 public:
  // A telemetry period's frames plus replies, with room to spare.
  static constexpr uint32_t kBytes = 256;

  // A frame at the end, whole or not at all.
  bool push(const wire::FrameBytes& frame) {
    if (!room_for(frame.size)) return false;
    for (uint8_t i = 0; i < frame.size; ++i) bytes_[(head_ + i) & kMask] = frame.bytes[i];
    head_ += frame.size;
    sizes_[size_head_++ & kSizeMask] = frame.size;
    return true;
  }
  // An answer, ahead of every frame not yet begun but behind the answers queued before it.
  bool push_answer(const wire::FrameBytes& frame) {
    if (!room_for(frame.size)) return false;
    // From the first frame not wholly sent: past one part-way out, then past the answers ahead.
    uint32_t at = front_start_;
    uint32_t index = size_tail_;
    if (index != size_head_ && before(at, tail_)) at += sizes_[index++ & kSizeMask];
    while (index != size_head_ && before(at, answers_end_)) at += sizes_[index++ & kSizeMask];
    // Everything from `at` on moves back by the answer's size; its size goes in at `index`.
    for (uint32_t i = head_; i != at;) {
      --i;
      bytes_[(i + frame.size) & kMask] = bytes_[i & kMask];
    }
    for (uint8_t i = 0; i < frame.size; ++i) bytes_[(at + i) & kMask] = frame.bytes[i];
    head_ += frame.size;
    for (uint32_t i = size_head_; i != index; --i) sizes_[i & kSizeMask] = sizes_[(i - 1) & kSizeMask];
    sizes_[index & kSizeMask] = frame.size;
    ++size_head_;
    answers_end_ = at + frame.size;
    return true;
  }

  bool peek(uint8_t& byte) const {
    if (head_ == tail_) return false;
    byte = bytes_[tail_ & kMask];
    return true;
  }
  void pop() {
    if (head_ != tail_) ++tail_;
  }

  bool empty() const { return head_ == tail_; }
  uint32_t size() const { return head_ - tail_; }
  uint32_t space() const { return kBytes - size(); }

 private:
  static constexpr uint32_t kMask = kBytes - 1;
  // A frame has at least 3 bytes: the ring holds fewer than half as many frames as bytes.
  static constexpr uint32_t kSizes = kBytes / 2;
  static constexpr uint32_t kSizeMask = kSizes - 1;
  static_assert((kBytes & kMask) == 0, "a power of two");

  // a is before b on the free-running counters.
  static bool before(uint32_t a, uint32_t b) { return static_cast<int32_t>(a - b) < 0; }

  // Room for `n` bytes; the sizes of frames wholly sent are let go on the way.
  bool room_for(uint8_t n) {
    while (size_tail_ != size_head_ && !before(tail_, front_start_ + sizes_[size_tail_ & kSizeMask]))
      front_start_ += sizes_[size_tail_++ & kSizeMask];
    return n <= space() && size_head_ - size_tail_ < kSizes;
  }

  uint8_t bytes_[kBytes] = {};
  uint32_t head_ = 0, tail_ = 0;  // free-running: their difference is the fill
  uint8_t sizes_[kSizes] = {};    // the size of every frame not yet let go, in line order
  uint32_t size_head_ = 0, size_tail_ = 0;
  uint32_t front_start_ = 0;  // where the frame at size_tail_ starts
  uint32_t answers_end_ = 0;  // where the answers put ahead end
};

}  // namespace qr
