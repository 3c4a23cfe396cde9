#include <pc/core/pilot_requests.hpp>

#include <pc/core/mode_names.hpp>
#include <pc/core/request_texts.hpp>

namespace qrterm {

void PilotRequests::mode(wire::Mode mode, uint32_t now_ms) {
  const bool leaving_safe = mode != wire::Mode::safe && mode != wire::Mode::panic;
  const bool in_safe = !telemetry_.attitude || telemetry_.attitude->mode == wire::Mode::safe;
  if (leaving_safe && in_safe) {
    std::string reason = input_.refuses_flight();
    if (reason.empty()) reason = controls_.not_neutral_reason();
    if (!reason.empty()) {
      note_(Severity::warning, std::string("not asking for ") + mode_name(mode) + ": " + reason);
      return;
    }
  }
  if (simulator_.take_mode_request(mode, in_safe, telemetry_)) return;
  const bool flying = telemetry_.attitude && is_flight_mode(telemetry_.attitude->mode);
  note_(Severity::info,
        std::string("asking for mode ") + mode_name(mode) +
            (mode == wire::Mode::safe && flying ? " (from flight through panic: the engines ramp down first)" : ""));
  requested_ = mode;
  if (mode == wire::Mode::panic) asked_panic("the pilot (key 1)", now_ms);
  if (mode == wire::Mode::safe && flying) asked_panic("the pilot (key 0, safe from flight goes through panic)", now_ms);
  // The QR judges "neutral" by the last control it received, which may be up to 20 ms old: a
  // pilot who centres the trims and at once asks for a mode would be refused. A control message
  // with the sticks as they are now goes first; frames arrive in order.
  send_control(now_ms);
  link_.request(wire::ModeChange{0, mode}, now_ms);
}

bool PilotRequests::motor_test(uint8_t engine, uint16_t level, uint32_t now_ms) {
  std::string reason = input_.refuses_flight();
  if (reason.empty()) reason = controls_.not_neutral_reason();
  if (!reason.empty()) {
    note_(Severity::warning, "not asking for the motor test: " + reason);
    return false;
  }
  note_(Severity::info, "motor test: engine " + std::to_string(engine + 1) + " at " + std::to_string(level / 10) +
                            " % for 2 s (any key stops it)");
  send_control(now_ms);  // the QR judges the lift by the last control it received, as for a mode
  link_.request(wire::MotorTest{0, engine, level}, now_ms);
  return true;
}

void PilotRequests::toggle_height_hold(uint32_t now_ms) {
  const bool holding = telemetry_.attitude && telemetry_.attitude->mode == wire::Mode::height_hold;
  mode(holding ? wire::Mode::full_control : wire::Mode::height_hold, now_ms);
}

void PilotRequests::abort(const std::string& why, bool line_closed, uint32_t now_ms) {
  // The pilot's inputs are centred too: the QR lands in safe, and leaving safe again needs them
  // neutral anyway; a lift trim left standing would be the first surprise of the next flight.
  const bool trimmed = controls_.trims() != Sticks{};
  controls_.apply(Action::trims_center);
  if (line_closed) {
    // Nothing can reach the QR: say what it does on its own instead of promising a request.
    note_(Severity::error, "ABORT (" + why + "): the line is gone, nothing can be sent; the QR panics by itself " +
                               "after the link timeout without a frame (safety rule 7)");
    return;
  }
  note_(Severity::error, "ABORT (" + why + "): panic requested" + (trimmed ? ", trims centred" : ""));
  requested_ = wire::Mode::panic;
  // The pilot's keys and button, or the console's own rule (a joystick lost in flight).
  asked_panic(why == "joystick lost" ? "the console (joystick lost)" : "the pilot (" + why + ")", now_ms);
  link_.request(wire::ModeChange{0, wire::Mode::panic}, now_ms);
}

void PilotRequests::send_control(uint32_t now_ms) {
  last_control_ = controls_.control();
  link_.send_control(last_control_, now_ms);
}

void PilotRequests::on_mode_answer(wire::NackReason reason) {
  if (reason == wire::NackReason::none) return;
  const std::string mode = requested_ ? mode_name(*requested_) : "?";
  note_(Severity::warning, "QR refused mode " + mode + ": " + reason_text(reason));
}

void PilotRequests::asked_panic(std::string who, uint32_t now_ms) {
  panic_asked_by_ = std::move(who);
  panic_asked_ms_ = now_ms;
}

std::string PilotRequests::panic_asked_by(uint32_t now_ms) const {
  if (panic_asked_by_.empty() || now_ms - panic_asked_ms_ > kPanicAskedMs) return {};
  return panic_asked_by_;
}

}  // namespace qrterm
