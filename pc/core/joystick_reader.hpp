// Reads the Linux joystick API (struct js_event from <linux/joystick.h>, /dev/input/jsN) and keeps
// the stick's state: axes through the JoystickMap into pilot inputs, the abort button as an edge.
// It reads any file descriptor that delivers js_event records, so tests feed it through a pipe.
#pragma once

#include <linux/joystick.h>
#include <stddef.h>
#include <stdint.h>

#include <array>

#include <pc/core/joystick_map.hpp>
#include <pc/core/js_event_stream.hpp>
#include <pc/core/sticks.hpp>

namespace qrterm {

class JoystickReader {
 public:
  explicit JoystickReader(const JoystickMap& map) : map_(map) {}

  using ReadResult = JsEventStream::ReadResult;

  // Reads every event available on a non-blocking descriptor.
  ReadResult read_from(int fd);

  // One event, as the driver delivers it.
  void feed(const js_event& event);

  // The pilot's inputs from the axes seen so far (an axis not yet reported counts as neutral).
  Sticks sticks() const;

  // Every mapped axis has reported a position. The driver reports all of them right after the
  // device is opened, so until then the stick's position is unknown and flying is refused.
  bool position_known() const;

  // True once for each press of the abort button (not for the state reported at open).
  bool take_abort();

  const JoystickMap& map() const { return map_; }

 private:
  static constexpr size_t kMaxAxes = 64;

  int32_t value(const AxisBinding& binding) const;
  bool seen(const AxisBinding& binding) const;

  JoystickMap map_;
  std::array<int32_t, kMaxAxes> axis_{};
  std::array<bool, kMaxAxes> seen_{};
  bool abort_pressed_ = false;
  JsEventStream stream_;
};

}  // namespace qrterm
