// The sending side of acknowledged requests (PC -> QR: mode change, parameters, log commands,
// exit). It holds the latest request of each acknowledged type, stamps it with that type's next
// sequence number, and hands it out again every kResendIntervalMs until an ack or a nack with the
// same type and number arrives, or until kMaxSends sends have gone unanswered.
//
// One request per type: a new request of a type replaces the pending one (the newer mode or log
// command is the one that matters); an ack for the replaced one is then recognised as stale by
// its sequence number and ignored. A caller that must deliver every request of a type (e.g. a
// parameter upload) submits the next one when pending(type) is false.
#pragma once

#include <stdint.h>

#include <common/frame.hpp>
#include <common/link_timing.hpp>
#include <common/message_table.hpp>
#include <common/nack_reason.hpp>
#include <common/payload_codec.hpp>
#include <common/replies.hpp>

namespace wire {

enum class AnswerMatch : uint8_t {
  matched,     // answered the pending request of that type: it is no longer pending
  stale,       // a request of that type is pending but with another sequence number: ignored
  unexpected,  // nothing of that type is pending (already answered, given up, never sent)
};

struct ResendEvent {
  enum class Kind : uint8_t { resend, gave_up };
  Kind kind = Kind::resend;
  MessageType type = MessageType::mode_change;
  uint8_t seq = 0;
  FrameBytes frame;  // resend: the bytes to send now; gave_up: the request that went unanswered
};

class ResendQueue {
 public:
  // Sequence numbers of every type start at first_seq; a console may start from a value of its
  // clock so that a quick restart does not repeat the numbers the QR saw last.
  explicit ResendQueue(uint8_t first_seq = 0);

  // Stamps the request with its type's next sequence number, keeps it for resending, and returns
  // the frame to send now.
  template <Message Request>
  FrameBytes submit(Request request, uint32_t now_ms) {
    static_assert(message_spec(Request::kType)->acked, "only acknowledged requests are queued");
    const uint8_t slot = ack_slot(Request::kType);
    request.seq = next_seq_[slot];
    next_seq_[slot] = static_cast<uint8_t>(next_seq_[slot] + 1);
    const FrameBytes frame = encode(request);
    hold(slot, request.seq, frame, now_ms);
    return frame;
  }

  AnswerMatch on_ack(const Ack& ack);
  AnswerMatch on_nack(const Nack& nack);

  // Reports one due event: a resend to transmit now, or a request given up (shown to the user).
  // Call until it returns false, once per pass of the caller's loop.
  bool poll(uint32_t now_ms, ResendEvent& event);

  bool pending(MessageType type) const;
  bool idle() const;
  // Sends so far of the pending request of `type` (0 when none is pending).
  uint8_t sends(MessageType type) const;

 private:
  struct Slot {
    bool pending = false;
    uint8_t seq = 0;
    uint8_t sends = 0;
    uint32_t last_sent_ms = 0;
    FrameBytes frame;
  };

  void hold(uint8_t slot, uint8_t seq, const FrameBytes& frame, uint32_t now_ms);
  AnswerMatch answer(MessageType type, uint8_t seq);

  Slot slots_[kAckedTypeCount];
  uint8_t next_seq_[kAckedTypeCount] = {};
};

}  // namespace wire
