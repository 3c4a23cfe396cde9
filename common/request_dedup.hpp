// The receiving side of acknowledged requests (on the QR). Requests are re-sent until answered, so
// the same request can arrive several times; it must take effect once. For each request type the
// dedup remembers the last request seen (its whole payload: sequence number and content) and the
// answer given to it. A request equal to it in every byte within kDedupWindowMs is a resend: it is
// answered again, with the same answer, and not applied again. A request that reuses the sequence
// number with other content is a new request (a console restarted part-way through its numbers
// must never be told "ack" for something that was not done).
//
// Stops (a mode change to safe or panic) are never treated as resends: they are applied every
// time they arrive. Applying one twice changes nothing, and the pilot's stop is then in force
// whatever the dedup remembers.
//
//   const Admission a = dedup.admit(frame, now_ms);
//   if (a.duplicate) send(reply_frame(frame.type, a.seq, a.previous));
//   else { NackReason r = apply(frame); dedup.record(frame, r, now_ms); send(reply_frame(frame.type, a.seq, r)); }
#pragma once

#include <stdint.h>

#include <common/frame.hpp>
#include <common/link_timing.hpp>
#include <common/message_table.hpp>
#include <common/nack_reason.hpp>

namespace wire {

struct Admission {
  bool request = false;    // the frame is an acknowledged request (else: nothing to dedup)
  bool duplicate = false;  // already applied: answer with `previous`, do not apply
  uint8_t seq = 0;
  NackReason previous = NackReason::none;  // the answer given the first time (none: an ack)
};

class RequestDedup {
 public:
  Admission admit(const Frame& frame, uint32_t now_ms);

  // Remembers the answer given to a request just applied (NackReason::none for an ack).
  void record(const Frame& frame, NackReason answer, uint32_t now_ms);

  uint32_t duplicates() const { return duplicates_; }

 private:
  struct Entry {
    bool seen = false;
    Frame request;  // the whole request: type, length, payload (its first byte is the seq)
    NackReason answer = NackReason::none;
    uint32_t last_seen_ms = 0;
  };

  Entry entries_[kAckedTypeCount];
  uint32_t duplicates_ = 0;
};

// The request's sequence number: byte 0 of every acknowledged request's payload.
uint8_t request_seq(const Frame& frame);

// A mode change to safe or panic: applied every time it arrives, never answered from memory.
bool is_stop_request(const Frame& frame);

// An ack (answer none) or a nack with the reason, for request `type` number `seq`.
FrameBytes reply_frame(MessageType type, uint8_t seq, NackReason answer);

}  // namespace wire
