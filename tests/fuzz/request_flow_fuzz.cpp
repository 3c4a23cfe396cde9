// Fuzz target: the resend queue and the request dedup driven by an arbitrary script of submits,
// answers (right, stale or for other types), duplicates and clock jumps. Checks that a request is
// never sent more than kMaxSends times, given up only after that, never resent after its answer,
// and that the dedup only ever calls a request a duplicate when its number was seen last.
#include <stddef.h>
#include <stdint.h>

#include <common/messages.hpp>
#include <common/request_dedup.hpp>
#include <common/resend_queue.hpp>

namespace {

void require(bool condition) {
  if (!condition) __builtin_trap();
}

wire::FrameBytes submit(wire::ResendQueue& queue, uint8_t which, uint8_t value, uint32_t now) {
  switch (which % wire::kAckedTypeCount) {
    case 0: return queue.submit(wire::ModeChange{0, static_cast<wire::Mode>(value % wire::kModeCount)}, now);
    case 1: return queue.submit(wire::ParamSet{0, value, value}, now);
    case 2: return queue.submit(wire::ParamGet{0, value}, now);
    case 3: return queue.submit(wire::LogStart{0, static_cast<uint8_t>(value % 3 + 1)}, now);
    case 4: return queue.submit(wire::LogStop{}, now);
    case 5: return queue.submit(wire::LogDownload{0, wire::LogKind::sensor, value, value}, now);
    case 6: return queue.submit(wire::ObservableGet{0, value}, now);
    case 7:
      return queue.submit(wire::StreamRequest{0,
                                              static_cast<uint8_t>(value % wire::kStreamCount),
                                              value,
                                              {value, wire::kNoObservable, wire::kNoObservable, wire::kNoObservable}},
                          now);
    case 8: return queue.submit(wire::LogResend{0, wire::LogKind::telemetry, value, {value, value, 0, 0, value}}, now);
    case 9:
      return queue.submit(wire::MotorTest{0, static_cast<uint8_t>(value % 4),
                                          static_cast<uint16_t>(value % (wire::kMotorTestMaxLevel + 1))},
                          now);
    case 10:
      return queue.submit(wire::EscDirection{0, static_cast<uint8_t>(value % 4), static_cast<uint8_t>(value % 2 + 1)},
                          now);
    default: return queue.submit(wire::Exit{}, now);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  wire::ResendQueue queue(size > 0 ? data[0] : 0);
  wire::RequestDedup dedup;
  uint32_t now = 0xFFFFF000u;  // close to the wrap, so it is crossed
  wire::FrameBytes last_sent[wire::kAckedTypeCount] = {};
  bool answered[wire::kAckedTypeCount] = {};
  uint8_t last_recorded_seq[wire::kAckedTypeCount] = {};
  bool recorded[wire::kAckedTypeCount] = {};

  for (size_t i = 1; i + 2 < size; i += 3) {
    const uint8_t op = data[i], a = data[i + 1], b = data[i + 2];
    const uint8_t slot = static_cast<uint8_t>(a % wire::kAckedTypeCount);
    const wire::MessageType type = wire::acked_type_at(slot);
    switch (op % 5) {
      case 0: {  // a new request
        const wire::FrameBytes frame = submit(queue, a, b, now);
        require(frame.size > 0);
        const uint8_t s = wire::ack_slot(wire::find_message(frame.bytes[1])->type);
        last_sent[s] = frame;
        answered[s] = false;
        require(queue.pending(wire::acked_type_at(s)) && queue.sends(wire::acked_type_at(s)) == 1);
        break;
      }
      case 1: {  // an answer, with the right number or not
        const uint8_t seq = (b & 1) != 0 && last_sent[slot].size > 0 ? last_sent[slot].bytes[2] : b;
        const wire::AnswerMatch m = (b & 2) != 0 ? queue.on_ack(wire::Ack{type, seq})
                                                 : queue.on_nack(wire::Nack{type, seq, wire::NackReason::busy});
        if (m == wire::AnswerMatch::matched) {
          require(last_sent[slot].size > 0 && seq == last_sent[slot].bytes[2] && !answered[slot]);
          answered[slot] = true;
        }
        require(!queue.pending(type) || !answered[slot]);
        break;
      }
      case 2: {  // time passes; collect what is due
        now += static_cast<uint32_t>(a) * 16u + b;
        wire::ResendEvent event;
        int events = 0;
        while (queue.poll(now, event)) {
          require(++events <= wire::kAckedTypeCount);
          const uint8_t s = wire::ack_slot(event.type);
          require(s != wire::kNoAckSlot && !answered[s]);
          require(event.frame == last_sent[s] && event.seq == last_sent[s].bytes[2]);
          if (event.kind == wire::ResendEvent::Kind::resend) require(queue.sends(event.type) <= wire::kMaxSends);
          if (event.kind == wire::ResendEvent::Kind::gave_up) require(!queue.pending(event.type));
        }
        break;
      }
      default: {  // the QR side sees the last frame of that type (maybe again)
        if (last_sent[slot].size == 0) break;
        wire::Frame frame;
        frame.type = type;
        frame.length = wire::find_message(wire::type_byte(type))->payload_length;
        for (uint8_t k = 0; k < frame.length; ++k) frame.payload[k] = last_sent[slot].bytes[2 + k];
        const wire::Admission adm = dedup.admit(frame, now);
        require(adm.request && adm.seq == frame.payload[0]);
        if (adm.duplicate) require(recorded[slot] && last_recorded_seq[slot] == adm.seq);
        else {
          dedup.record(frame, wire::NackReason::none, now);
          recorded[slot] = true;
          last_recorded_seq[slot] = adm.seq;
        }
        break;
      }
    }
  }
  return 0;
}
