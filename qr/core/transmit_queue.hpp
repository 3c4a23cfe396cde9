// What the QR has queued for the serial line, in two lanes: answers to requests (ack, nack) and
// everything else (telemetry, reports, debug text, log parts, samples). The line takes whole
// frames, answers first: an answer waits for nothing but the rest of a frame already on its way
// and the board's transmit buffer, whatever telemetry, a log download or a stream has queued
// (docs/devboard.md, "The ground line": every request answered within two control periods).
// Through one queue, an answer made while a download's parts or a telemetry period filled the
// ring waited behind them all.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <common/byte_ring.hpp>
#include <common/frame.hpp>

namespace qr {

class TransmitQueue {
 public:
  // Bytes the other frames may take: a telemetry period's frames plus replies, with room to spare.
  static constexpr size_t kBytes = 256;
  // Bytes for answers: a tick answers at most the few requests a period of the line can carry.
  static constexpr size_t kAnswerBytes = 32;

  // A frame in the other lane, whole or not at all.
  bool push(const wire::FrameBytes& frame) { return push_to(bytes_, sizes_, frame); }
  // An answer, ahead of the other lane; in it when the answers' lane is full (never lost for that).
  bool push_answer(const wire::FrameBytes& frame) { return push_to(answers_, answer_sizes_, frame) || push(frame); }

  // The next byte for the line, and taking it: the frame part-way out goes on, else an answer.
  bool peek(uint8_t& byte) const { return answering() ? answers_.peek(byte) : bytes_.peek(byte); }
  void pop() {
    if (left_ == 0) {
      from_answers_ = !answers_.empty();
      uint8_t size = 0;
      if (!(from_answers_ ? answer_sizes_.pop(size) : sizes_.pop(size))) return;
      left_ = size;
    }
    if (from_answers_) {
      answers_.drop();
    } else {
      bytes_.drop();
    }
    --left_;
  }

  bool empty() const { return bytes_.empty() && answers_.empty(); }
  // The other lane's fill and room, for the senders that keep a backlog bounded.
  size_t size() const { return bytes_.size(); }
  size_t space() const { return bytes_.space(); }

 private:
  template <class Ring, class Sizes>
  static bool push_to(Ring& ring, Sizes& sizes, const wire::FrameBytes& frame) {
    if (sizes.space() == 0 || !ring.push(frame.bytes, frame.size)) return false;
    sizes.push(frame.size);
    return true;
  }
  bool answering() const { return left_ == 0 ? !answers_.empty() : from_answers_; }

  // Each lane's bytes and, one a frame, its frames' sizes (a frame has at least 3 bytes).
  wire::ByteRing<kBytes> bytes_;
  wire::ByteRing<kBytes / 2> sizes_;
  wire::ByteRing<kAnswerBytes> answers_;
  wire::ByteRing<kAnswerBytes / 2> answer_sizes_;
  uint8_t left_ = 0;  // bytes of the frame part-way out still to go; 0 between frames
  bool from_answers_ = false;
};

}  // namespace qr
