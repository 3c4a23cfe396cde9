// The console's record of an identification flight (mode autotune, docs/signal-chain.md,
// "Autotune: the identification flight"). The line carries about two observables at the control
// rate (docs/protocol.md section 13.4), not the six the three axes need, so the QR's stream 0
// carries the excited axis' pair, its moment and its rate, and the console moves it to the next
// axis' pair during that axis' half second of quiet: the console's clock picks the moment of the
// switch (from the mode's first report, with room on both sides), the QR's counters place the
// samples (a sample's number in its stream: one control period apart, gaps counted from the
// frames' counter) and time the mode (the attitude reports' tick, one per telemetry period).
// An axis' record is its samples from its quiet part through its bits: at most one axis' worth
// (kAxisTicks) of the stream that started in its quiet part. A mode that ended before its 9.12 s
// (a stick, tilt, battery) or a lost sample keeps nothing.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <array>
#include <optional>
#include <string>

#include <common/mode.hpp>
#include <tune/identification_design.hpp>

namespace qrterm {

// The sequence's timing at the QR's control rate (qr/core/chain/identification.hpp).
struct IdentificationTiming {
  uint32_t control_hz = 1000;
  uint32_t quiet_ticks() const { return control_hz / 2; }
  uint32_t axis_ticks() const { return quiet_ticks() + 127 * (control_hz / 50); }
  uint32_t ticks() const { return 3 * axis_ticks(); }
};

// The pair of observables (names in the QR's table) that carries each axis: moment, then rate.
struct AxisPair {
  const char* moment;
  const char* rate;
};
inline constexpr AxisPair kAxisPairs[3] = {{"roll_moment", "p"}, {"pitch_moment", "q"}, {"yaw_moment", "r"}};

// From the mode's first report, the next axis' pair is asked for this far into its quiet part:
// the report reaches the console a telemetry period or two after the QR entered the mode, and the
// new stream must run before the bits start at 500 ms.
inline constexpr uint32_t kSwitchIntoQuietMs = 100;

class IdentificationRecorder {
 public:
  enum class State : uint8_t { idle, recording, recorded, failed };

  explicit IdentificationRecorder(uint32_t control_hz = 1000) { timing_.control_hz = control_hz; }
  void set_control_hz(uint32_t control_hz) {
    if (state_ != State::recording) timing_.control_hz = control_hz;
  }

  // Every attitude report: its mode and tick (one per telemetry period), at the console's time.
  void on_mode(wire::Mode mode, uint8_t tick, uint32_t telemetry_hz, uint32_t now_ms);
  // The axis whose pair the stream should carry now; empty when not recording.
  std::optional<size_t> streamed_axis(uint32_t now_ms) const;
  // One sample of axis `axis`'s stream: `index` its number in that stream (QR control periods
  // since the stream started, lost samples included), the moment in thrust units, the rate in rad/s.
  void on_sample(size_t axis, uint32_t index, double moment, double rate);
  // The pilot has the result: the recorder waits for the next identification.
  void clear();

  State state() const { return state_; }
  // Why the last identification kept nothing; "" otherwise.
  const std::string& why() const { return why_; }
  // The three records (roll, pitch, yaw), moment and rate filled; valid in State::recorded.
  const std::array<tune::AxisRecord, 3>& records() const { return records_; }
  const IdentificationTiming& timing() const { return timing_; }

 private:
  void fail(const std::string& why);
  void finish(uint32_t periods, uint32_t telemetry_hz);

  IdentificationTiming timing_;
  State state_ = State::idle;
  std::string why_;
  bool in_autotune_ = false;  // the last report's mode was autotune
  uint32_t start_ms_ = 0;
  uint8_t last_tick_ = 0;
  uint32_t periods_ = 0;  // telemetry periods since the mode's first report
  std::array<tune::AxisRecord, 3> records_;
  std::array<uint32_t, 3> next_index_{};  // the sample number each axis' stream should send next
};

}  // namespace qrterm
