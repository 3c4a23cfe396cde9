#include <pc/core/identification_recorder.hpp>

#include <cstdio>

namespace qrterm {

void IdentificationRecorder::on_mode(wire::Mode mode, uint8_t tick, uint32_t telemetry_hz, uint32_t now_ms) {
  const bool autotune = mode == wire::Mode::autotune;
  const bool entered = autotune && !in_autotune_;
  in_autotune_ = autotune;
  if (state_ != State::recording) {
    // A record that failed mid-way waits for the mode's next entry.
    if (!entered) return;
    // The mode's first report: a new identification.
    state_ = State::recording;
    why_.clear();
    start_ms_ = now_ms;
    last_tick_ = tick;
    periods_ = 0;
    records_ = {};
    next_index_ = {};
    return;
  }
  periods_ += static_cast<uint8_t>(tick - last_tick_);
  last_tick_ = tick;
  if (!autotune) finish(periods_, telemetry_hz);
}

void IdentificationRecorder::finish(uint32_t periods, uint32_t telemetry_hz) {
  // The QR's own count of the mode's length: from its first report to its first report in another
  // mode, within a telemetry period of the sequence's length when the sequence ran to its end.
  const uint64_t sequence_periods = uint64_t{timing_.ticks()} * telemetry_hz / timing_.control_hz;
  if (telemetry_hz == 0 || uint64_t{periods} + 2 < sequence_periods) {
    const double seconds = telemetry_hz ? static_cast<double>(periods) / telemetry_hz : 0;
    char text[96];
    std::snprintf(text, sizeof text, "the identification ended after %.2f of its %.2f s: nothing kept", seconds,
                  static_cast<double>(timing_.ticks()) / timing_.control_hz);
    return fail(text);
  }
  // Each axis' stream started in its quiet part, so a whole record holds at least its bits.
  const uint32_t bits = timing_.axis_ticks() - timing_.quiet_ticks();
  for (size_t axis = 0; axis < 3; ++axis) {
    if (records_[axis].rate.size() < bits) {
      return fail(std::string("the ") + tune::kAxisNames[axis] + " record holds " +
                  std::to_string(records_[axis].rate.size()) + " samples, fewer than its " + std::to_string(bits) +
                  " bits' periods: nothing kept");
    }
  }
  state_ = State::recorded;
}

std::optional<size_t> IdentificationRecorder::streamed_axis(uint32_t now_ms) const {
  if (state_ != State::recording) return std::nullopt;
  const uint32_t axis_ms = timing_.axis_ticks() * 1000 / timing_.control_hz;
  const uint32_t since = now_ms - start_ms_;
  if (since < axis_ms + kSwitchIntoQuietMs) return 0;
  if (since < 2 * axis_ms + kSwitchIntoQuietMs) return 1;
  return 2;
}

void IdentificationRecorder::on_sample(size_t axis, uint32_t index, double moment, double rate) {
  if (state_ != State::recording || axis >= 3) return;
  if (index >= timing_.axis_ticks()) return;  // past the axis' worth: the next axis' quiet part or later
  if (index != next_index_[axis]) {
    return fail(std::to_string(index - next_index_[axis]) + " samples of the " + tune::kAxisNames[axis] +
                " record lost on the line: nothing kept");
  }
  ++next_index_[axis];
  records_[axis].moment.push_back(moment);
  records_[axis].rate.push_back(rate);
}

void IdentificationRecorder::clear() {
  state_ = State::idle;
  records_ = {};
}

void IdentificationRecorder::fail(const std::string& why) {
  state_ = State::failed;
  why_ = why;
  records_ = {};
}

}  // namespace qrterm
