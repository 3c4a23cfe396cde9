#include <common/payload_codec.hpp>
#include <common/replies.hpp>
#include <common/request_dedup.hpp>
#include <common/requests.hpp>

namespace wire {

uint8_t request_seq(const Frame& frame) { return frame.length > 0 ? frame.payload[0] : 0; }

bool is_stop_request(const Frame& frame) {
  ModeChange m;
  return frame.type == MessageType::mode_change && decode(frame, m) && (m.mode == Mode::safe || m.mode == Mode::panic);
}

Admission RequestDedup::admit(const Frame& frame, uint32_t now_ms) {
  Admission admission;
  const uint8_t slot = ack_slot(frame.type);
  if (slot == kNoAckSlot || frame.length == 0) return admission;

  admission.request = true;
  admission.seq = request_seq(frame);
  Entry& e = entries_[slot];
  if (e.seen && e.request == frame && !is_stop_request(frame) && !reached(now_ms, e.last_seen_ms + kDedupWindowMs)) {
    admission.duplicate = true;
    admission.previous = e.answer;
    e.last_seen_ms = now_ms;  // each resend extends the window
    ++duplicates_;
  }
  return admission;
}

void RequestDedup::record(const Frame& frame, NackReason answer, uint32_t now_ms) {
  const uint8_t slot = ack_slot(frame.type);
  if (slot == kNoAckSlot || frame.length == 0) return;
  Entry& e = entries_[slot];
  e.seen = true;
  e.request = frame;
  e.answer = answer;
  e.last_seen_ms = now_ms;
}

FrameBytes reply_frame(MessageType type, uint8_t seq, NackReason answer) {
  if (answer == NackReason::none) return encode(Ack{type, seq});
  return encode(Nack{type, seq, answer});
}

}  // namespace wire
