// The console's end of the wire: bytes in through the frame parser, requests out through the
// resend queue, control out at 50 Hz, and the figures that tell the pilot how healthy the link is.
// It knows nothing of what the messages mean; the Console does. Time comes in from the caller in
// ms (a wrapping counter), so tests run it on a scripted clock.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <vector>

#include <common/frame_parser.hpp>
#include <common/link_timing.hpp>
#include <common/messages.hpp>
#include <common/resend_queue.hpp>

namespace qrterm {

// No valid frame for this long and the screen says LINK LOST (the IN4073 console's 2 s).
inline constexpr uint32_t kLinkLostAfterMs = 2000;
// Silence after which kept bytes of a cut-off frame are dropped (docs/protocol.md section 4).
inline constexpr uint32_t kLineIdleMs = 50;

enum class LinkState : uint8_t {
  waiting,  // no valid frame yet, for less than kLinkLostAfterMs
  up,
  lost,    // no valid frame for kLinkLostAfterMs
  closed,  // the serial line itself is gone (device unplugged, simulator ended)
};

const char* link_state_name(LinkState state);

struct LinkFigures {
  uint32_t frames_per_s = 0;  // valid frames received in the last whole second
  uint32_t frames_sent = 0;
  uint32_t resends = 0;
  uint32_t gave_up = 0;        // requests never answered
  int32_t round_trip_ms = -1;  // last request answered after its first send; -1: none yet
};

struct Answer {
  wire::AnswerMatch match = wire::AnswerMatch::unexpected;
  int32_t round_trip_ms = -1;  // for a match on the first send; -1 otherwise
};

class LinkSession {
 public:
  LinkSession(uint32_t now_ms, uint8_t first_seq);

  // Bytes from the QR; calls on_frame(const wire::Frame&) for every valid frame among them.
  template <class OnFrame>
  void receive(const uint8_t* data, size_t count, uint32_t now_ms, OnFrame&& on_frame) {
    if (count > 0) last_byte_ms_ = now_ms;
    for (size_t i = 0; i < count; ++i) {
      parser_.push(data[i], [&](const wire::Frame& frame) {
        note_frame(now_ms);
        on_frame(frame);
      });
    }
  }

  // Queues a request for sending (now, and again until answered); returns its sequence number.
  template <wire::Message Request>
  uint8_t request(const Request& request, uint32_t now_ms) {
    const wire::FrameBytes frame = queue_.submit(request, now_ms);
    sent_at_[wire::ack_slot(Request::kType)] = now_ms;
    put(frame);
    return frame.bytes[2];  // payload byte 0 of every request is its seq
  }

  // True when a control message is due (every kControlPeriodMs); the caller then sends one.
  bool control_due(uint32_t now_ms) const;
  // Sends one now: the one due, or an extra one.
  void send_control(const wire::Control& control, uint32_t now_ms);

  Answer answer(const wire::Ack& ack, uint32_t now_ms);
  Answer answer(const wire::Nack& nack, uint32_t now_ms);

  // Puts due resends into the output; calls on_gave_up(const wire::ResendEvent&) for each request
  // given up. Also drops a half frame after kLineIdleMs of silence and rolls the rate counter.
  template <class OnGaveUp>
  void poll(uint32_t now_ms, OnGaveUp&& on_gave_up) {
    housekeeping(now_ms);
    wire::ResendEvent event;
    while (queue_.poll(now_ms, event)) {
      if (event.kind == wire::ResendEvent::Kind::resend) {
        ++figures_.resends;
        put(event.frame);
      } else {
        ++figures_.gave_up;
        on_gave_up(static_cast<const wire::ResendEvent&>(event));
      }
    }
  }

  // The serial line is gone: nothing will come in any more.
  void close() { closed_ = true; }

  LinkState state(uint32_t now_ms) const;
  // Since the last valid frame (or since the start, before the first one).
  uint32_t silence_ms(uint32_t now_ms) const { return now_ms - last_frame_ms_; }
  bool ever_up() const { return ever_up_; }
  bool pending(wire::MessageType type) const { return queue_.pending(type); }

  const LinkFigures& figures() const { return figures_; }
  const wire::LinkCounters& counters() const { return parser_.counters(); }

  // Bytes to write to the serial line, oldest first; the caller writes what it can.
  std::vector<uint8_t>& output() { return output_; }

 private:
  void note_frame(uint32_t now_ms);
  void housekeeping(uint32_t now_ms);
  void put(const wire::FrameBytes& frame);
  Answer match(wire::MessageType type, uint8_t sends, wire::AnswerMatch result, uint32_t now_ms);

  wire::FrameParser parser_{wire::Listen::qr_to_pc};
  wire::ResendQueue queue_;
  uint32_t last_frame_ms_;
  uint32_t last_byte_ms_;
  uint32_t next_control_ms_;
  uint32_t rate_window_start_ms_;
  uint32_t frames_this_window_ = 0;
  bool ever_up_ = false;
  bool closed_ = false;
  uint32_t sent_at_[wire::kAckedTypeCount] = {};
  LinkFigures figures_;
  std::vector<uint8_t> output_;
};

}  // namespace qrterm
