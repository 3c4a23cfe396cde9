#include <qr/sim_runner/preflight.hpp>

#include <common/messages.hpp>
#include <qr/sim_runner/pilot.hpp>

namespace qrsim {
namespace {

// After power-up the pilot waits this long for the sensors to settle before anything goes up.
constexpr double kSensorsSettleS = 0.3;

}  // namespace

bool Preflight::step(double t, wire::Mode mode, Pilot& pilot) {
  switch (stage_) {
    case Stage::power_up:
      if (t < kSensorsSettleS) break;
      upload(pilot);
      if (plan_.calibrate_with_upload) ask(wire::Mode::calibration, pilot);
      stage_ = Stage::calibrate;
      break;
    case Stage::calibrate:
      if (!calibration_asked_ && !pilot.request_pending(wire::MessageType::mode_change)) {
        ask(wire::Mode::calibration, pilot);
      }
      calibrating_seen_ = calibrating_seen_ || mode == wire::Mode::calibration;
      if (calibration_refused(mode, pilot)) {
        stage_ = Stage::refused;
        break;
      }
      if (!calibrated_on_ground(mode, pilot)) break;
      if (!plan_.arm) {
        stage_ = Stage::ready;
        break;
      }
      if (plan_.log_from_arming) pilot.request(wire::LogStart{0, wire::kLogTelemetry});
      ask(wire::Mode::full_control, pilot);
      stage_ = Stage::arm;
      break;
    case Stage::arm:
      if (mode == wire::Mode::full_control) stage_ = Stage::ready;
      break;
    case Stage::ready:
    case Stage::refused: break;
  }
  return stage_ == Stage::ready;
}

const char* Preflight::stage_name() const {
  static const char* const kNames[] = {"power up", "calibration", "arming", "ready", "calibration refused"};
  return kNames[static_cast<int>(stage_)];
}

void Preflight::upload(Pilot& pilot) const {
  for (const auto& [id, raw] : plan_.parameters) pilot.set_parameter(id, raw);
  if (plan_.radio) {
    pilot.set_parameter(wire::ParamId::pilot, 1);
    pilot.use_radio();
  }
}

void Preflight::ask(wire::Mode mode, Pilot& pilot) {
  if (mode == wire::Mode::calibration) {
    calibration_asked_ = true;
    text_at_ask_ = pilot.view().debug_text.size();
    nacks_at_ask_ = pilot.view().nacks;
  }
  requested_ = mode;
  pilot.request_mode(mode);
}

// Calibrated and back in safe, with nothing the pilot sent still waiting for its ack: armed
// before its parameters are in, the QR would fly the defaults; and a mode request still being
// resent could reach the QR after the arming request.
bool Preflight::calibrated_on_ground(wire::Mode mode, const Pilot& pilot) const {
  const ConsoleView& view = pilot.view();
  return view.heard && (view.flags & wire::kFlagCalibrated) != 0 && mode == wire::Mode::safe &&
         !pilot.request_pending(wire::MessageType::param_set) && !pilot.request_pending(wire::MessageType::mode_change);
}

// Back in safe from the calibration it asked for, and the QR said it refused it (Flight's
// say_calibration_verdict): the flag alone could lag the mode on a damaged line. Or never in it:
// the request answered with a NACK (the pre-flight's parameters are in range: a NACK is the
// calibration's).
bool Preflight::calibration_refused(wire::Mode mode, const Pilot& pilot) const {
  const ConsoleView& view = pilot.view();
  if (mode != wire::Mode::safe || (view.flags & wire::kFlagCalibrated) != 0) return false;
  if (!calibrating_seen_) {
    return calibration_asked_ && view.nacks > nacks_at_ask_ && !pilot.request_pending(wire::MessageType::mode_change);
  }
  return view.debug_text.find("calibration refused", text_at_ask_) != std::string::npos;
}

}  // namespace qrsim
