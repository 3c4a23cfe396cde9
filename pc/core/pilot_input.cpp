#include <pc/core/pilot_input.hpp>

#include <pc/core/key_map.hpp>

namespace qrterm {

CockpitKey PilotInput::cockpit_key(Key key) {
  const Action action = action_for(key);
  const bool second_escape = escape_armed_ && action == Action::abort;
  escape_armed_ = action == Action::abort && !second_escape;
  return {action, second_escape};
}

bool PilotInput::joystick_lost() {
  if (joystick_ != JoystickState::ok) return false;
  joystick_ = JoystickState::lost;
  position_known_ = false;
  return true;
}

bool PilotInput::joystick_back() {
  if (joystick_ != JoystickState::lost) return false;
  joystick_ = JoystickState::ok;
  return true;
}

std::string PilotInput::refuses_flight() const {
  if (joystick_ == JoystickState::lost) return "the joystick is gone (plug it back in, or restart with --no-joystick)";
  if (joystick_ == JoystickState::ok && !position_known_) return "the joystick has not reported its position yet";
  return "";
}

}  // namespace qrterm
