#include <pc/core/joystick_reader.hpp>

namespace qrterm {

JoystickReader::ReadResult JoystickReader::read_from(int fd) {
  return stream_.read_from(fd, [this](const js_event& event) { feed(event); });
}

void JoystickReader::feed(const js_event& event) {
  const uint8_t type = event.type & static_cast<uint8_t>(~JS_EVENT_INIT);
  const bool initial = (event.type & JS_EVENT_INIT) != 0;
  if (type == JS_EVENT_AXIS && event.number < kMaxAxes) {
    axis_[event.number] = event.value;
    seen_[event.number] = true;
  } else if (type == JS_EVENT_BUTTON && event.number == map_.abort_button && event.value != 0 && !initial) {
    abort_pressed_ = true;
  }
}

int32_t JoystickReader::value(const AxisBinding& binding) const {
  return binding.axis < kMaxAxes ? axis_[binding.axis] : 0;
}

bool JoystickReader::seen(const AxisBinding& binding) const { return binding.axis < kMaxAxes && seen_[binding.axis]; }

Sticks JoystickReader::sticks() const {
  Sticks s;
  // A throttle not yet reported counts as closed, not as half open (its raw 0).
  s.lift = seen(map_.lift) ? map_.lift_of(value(map_.lift)) : 0;
  s.roll = map_.stick(map_.roll, value(map_.roll));
  s.pitch = map_.stick(map_.pitch, value(map_.pitch));
  s.yaw = map_.stick(map_.yaw, value(map_.yaw));
  return s;
}

bool JoystickReader::position_known() const {
  return seen(map_.lift) && seen(map_.roll) && seen(map_.pitch) && seen(map_.yaw);
}

bool JoystickReader::take_abort() {
  const bool pressed = abort_pressed_;
  abort_pressed_ = false;
  return pressed;
}

}  // namespace qrterm
