#include <pc/core/link_session.hpp>

namespace qrterm {
namespace {

// A device that takes no bytes (a dead adapter) must not make the console hoard stale controls:
// past this the oldest output is dropped. A few seconds of traffic at the full uplink rate.
constexpr size_t kMaxOutput = 32 * 1024;

}  // namespace

const char* link_state_name(LinkState state) {
  constexpr const char* kNames[] = {"waiting", "up", "LINK LOST", "closed"};
  return kNames[static_cast<size_t>(state)];
}

LinkSession::LinkSession(uint32_t now_ms, uint8_t first_seq)
    : queue_(first_seq), last_frame_ms_(now_ms), last_byte_ms_(now_ms), next_control_ms_(now_ms),
      rate_window_start_ms_(now_ms) {}

void LinkSession::note_frame(uint32_t now_ms) {
  last_frame_ms_ = now_ms;
  ever_up_ = true;
  ++frames_this_window_;
}

void LinkSession::housekeeping(uint32_t now_ms) {
  if (parser_.buffered() > 0 && now_ms - last_byte_ms_ >= kLineIdleMs) parser_.line_idle();
  if (now_ms - rate_window_start_ms_ >= 1000) {
    // A window that ran long (the caller was held up) still gives a per-second figure.
    const uint32_t window = now_ms - rate_window_start_ms_;
    figures_.frames_per_s = window < 2000 ? frames_this_window_ * 1000 / window : 0;
    frames_this_window_ = 0;
    rate_window_start_ms_ = now_ms;
  }
}

bool LinkSession::control_due(uint32_t now_ms) const { return wire::reached(now_ms, next_control_ms_); }

void LinkSession::send_control(const wire::Control& control, uint32_t now_ms) {
  put(wire::encode(control));
  // An extra one (before a mode request) leaves the 50 Hz schedule alone. The schedule advances
  // by whole periods, so the rate holds on average whatever the caller's tick; after a stall (a
  // suspended console) it restarts from now instead of sending a burst.
  if (!control_due(now_ms)) return;
  next_control_ms_ += wire::kControlPeriodMs;
  if (control_due(now_ms)) next_control_ms_ = now_ms + wire::kControlPeriodMs;
}

Answer LinkSession::match(wire::MessageType type, uint8_t sends, wire::AnswerMatch result, uint32_t now_ms) {
  Answer out{result, -1};
  // Only an answer to a request sent once times the round trip: after a resend there is no
  // telling which of the sends it answers.
  if (result == wire::AnswerMatch::matched && sends == 1) {
    out.round_trip_ms = static_cast<int32_t>(now_ms - sent_at_[wire::ack_slot(type)]);
    figures_.round_trip_ms = out.round_trip_ms;
  }
  return out;
}

Answer LinkSession::answer(const wire::Ack& ack, uint32_t now_ms) {
  const uint8_t sends = queue_.sends(ack.type);
  return match(ack.type, sends, queue_.on_ack(ack), now_ms);
}

Answer LinkSession::answer(const wire::Nack& nack, uint32_t now_ms) {
  const uint8_t sends = queue_.sends(nack.type);
  return match(nack.type, sends, queue_.on_nack(nack), now_ms);
}

LinkState LinkSession::state(uint32_t now_ms) const {
  if (closed_) return LinkState::closed;
  if (now_ms - last_frame_ms_ >= kLinkLostAfterMs) return LinkState::lost;
  return ever_up_ ? LinkState::up : LinkState::waiting;
}

void LinkSession::put(const wire::FrameBytes& frame) {
  if (output_.size() + frame.size > kMaxOutput) output_.clear();
  output_.insert(output_.end(), frame.bytes, frame.bytes + frame.size);
  ++figures_.frames_sent;
}

}  // namespace qrterm
