// Member definitions of qr::Flight (a template, so they live in a header): the safety task, the
// debug text, telemetry's flags, the logger and stream tasks, a turn measurement's end. The link
// task's are flight_link.hpp's. Include flight.hpp.
#pragma once

#include <qr/core/chain/sensor_calibration.hpp>
#include <qr/core/chain/sign_check.hpp>
#include <qr/core/flight.hpp>
#include <qr/core/flight_log_lines.hpp>

namespace qr {

template <SignalChain Chain>
void Flight<Chain>::run_safety() {
  const Situation s = situation();
  safety_.supervise(s);
  engines_ = safety_.limit_engines(wanted_, s);
  if (safety_.mode() != announced_mode_) announce_mode();
  report_sensor_faults();
}

// Which sensor and which fault, when its drivers count new ones (sensor_fault_report.hpp: at most
// a line a second per sensor). Boards without drivers report none: their counts stay 0.
template <SignalChain Chain>
void Flight<Chain>::report_sensor_faults() {
  if ((sample_.health.imu_faults | sample_.health.barometer_faults) == 0) return;
  say_sensor_faults();
}

template <SignalChain Chain>
[[gnu::noinline]] void Flight<Chain>::say_sensor_faults() {
  char line[kSensorReportChars];
  if (fault_report_.due(sample_.health, tick_us_, line)) say(line);
}

// A new mode on the debug text.
template <SignalChain Chain>
[[gnu::noinline]] void Flight<Chain>::announce_mode() {
  const Mode now = safety_.mode();
  announced_mode_ = now;
  say("mode: ");
  say(wire::mode_name(now));
  if (now == Mode::panic) {
    say(" (");
    say(kPanicCauseNames[static_cast<uint8_t>(safety_.panic_cause())]);
    if (safety_.panic_cause() == PanicCause::wrong_sign) {
      say(": ");
      say(chain::kSignAxisNames[static_cast<uint8_t>(chain_.wrong_sign())]);
    }
    say(")");
  }
  say("\n");
}

// How a bench's ESC direction ended: "ESC 3: spin direction 2, saved", or not set.
template <SignalChain Chain>
[[gnu::noinline]] void Flight<Chain>::say_esc_direction(bool saved) {
  char line[] = "ESC 0: spin direction 0";
  line[4] = static_cast<char>('1' + esc_direction_.engine());
  line[22] = static_cast<char>('0' + esc_direction_.direction());
  say(line);
  say(saved ? ", saved\n" : " not set (an engine turned, or no DShot ESC took it)\n");
}

// A calibration that refused its offsets, or whose sign probe found a loop pushing its error
// further (rule 21), says so and names the axis: the pilot's next request would be refused.
template <SignalChain Chain>
[[gnu::noinline]] void Flight<Chain>::say_calibration_verdict() {
  if (const auto axis = static_cast<uint8_t>(chain_.calibration_refused()); axis != 0) {
    say("calibration refused: the accelerometer's ");
    say(chain::kCalibrationAxisNames[axis]);
    say(" reads gravity: level the vehicle, or check the IMU's mounting\n");
  } else if (const auto sign = static_cast<uint8_t>(chain_.wrong_sign()); sign != 0) {
    say("sign check: the ");
    say(chain::kSignAxisNames[sign]);
    say(" loop pushes its error further: flight modes refused\n");
  }
}

template <SignalChain Chain>
uint8_t Flight<Chain>::telemetry_flags() const {
  uint8_t flags = 0;
  if (chain_.calibrated()) flags |= wire::kFlagCalibrated;
  if (log_.logging()) flags |= wire::kFlagLogging;
  if (safety_.battery_warning()) flags |= wire::kFlagBatteryWarning;
  if (log_.full()) flags |= wire::kFlagLogFull;
  if (!chain_.landed()) flags |= wire::kFlagFlying;
  return flags;
}

// A line in each running log (the row's rate is log_divider).
template <SignalChain Chain>
void Flight<Chain>::run_logger() {
  if (log_.logging()) log_.write(sensor_log_line(*this), telemetry_log_line(*this), chain_);
}

// Observable samples that are due, and a row of the observable table when one is owed and the
// line has room for it beside a telemetry period (the same reserve as log downloads keep).
template <SignalChain Chain>
void Flight<Chain>::run_stream() {
  if constexpr (!kObservableStreams) return;
  if (streams_.idle()) return;
  constexpr size_t kTxReserve = 64;
  streams_.run(
      *this, kControlHz, [this](const wire::FrameBytes& frame) { send(frame); },
      [this](uint32_t bytes) { return tx_.space() >= bytes + kTxReserve; });
}

// A turn measurement's end (gyro_turns.hpp): a found scale becomes its axis' parameter, the turns
// go back to 0 (the next calibration is one at rest again), and the console is told both.
template <SignalChain Chain>
[[gnu::noinline]] void Flight<Chain>::take_gyro_turns(const chain::GyroTurnsResult& turns) {
  using wire::ParamId;
  static constexpr ParamId kScale[3] = {ParamId::gyro_scale_x_ppm, ParamId::gyro_scale_y_ppm,
                                        ParamId::gyro_scale_z_ppm};
  static constexpr const char* kFound[3] = {"gyro turns: x scale set\n", "gyro turns: y scale set\n",
                                            "gyro turns: z scale set\n"};
  if (turns.found) params_.set(static_cast<uint8_t>(kScale[turns.axis]), turns.ppm);
  params_.set(static_cast<uint8_t>(ParamId::gyro_turns), 0);
  apply_parameters();
  say(turns.found ? kFound[turns.axis] : "gyro turns: no turn of the count asked for, scales unchanged\n");
  // The rows gyro_scale_x_ppm .. gyro_turns, with any reports still owed.
  const uint8_t first = static_cast<uint8_t>(ParamId::gyro_scale_x_ppm) - 1;
  const uint8_t end = static_cast<uint8_t>(ParamId::gyro_turns);
  if (report_next_ >= report_end_ || report_next_ > first) report_next_ = first;
  if (report_end_ < end) report_end_ = end;
}

template <SignalChain Chain>
void Flight<Chain>::say(const char* text) {
  while (*text != '\0') {
    wire::DebugText piece;
    text += piece.fill(text, wire::kDebugTextChars);
    send(wire::encode(piece));
  }
}

}  // namespace qr
