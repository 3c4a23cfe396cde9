// The pilot's input devices as the console sees them: a cockpit key's action (key_map.hpp), with
// ESC's pairing (the first aborts, a second in a row exits), and the joystick's presence (none,
// there, lost) and whether its position is known yet. A joystick whose position is unknown, or
// that went away, must never let the QR leave safe.
#pragma once

#include <stdint.h>

#include <string>

#include <pc/core/action.hpp>
#include <pc/core/key.hpp>

namespace qrterm {

enum class JoystickState : uint8_t {
  none,  // keyboard only (--no-joystick)
  ok,
  lost,  // it was there and went away
};

struct CockpitKey {
  Action action;       // Action::none: the key does nothing
  bool second_escape;  // ESC after ESC: exit
};

class PilotInput {
 public:
  explicit PilotInput(bool joystick) : joystick_(joystick ? JoystickState::ok : JoystickState::none) {}

  // A key the screens did not take.
  CockpitKey cockpit_key(Key key);
  // A key the screens took: it breaks an ESC pair.
  void screen_key() { escape_armed_ = false; }

  JoystickState joystick() const { return joystick_; }
  bool position_known() const { return position_known_; }
  void joystick_moved(bool position_known) { position_known_ = position_known; }
  // True when it was there: the caller centres its sticks and stops a flight on it.
  bool joystick_lost();
  // True when it had been lost.
  bool joystick_back();
  // Why the joystick keeps the QR in safe, for the pilot; empty when it does not.
  std::string refuses_flight() const;

 private:
  JoystickState joystick_;
  bool position_known_ = false;
  bool escape_armed_ = false;  // the last key was ESC: another one exits
};

}  // namespace qrterm
