// The console's end of the simulator's truth channel (docs/simulator.md section 5): the hand of
// the person at the desk (a push, set down upright, turned for the gyro's scale, tilted for the
// orientation check), the simulated
// radio's switches, and the truth lines that come back. Only a QR the console started in qrsim has
// one; on a real QR each of these keys says so and does nothing.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <common/mode.hpp>
#include <pc/core/action.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/plot_model.hpp>
#include <pc/core/task_figures.hpp>
#include <pc/core/telemetry_model.hpp>

namespace qrterm {

class SimulatorControls {
 public:
  using Note = std::function<void(Severity, const std::string&)>;

  // `present`: the console started qrsim and has its truth channel.
  SimulatorControls(bool present, Note note) : present_(present), note_(std::move(note)) {}

  bool present() const { return present_; }

  // The simulator's keys (push, reset, turn, the radio's arm switch off); false for any other.
  bool act(Action action);

  // The orientation check's hand (orientation_check.hpp): it tilts the QR 45 deg the positive
  // way about body axis `axis` (0 x, 1 y, 2 z), holds it and sets it down as it was, in 1 s
  // (`tilt x 45 1`). False, and nothing sent, without a simulator: a person's hand does it.
  bool hand_tilt(size_t axis);

  // A mode request while the simulator's radio flies (radio_pilot.hpp): the pilot's hand on the
  // transmitter moves its switches instead. True when it was the radio's to take, done or refused.
  bool take_mode_request(wire::Mode mode, bool in_safe, const TelemetryModel& telemetry);

  // A line from the truth channel at `now_ms`: a truth line is kept for the screen and returned
  // for the plot (rad, m, m/s); an error line or the reset's answer goes to the log.
  std::optional<PlotModel::TrueState> on_line(const std::string& line, uint32_t now_ms);

  // Command lines for the truth channel, taken once; the main loop writes them.
  std::vector<std::string> take_commands();

  // "truth roll +1.2 pitch -0.5 yaw +10.0 height 1.50 m", or empty: no line yet.
  const std::string& truth() const { return truth_; }
  // Each rotor's speed in the last truth line, rad/s, front, right, back, left, positive clockwise
  // seen from above; empty before a line that has them.
  const std::optional<std::array<double, 4>>& rotors() const { return rotors_; }
  // The devboard's clock and the tick's instructions, from the simulator's "devboard" line (once
  // a second while qrsim --devboard flies); empty before one, and for the host build.
  const std::optional<DevboardFigures>& devboard() const { return devboard_; }
  // The simulator's clock on the console's (ms to add to a QR time): from the truth lines, the
  // smallest difference seen, so the one that waited least on its way. Empty without truth lines.
  std::optional<int64_t> clock_offset_ms() const { return clock_offset_ms_; }

 private:
  void turn();
  void take_devboard(const std::string& line);

  bool present_;
  Note note_;
  std::string truth_;
  std::optional<std::array<double, 4>> rotors_;
  std::optional<int64_t> clock_offset_ms_;
  std::optional<DevboardFigures> devboard_;
  std::vector<std::string> commands_;
  int next_turn_axis_ = 0;  // the y key's next axis: z, x, y
};

}  // namespace qrterm
