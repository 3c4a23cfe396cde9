#include <qr/sim_runner/full_line_console.hpp>

#include <algorithm>

#include <common/frame.hpp>
#include <qr/core/control_rate.hpp>
#include <qr/core/transmit_queue.hpp>
#include <qr/sim_runner/scoring.hpp>

namespace qrsim {
namespace {

constexpr uint64_t kPeriodNs = uint64_t{qr::kPeriodUs} * 1000;
// The console's sequence numbers: 1 to 63. The pilot numbers its own from 0x40 (Pilot), so an
// answer to one is never taken for the other's.
constexpr uint8_t kLastSeq = 0x3F;
// A telemetry_link report says what the QR had counted at the tick that composed it: no later
// than when the report's last byte was queued, and no earlier than everything the QR can hold
// ahead of it takes to drain (the firmware's 256-byte transmit queue and the board's 32-byte
// buffer) and a tick. A report with no frame arriving in that span before its last byte was
// queued (the line quiet, `link off`) tells exactly how many frames the QR should have counted.
constexpr uint64_t kReportLagNs = (qr::TransmitQueue::kBytes + SimBoard::kTransmitBuffer) * kByteTimeNs + kPeriodNs;

double ms(uint64_t ns) { return static_cast<double>(ns) * 1e-6; }

}  // namespace

uint64_t FullLineConsole::answer_bound_ns() {
  const uint64_t ack_bytes = wire::frame_length(*wire::message_spec(wire::MessageType::ack));
  return 2 * kPeriodNs + (SimBoard::kTransmitBuffer + ack_bytes) * kByteTimeNs;
}

FullLineConsole::FullLineConsole(SimBoard& board, Pilot& pilot) : board_(board), pilot_(pilot) {
  pilot_.on_bytes_up([this](uint8_t byte) { went_up(byte); });
  pilot_.on_every_frame([this](const wire::Frame& frame, const wire::LinkCounters&) { on_frame(frame); });
}

void FullLineConsole::set_full(bool full) {
  if (full == full_) return;
  full_ = full;
  if (full) {
    full_since_ns_ = now_ns();
    next_request_ns_ = full_since_ns_;
  } else {
    full_ns_ += now_ns() - full_since_ns_;
  }
}

void FullLineConsole::send(const wire::FrameBytes& frame) {
  for (uint8_t i = 0; i < frame.size; ++i) {
    board_.pc_send(frame.bytes[i]);
    went_up(frame.bytes[i]);
  }
}

void FullLineConsole::step() {
  if (!full_ || silent_) return;
  const uint64_t now = now_ns();
  if (now >= next_request_ns_) {
    next_request_ns_ += kRequestEveryNs;
    if (next_request_ns_ <= now) next_request_ns_ = now + kRequestEveryNs;  // after a silence: one, not a burst
    seq_ = static_cast<uint8_t>(seq_ == kLastSeq ? 1 : seq_ + 1);
    send(wire::encode(wire::ModeChange{seq_, pilot_.view().mode}));
    requests_.push_back({seq_, board_.to_qr_busy_until_ns()});
  }
  // Busy until the next period's step at least, so the line never idles in between.
  while (board_.to_qr_busy_until_ns() < now + kPeriodNs) send(wire::encode(pilot_.sticks()));
}

void FullLineConsole::went_up(uint8_t byte) {
  const uint64_t arrives = board_.to_qr_busy_until_ns();
  const uint64_t starts = arrives - kByteTimeNs;
  const uint64_t busy_to = std::max(last_byte_arrives_ns_, full_since_ns_);
  if (full_ && starts > busy_to) idle_ns_ += starts - busy_to;
  last_byte_arrives_ns_ = arrives;
  up_.push(byte, [&](const wire::Frame&) { frame_arrivals_ns_.push_back(arrives); });
}

void FullLineConsole::on_frame(const wire::Frame& frame) {
  const uint64_t arrived = board_.pc_last_arrived_ns();
  uint8_t seq = 0;
  bool answer = false;
  wire::Ack ack;
  wire::Nack nack;
  wire::TelemetryLink link;
  if (wire::decode(frame, ack) && ack.type == wire::MessageType::mode_change) {
    seq = ack.seq, answer = true;
  } else if (wire::decode(frame, nack) && nack.type == wire::MessageType::mode_change) {
    seq = nack.seq, answer = true;
  } else if (wire::decode(frame, link)) {
    reports_.push_back({link, board_.pc_last_sent_ns()});
  }
  if (!answer) return;
  // The latest unanswered request with that number (numbers come round every 6.3 s).
  for (auto r = requests_.rbegin(); r != requests_.rend(); ++r) {
    if (r->seq != seq) continue;
    if (r->answered_ns == 0) r->answered_ns = arrived;
    break;
  }
}

void FullLineConsole::add_figures(std::vector<Figure>& f) const {
  const uint64_t now = now_ns();
  const uint64_t full_ns = full_ns_ + (full_ ? now - full_since_ns_ : 0);
  f.push_back({"line_full_s", static_cast<double>(full_ns) * 1e-9});
  f.push_back({"line_idle_ms", ms(idle_ns_)});
  f.push_back({"line_frames_sent", static_cast<double>(frame_arrivals_ns_.size())});

  // The QR's count against the frames sent, at the last report composed while none arrived.
  double uncounted = kNotMeasured;
  const auto arrived_by = [&](uint64_t t) {
    return static_cast<size_t>(std::upper_bound(frame_arrivals_ns_.begin(), frame_arrivals_ns_.end(), t) -
                               frame_arrivals_ns_.begin());
  };
  for (auto r = reports_.rbegin(); r != reports_.rend(); ++r) {
    const size_t sent = arrived_by(r->sent_ns);
    if (r->sent_ns < kReportLagNs || arrived_by(r->sent_ns - kReportLagNs) != sent) continue;
    uncounted = static_cast<double>(static_cast<uint16_t>(sent - r->counters.frames_ok));  // the wire's u16
    break;
  }
  f.push_back({"line_frames_uncounted", uncounted});
  double faults = kNotMeasured;
  if (!reports_.empty()) {
    const wire::TelemetryLink& c = reports_.back().counters;
    faults = static_cast<double>(c.check_failures) + c.unknown_types + c.bytes_skipped + c.rx_overruns;
  }
  f.push_back({"line_rx_faults", faults});

  // The answers: a request not answered within the bound by the end of the run is unanswered.
  const uint64_t bound = answer_bound_ns();
  std::vector<uint64_t> delays;
  size_t unanswered = 0, late = 0;
  for (const Request& r : requests_) {
    if (r.answered_ns == 0) {
      if (r.reached_qr_ns + bound <= now) ++unanswered;
      continue;
    }
    delays.push_back(r.answered_ns - r.reached_qr_ns);
    if (delays.back() > bound) ++late;
  }
  std::sort(delays.begin(), delays.end());
  f.push_back({"line_requests", static_cast<double>(requests_.size())});
  f.push_back({"line_requests_unanswered", static_cast<double>(unanswered)});
  f.push_back({"line_answer_ms_median", delays.empty() ? kNotMeasured : ms(delays[delays.size() / 2])});
  f.push_back({"line_answer_ms_max", delays.empty() ? kNotMeasured : ms(delays.back())});
  f.push_back({"line_answer_bound_ms", ms(bound)});
  f.push_back({"line_answers_late", static_cast<double>(late)});
}

}  // namespace qrsim
