// What the pilot asks for: the joystick's position plus the keyboard's trims, clamped to the
// wire's ranges. The IN4073 way: keys add to the stick rather than replace it, so a pilot can fly
// the joystick and correct a drift with a few presses.
#pragma once

#include <string>

#include <common/requests.hpp>
#include <pc/core/action.hpp>
#include <pc/core/console_log.hpp>
#include <pc/core/sticks.hpp>

namespace qrterm {

// How far one key press moves a trim, per mille of full deflection.
inline constexpr int32_t kLiftTrimStep = 10;
// A hover needs some 530 of lift: 53 presses of the fine step; the coarse keys take ten at a time.
inline constexpr int32_t kLiftCoarseStep = 10 * kLiftTrimStep;
inline constexpr int32_t kStickTrimStep = 10;

class PilotControls {
 public:
  // A trim action (lift/roll/pitch/yaw up/down, centre): applies it and returns true. Any other
  // action is not ours: false.
  bool apply(Action action);

  // The lift trim set so that joystick plus trim gives `lift` (the hover key), as far as the trim's
  // range 0..1000 allows: a throttle already above `lift` leaves the trim at 0. Returns the lift
  // that goes out now.
  int32_t set_lift(int32_t lift);

  void set_joystick(const Sticks& sticks) { joystick_ = sticks; }
  const Sticks& joystick() const { return joystick_; }
  const Sticks& trims() const { return trims_; }

  // Joystick plus trims, clamped: what goes out in the next control message.
  wire::Control control() const;

  // Leaving safe needs neutral controls (docs/safety.md rule 3). Empty when neutral; otherwise
  // what is not, and what to do about it, for the pilot.
  std::string not_neutral_reason() const;

 private:
  Sticks joystick_;
  Sticks trims_;
};

// The hover key (Home): the lift to the hover lift the QR learnt (`hover_lift`, 0: none yet), and
// what the log says about it.
Notice lift_to_hover(PilotControls& controls, uint16_t hover_lift);

}  // namespace qrterm
