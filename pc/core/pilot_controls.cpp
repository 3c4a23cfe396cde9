#include <pc/core/pilot_controls.hpp>

#include <algorithm>

#include <common/units.hpp>

namespace qrterm {
namespace {

struct TrimStep {
  Action action;
  int32_t Sticks::*axis;
  int32_t step;
};

constexpr TrimStep kTrimSteps[] = {
    {Action::lift_up, &Sticks::lift, kLiftTrimStep},
    {Action::lift_down, &Sticks::lift, -kLiftTrimStep},
    {Action::lift_up_coarse, &Sticks::lift, kLiftCoarseStep},
    {Action::lift_down_coarse, &Sticks::lift, -kLiftCoarseStep},
    {Action::roll_right, &Sticks::roll, kStickTrimStep},
    {Action::roll_left, &Sticks::roll, -kStickTrimStep},
    {Action::pitch_up, &Sticks::pitch, kStickTrimStep},
    {Action::pitch_down, &Sticks::pitch, -kStickTrimStep},
    {Action::yaw_right, &Sticks::yaw, kStickTrimStep},
    {Action::yaw_left, &Sticks::yaw, -kStickTrimStep},
};

constexpr int32_t kLiftMax = wire::kLiftMax;
constexpr int32_t kStickMax = wire::kStickMax;

int16_t stick(int32_t value) { return static_cast<int16_t>(std::clamp(value, -kStickMax, kStickMax)); }

}  // namespace

bool PilotControls::apply(Action action) {
  if (action == Action::trims_center) {
    trims_ = Sticks{};
    return true;
  }
  for (const TrimStep& trim : kTrimSteps) {
    if (trim.action != action) continue;
    int32_t& value = trims_.*trim.axis;
    const bool lift = trim.axis == &Sticks::lift;
    value = std::clamp(value + trim.step, lift ? 0 : -kStickMax, lift ? kLiftMax : kStickMax);
    return true;
  }
  return false;
}

int32_t PilotControls::set_lift(int32_t lift) {
  trims_.lift = std::clamp(lift - joystick_.lift, 0, kLiftMax);
  return control().lift;
}

wire::Control PilotControls::control() const {
  wire::Control c;
  c.lift = static_cast<uint16_t>(std::clamp(joystick_.lift + trims_.lift, 0, kLiftMax));
  c.roll = stick(joystick_.roll + trims_.roll);
  c.pitch = stick(joystick_.pitch + trims_.pitch);
  c.yaw = stick(joystick_.yaw + trims_.yaw);
  return c;
}

std::string PilotControls::not_neutral_reason() const {
  std::string reason;
  const auto note = [&reason](bool off, const char* what) {
    if (!off) return;
    if (!reason.empty()) reason += ", ";
    reason += what;
  };
  note(joystick_.lift != 0, "joystick throttle not at zero");
  note(joystick_.roll != 0 || joystick_.pitch != 0 || joystick_.yaw != 0, "joystick stick or twist not centred");
  note(trims_ != Sticks{}, "keyboard trims not zero (c centres them)");
  return reason;
}

Notice lift_to_hover(PilotControls& controls, uint16_t hover_lift) {
  // The QR reports its hover in engine units (FlightChain::hover_lift(): the engine command that
  // gives the learnt per-engine hover thrust). The lift stick is on the same scale: lift l asks
  // each engine for the thrust l^2 / 1000, which is engine command l (engine_mixer.hpp), so the
  // hover lift is the lift stick value that carries the vehicle, with no conversion
  // (HoverKey.TheHoverLiftIsTheLiftStickThatGivesTheHoverThrust holds the firmware to it).
  const int32_t before = controls.control().lift;
  if (hover_lift == 0) {
    return {Severity::warning,
            "no hover lift known yet: the QR learns it in flight, a few seconds flying slowly; lift stays " +
                std::to_string(before)};
  }
  const int32_t lift = controls.set_lift(hover_lift);
  if (lift == hover_lift) {
    return {Severity::info, "lift " + std::to_string(before) + " -> " + std::to_string(lift) +
                                ", the hover lift the QR learnt (more lift to stop a descent: PgUp)"};
  }
  return {Severity::warning, "the throttle alone gives lift " + std::to_string(lift) + ", above the hover lift " +
                                 std::to_string(hover_lift) + ": lift trim 0; close the throttle to reach the hover"};
}

}  // namespace qrterm
