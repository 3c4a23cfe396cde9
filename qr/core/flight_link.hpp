// The link task of qr::Flight (a template, so its member definitions live in a header): the bytes
// the scheduler put in the receive rings, from the PC's line (frames, applied by
// flight_requests.hpp and answered) and from the radio's receiver (the sticks and switches when
// the radio flies); the sticks to the chain's set-points; the one door (Flight::change_modes,
// flight.hpp), opened once the tick's frames are read; then what the link owes the PC: parameter
// reports, the log's status and download parts. Include flight.hpp.
#pragma once

#include <qr/core/flight.hpp>
#include <qr/core/flight_requests.hpp>

namespace qr {

template <SignalChain Chain>
void Flight<Chain>::run_link() {
  // Most ticks bring no byte on either line, no new sticks and owe no report: the work of each
  // is out of line, so such a tick only checks (and does not save the registers that work needs).
  if (!rx_.empty()) receive_link_bytes();
  // A frame's bytes come within a millisecond; after 50 ms of silence what the parser holds is
  // the start of a frame whose sender stopped (docs/protocol.md, section 4).
  if (parser_.buffered() != 0 && tick_us_ - last_byte_us_ > 50000u) parser_.line_idle();
  if (!radio_rx_.empty()) receive_radio_bytes();

  if (pilot_changed_) take_sticks();
  change_modes();  // the one door (flight.hpp): what this tick's frames and switches changed

  if (log_status_owed_ || report_next_ < report_end_) send_owed_reports();
  if (log_.downloading()) send_download_parts();  // the check here: the parts' work is out of line
}

// The set-points change only with the sticks (or a parameter that scales them).
template <SignalChain Chain>
[[gnu::noinline]] void Flight<Chain>::take_sticks() {
  pilot_changed_ = false;
  chain_.set_pilot(controls_);
}

// Reports a request asked for: the log's status, and the parameters owed to a param_get, one per
// tick, so a full report never crowds out telemetry or replies. Out of line, as the bytes' work
// is: most ticks owe nothing, and only check.
template <SignalChain Chain>
[[gnu::noinline]] void Flight<Chain>::send_owed_reports() {
  if (log_status_owed_) {
    log_status_owed_ = false;
    send(wire::encode(log_.status()));
  }
  if (report_next_ < report_end_ && tx_.space() >= wire::kMaxFrameBytes) {
    const wire::ParameterLimits& spec = wire::kParameterLimits[report_next_++];
    send(wire::encode(wire::ParamReport{static_cast<uint8_t>(spec.id), params_.get(spec.id)}));
  }
}

template <SignalChain Chain>
[[gnu::noinline]] void Flight<Chain>::receive_link_bytes() {
  uint8_t byte = 0;
  while (rx_.pop(byte)) {
    last_byte_us_ = tick_us_;
    parser_.push(byte, [this](const wire::Frame& frame) { on_frame(frame); });
  }
}

template <SignalChain Chain>
[[gnu::noinline]] void Flight<Chain>::receive_radio_bytes() {
  uint8_t radio_bytes[decltype(radio_rx_)::kCapacity];
  const size_t radio_count = radio_rx_.pop(radio_bytes, sizeof radio_bytes);
  radio_.push(radio_bytes, radio_count, tick_us_, [this](const drivers::RcSticks& sticks) { on_radio_sticks(sticks); });
}

template <SignalChain Chain>
void Flight<Chain>::on_frame(const wire::Frame& frame) {
  const wire::Admission admission = dedup_.admit(frame, uptime_ms_);
  if (admission.duplicate) {
    last_frame_us_ = tick_us_;  // the resend decoded when it was first applied
    send_answer(wire::reply_frame(frame.type, admission.seq, admission.previous));
    return;
  }
  FlightRequests<Flight> handler{*this};
  const wire::DispatchResult result = wire::dispatch<wire::PcToQrMessages>(frame, handler);
  // Only a frame whose every field is in range proves the console alive: a console sending
  // nothing but out-of-range controls flies on no sticks at all and ends in the link-loss panic
  // (docs/safety.md), not in a flight on the last good ones.
  if (result != wire::DispatchResult::invalid_payload) last_frame_us_ = tick_us_;
  if (!admission.request) return;  // control: periodic, never answered

  const NackReason answer = result == wire::DispatchResult::handled           ? handler.answer
                            : result == wire::DispatchResult::invalid_payload ? NackReason::bad_value
                                                                              : NackReason::not_supported;
  dedup_.record(frame, answer, uptime_ms_);
  send_answer(wire::reply_frame(frame.type, admission.seq, answer));
  if (handler.report.id != 0) send(wire::encode(handler.report));
}

// An RC frame's sticks and switches, when the radio is the pilot: the controls as a control frame
// would set them, then the switches (arming, the emergency stop: docs/safety.md rule 17).
template <SignalChain Chain>
void Flight<Chain>::on_radio_sticks(const drivers::RcSticks& sticks) {
  if (pilot_ != Pilot::radio) return;
  controls_ = ControlInput{sticks.lift, sticks.roll, sticks.pitch, sticks.yaw};
  pilot_changed_ = true;
  safety_.sticks_moved(controls_);
  Situation s = situation();
  s.requester = Pilot::radio;
  safety_.radio_switches(sticks.arm, wire::mode_at_switch(sticks.mode_position), s);
}

// Parts of a download while the link has room for them next to a telemetry period's frames.
template <SignalChain Chain>
[[gnu::noinline]] void Flight<Chain>::send_download_parts() {
  // Parts queue only this deep: more than the line sends in a period (11.5 bytes at 1 kHz, 23 at
  // 500 Hz), so it never idles, but an ack queued behind them leaves within a few ms. A deeper
  // queue (the whole ring) held acks 20 ms, and a bad line's log_resend requests, one out at a
  // time, could not keep up with the parts it lost.
  constexpr size_t kPartBacklog = 48;
  log_.send_parts(4, [this](const wire::FrameBytes& frame) {
    if (tx_.size() + size_t{frame.size} > kPartBacklog) return false;
    send(frame);
    return true;
  });
}

}  // namespace qr
