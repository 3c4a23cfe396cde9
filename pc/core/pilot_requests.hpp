// What the pilot asks of the QR: a mode, the abort, and the control message. A mode that leaves
// safe is checked here first, so that a refusal says what to fix (the QR refuses it too) and a
// joystick whose position is unknown never takes off; while the simulator's radio flies, its
// switches take the request instead (radio_pilot.hpp).
#pragma once

#include <stdint.h>

#include <functional>
#include <optional>
#include <string>

#include <common/mode.hpp>
#include <common/requests.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/link_session.hpp>
#include <pc/core/pilot_controls.hpp>
#include <pc/core/pilot_input.hpp>
#include <pc/core/simulator_controls.hpp>
#include <pc/core/telemetry_model.hpp>

namespace qrterm {

class PilotRequests {
 public:
  using Note = std::function<void(Severity, const std::string&)>;

  PilotRequests(LinkSession& link, const TelemetryModel& telemetry, PilotControls& controls, const PilotInput& input,
                SimulatorControls& simulator, Note note)
      : link_(link), telemetry_(telemetry), controls_(controls), input_(input), simulator_(simulator),
        note_(std::move(note)) {}

  void mode(wire::Mode mode, uint32_t now_ms);
  // The motor test of one engine (0..3) at `level` (docs/safety.md rule 22), checked as leaving
  // safe is; false when not asked for (the reason is in the log).
  bool motor_test(uint8_t engine, uint16_t level, uint32_t now_ms);
  // Height hold is a toggle: the QR's mode as last heard says which way (it is entered from full
  // control, and left back to it).
  void toggle_height_hold(uint32_t now_ms);
  // ESC, the fire button, a lost joystick: panic, with the trims centred. With the line closed
  // nothing can be sent, and the log says what the QR does on its own.
  void abort(const std::string& why, bool line_closed, uint32_t now_ms);
  // The sticks and trims as they are now, to the QR.
  void send_control(uint32_t now_ms);
  const wire::Control& last_control() const { return last_control_; }
  // The QR's answer to the last mode change (reason none: ack).
  void on_mode_answer(wire::NackReason reason);
  // Who asked the QR for a panic in the last kPanicAskedMs, in the pilot's words: "the pilot (key
  // 0, safe from flight goes through panic)", "the pilot (ESC)", "the console (joystick lost)";
  // empty when nobody here did (the QR panicked by its own rules).
  std::string panic_asked_by(uint32_t now_ms) const;

 private:
  LinkSession& link_;
  const TelemetryModel& telemetry_;
  PilotControls& controls_;
  const PilotInput& input_;
  SimulatorControls& simulator_;
  Note note_;
  void asked_panic(std::string who, uint32_t now_ms);

  std::optional<wire::Mode> requested_;  // the last mode asked for, for its refusal
  wire::Control last_control_;
  std::string panic_asked_by_;
  uint32_t panic_asked_ms_ = 0;
};

// A panic the QR reports this long after the console asked for one is the one it asked for (the
// request is re-sent for 1 s at most, and the QR's mode is in every attitude report).
inline constexpr uint32_t kPanicAskedMs = 2000;

}  // namespace qrterm
