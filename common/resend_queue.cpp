#include <common/resend_queue.hpp>

namespace wire {

ResendQueue::ResendQueue(uint8_t first_seq) {
  for (uint8_t& seq : next_seq_) seq = first_seq;
}

void ResendQueue::hold(uint8_t slot, uint8_t seq, const FrameBytes& frame, uint32_t now_ms) {
  Slot& s = slots_[slot];
  s.pending = true;
  s.seq = seq;
  s.sends = 1;
  s.last_sent_ms = now_ms;
  s.frame = frame;
}

AnswerMatch ResendQueue::answer(MessageType type, uint8_t seq) {
  const uint8_t slot = ack_slot(type);
  if (slot == kNoAckSlot || !slots_[slot].pending) return AnswerMatch::unexpected;
  if (slots_[slot].seq != seq) return AnswerMatch::stale;
  slots_[slot].pending = false;
  return AnswerMatch::matched;
}

AnswerMatch ResendQueue::on_ack(const Ack& ack) { return answer(ack.type, ack.seq); }

AnswerMatch ResendQueue::on_nack(const Nack& nack) { return answer(nack.type, nack.seq); }

bool ResendQueue::poll(uint32_t now_ms, ResendEvent& event) {
  for (uint8_t slot = 0; slot < kAckedTypeCount; ++slot) {
    Slot& s = slots_[slot];
    if (!s.pending || !reached(now_ms, s.last_sent_ms + kResendIntervalMs)) continue;

    event.type = acked_type_at(slot);
    event.seq = s.seq;
    event.frame = s.frame;
    if (s.sends >= kMaxSends) {
      s.pending = false;
      event.kind = ResendEvent::Kind::gave_up;
    } else {
      ++s.sends;
      s.last_sent_ms = now_ms;
      event.kind = ResendEvent::Kind::resend;
    }
    return true;
  }
  return false;
}

bool ResendQueue::pending(MessageType type) const {
  const uint8_t slot = ack_slot(type);
  return slot != kNoAckSlot && slots_[slot].pending;
}

bool ResendQueue::idle() const {
  for (const Slot& s : slots_) {
    if (s.pending) return false;
  }
  return true;
}

uint8_t ResendQueue::sends(MessageType type) const {
  const uint8_t slot = ack_slot(type);
  return slot != kNoAckSlot && slots_[slot].pending ? slots_[slot].sends : 0;
}

}  // namespace wire
